/*
 * The motors' PI speed controller, pure integer logic (no hardware, host
 * tested in drivers/tests/): error in counts/s, output in per-mille of
 * power, gains in Q8 (see drivers/motor.h motor_set_gains).
 *
 * Anti-windup: the integral term integrates only up to the point where the
 * output reaches its limit, never further in the direction in which the
 * output is saturated (clamping), and stays within the output range, so a
 * long saturation (a stalled or overloaded motor, a large step) leaves no
 * wound-up integral to overshoot with afterwards.
 */
#ifndef DRIVERS_MOTOR_PI_H
#define DRIVERS_MOTOR_PI_H

#include <stdint.h>

#define MOTOR_PI_OUT_MAX 1000          /* per-mille */
#define MOTOR_PI_Q 8                   /* gains and the integral are in Q8 */
#define MOTOR_PI_GAIN_MAX (1000 << MOTOR_PI_Q) /* kp, ki 0..this (overflow-free range) */

struct motor_pi {
    int32_t kp;        /* Q8 per-mille per count/s */
    int32_t ki;        /* Q8 per-mille per count/s per second */
    int32_t integral;  /* Q8 per-mille, within +-MOTOR_PI_OUT_MAX << Q */
    int32_t out;       /* last output, per-mille */
    uint8_t saturated; /* the last output was clamped */
};

void motor_pi_init(struct motor_pi *pi, int32_t kp, int32_t ki);
/* Makes the next output continue from out_permille (bumpless start). */
void motor_pi_preset(struct motor_pi *pi, int32_t out_permille);
/* One period of dt_us microseconds (longer counts as 1 s): returns the output, -1000..1000. */
int32_t motor_pi_step(struct motor_pi *pi, int32_t setpoint, int32_t measured, uint32_t dt_us);

#endif /* DRIVERS_MOTOR_PI_H */
