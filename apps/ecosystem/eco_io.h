/*
 * The ecosystem robot's ports on the RoboCube, as the world wires them
 * (emu/world/arenas/default.json "wiring"): station light L/R on AIN0/AIN1,
 * infrared L/R on AIN2/AIN3 (PCF8591 0x48), battery on AIN4, competitor
 * light L/R on AIN5/AIN6 (PCF8591 0x49); bumpers L/R on DUART IP1/IP2 and
 * the charger contact on IP3 (active low); left wheel motor 0, right wheel
 * motor 1 (TPU PWM TP0/TP2, direction OP2/OP3 and OP4/OP5).
 *
 * Interim, app-local: polled PCF8584 transfers and direct TPU PWM set-up,
 * until the `drivers` (analog_read, binin_read) and `motion` (motor_set)
 * streams' drivers are merged; then this file becomes calls to them.
 */
#ifndef ECO_IO_H
#define ECO_IO_H

#include "eco_program.h"

/* 0 or a negative code (the I2C controller did not answer in time). */
int eco_io_init(void);
/* Reads every sensor; on an I2C error keeps the previous analog values
 * and returns the negative code. */
int eco_io_read(struct eco_inputs *in);
/* Motor set-points in permille (-1000..1000) for the left and right wheel. */
void eco_io_motors(int32_t left, int32_t right);
/* I2C transfers that failed since start. */
uint32_t eco_io_errors(void);

#endif
