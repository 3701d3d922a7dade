/*
 * The RoboCube's three DC motors (emu/IO.md section 1.4): each is a TPU PWM
 * channel (power), two DUART output bits (direction: forward, reverse,
 * brake) and a quadrature encoder on two TPU channels (QDEC):
 *
 *   motor 0: PWM TP0, direction OP2/OP3, encoder A/B TP1/TP12
 *   motor 1: PWM TP2, direction OP4/OP5, encoder A/B TP3/TP14
 *   motor 2: PWM TP4, direction OP6/OP7, encoder A/B TP5/TP13
 *
 * Open loop: motor_set(m, permille), signed per-mille of full power.
 * Closed loop: a service thread (motor_control_start) samples every encoder
 * each period, estimates the speed from the TPU's edge times, and runs a PI
 * controller (drivers/motor_pi.h) for every motor given a speed set-point
 * with motor_set_speed. motor_set or motor_control_off returns a motor to
 * open loop.
 *
 * Units: position in encoder counts (4 per line), speed in counts/s, power in
 * per-mille (-1000..1000, negative = reverse). Gains: see motor_set_gains.
 * Returns DRV_ERR_CHANNEL for m >= MOTOR_COUNT, DRV_ERR_RANGE for a value out
 * of range, DRV_ERR_STATE before motor_init (or, for the speed, before the
 * service runs). No call blocks: shared state is guarded by short sections
 * with interrupts masked.
 */
#ifndef DRIVERS_MOTOR_H
#define DRIVERS_MOTOR_H

#include <stdint.h>

#define MOTOR_COUNT 3u
#define MOTOR_PWM_HZ 1000u              /* PWM frequency of the power stage */
#define MOTOR_DEFAULT_PERIOD_MS 10u     /* service period motor_init starts with */
#define MOTOR_PERIOD_MS_MAX 1000u
#define MOTOR_SPEED_MAX 10000000        /* |set-point| limit, counts/s (the model's max) */
#define MOTOR_SERVICE_PRIO 28u          /* K_PRIO_SERVICE_MIN: above every application thread */

/* Sets up the TPU channels (PWM at 0 %, QDEC at position 0), brakes all
 * three motors and starts the service thread at MOTOR_DEFAULT_PERIOD_MS.
 * Calls tpu_init itself. Call after k_init (before or after k_start; the
 * thread runs once the scheduler does). Again = no-op. */
int motor_init(void);

/* Open loop: signed per-mille of full power, -1000..1000; 0 brakes. Turns
 * the motor's speed controller off. */
int motor_set(unsigned m, int permille);
/* The power last applied (by motor_set or by the controller). */
int motor_power(unsigned m, int *permille);

/* Encoder position (counts since motor_init) and speed (counts/s, as the
 * service measured it at its last period). */
int motor_position(unsigned m, int32_t *counts);
int motor_speed(unsigned m, int32_t *counts_per_s);

/* Starts the service thread with this period (1..MOTOR_PERIOD_MS_MAX ms), or
 * changes the period of the running one. motor_init has started it at
 * MOTOR_DEFAULT_PERIOD_MS already. */
int motor_control_start(unsigned period_ms);

/* Closed loop: the PI controller drives m to counts_per_s
 * (|v| <= MOTOR_SPEED_MAX). Starts from the motor's present power
 * (bumpless). DRV_ERR_STATE if the service does not run. */
int motor_set_speed(unsigned m, int32_t counts_per_s);
/* Open loop again, power 0 (brake). */
int motor_control_off(unsigned m);

/* PI gains in Q8 fixed point (value / 256):
 *   kp: per-mille of power per count/s of speed error,
 *   ki: per-mille of power per count/s of error per second.
 * 0..MOTOR_GAIN_MAX each. Defaults (MOTOR_KP_DEFAULT, MOTOR_KI_DEFAULT) suit
 * the board model's default motor (2000 counts/s at full power, tau 50 ms):
 * kp = 1.0, ki = 20.0 (the integral time kp/ki = 50 ms cancels the motor's
 * time constant). */
#define MOTOR_GAIN_MAX   (1000 * 256)   /* = MOTOR_PI_GAIN_MAX */
#define MOTOR_KP_DEFAULT 256
#define MOTOR_KI_DEFAULT (20 * 256)
int motor_set_gains(unsigned m, int32_t kp, int32_t ki);
int motor_get_gains(unsigned m, int32_t *kp, int32_t *ki);

/* Service statistics: periods run, and the period in effect (ms). */
struct motor_service_stats {
    uint32_t periods;
    uint32_t period_ms;
    uint32_t late;          /* periods that started after their deadline */
};
int motor_service_stats(struct motor_service_stats *out);

#endif /* DRIVERS_MOTOR_H */
