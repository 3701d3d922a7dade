/*
 * The port table of the RoboCube: every kind of port, its numbers, its
 * direction, its value range, and the functions that read and write it. The
 * one place these are written: the uniform access layer (sai.c) builds its
 * table and dispatch from it, and PDL (pdl/pdl_bind.c, on the board and on
 * the host; pdl/pdl_board.c) its port ranges and writes.
 *
 * SAI_PORT_TABLE(X) calls X once per kind, with
 *   X(KIND, name, short_name, first, last, readable, writable, min, max, unit, read, write)
 * read(index, &value) and write(index, value) return DRV_OK or an error
 * (drv_err.h); NULL where the kind has no such direction. A user that only
 * needs the ranges (the PDL host runtime) ignores the last two columns, so it
 * links no driver. SAI_<KIND>_FIRST/_LAST/_MIN/_MAX below are the ranges as
 * constants.
 */
#ifndef DRIVERS_SAI_PORTS_H
#define DRIVERS_SAI_PORTS_H

#include <stdint.h>

#include "drivers/analog.h"
#include "drivers/binin.h"
#include "drivers/bio.h"
#include "drivers/fastout.h"
#include "drivers/motor.h"
#include "drivers/tpu.h"

#define SAI_PORT_TABLE(X) \
    X(SAI_ANALOG_IN,  "analog in",  "ad",    0, ANALOG_INPUTS - 1u,  1, 0, 0, 255, "", \
      sai_port_analog_read, NULL) \
    X(SAI_ANALOG_OUT, "analog out", "da",    0, ANALOG_OUTPUTS - 1u, 0, 1, 0, 255, "", \
      NULL, sai_port_analog_write) \
    X(SAI_BINARY_IO,  "binary io",  "bio",   0, BIO_LINES - 1u,      1, 1, 0, 1, "", \
      sai_port_bio_read, sai_port_bio_write) \
    X(SAI_BINARY_IN,  "binary in",  "bin",   BININ_FIRST, BININ_LAST, 1, 0, 0, 1, "", \
      sai_port_binin_read, NULL) \
    X(SAI_FAST_OUT,   "fast out",   "fast",  0, FASTOUT_BITS - 1u,   1, 1, 0, 1, "", \
      sai_port_fastout_read, sai_port_fastout_write) \
    X(SAI_PWM,        "pwm",        "pwm",   0, TPU_USER_CHANNELS - 1u, 1, 1, 0, 1000, "per-mille", \
      sai_port_pwm_read, sai_port_pwm_write) \
    X(SAI_MOTOR,      "motor",      "motor", 0, MOTOR_COUNT - 1u,    1, 1, -1000, 1000, "per-mille", \
      sai_port_motor_read, sai_port_motor_write) \
    X(SAI_ENCODER,    "encoder",    "enc",   0, MOTOR_COUNT - 1u,    1, 0, INT32_MIN, INT32_MAX, "counts", \
      sai_port_encoder_read, NULL) \
    X(SAI_LED,        "led",        "led",   0, 0,                   1, 1, 0, 1, "", \
      sai_port_led_read, sai_port_led_write)

/* The kinds, in table order. */
#define SAI_PORT_KIND(kind, ...) kind,
enum sai_kind {
    SAI_PORT_TABLE(SAI_PORT_KIND)
    SAI_KIND_COUNT
};
#undef SAI_PORT_KIND

/* SAI_<KIND>_FIRST, _LAST, _MIN, _MAX: the ranges as integer constants. */
#define SAI_PORT_RANGE(kind, name, short_name, first, last, rd, wr, min, max, unit, read, write) \
    enum { kind##_FIRST = (first), kind##_LAST = (last), kind##_MIN = (min), kind##_MAX = (max) };
SAI_PORT_TABLE(SAI_PORT_RANGE)
#undef SAI_PORT_RANGE

#endif /* DRIVERS_SAI_PORTS_H */
