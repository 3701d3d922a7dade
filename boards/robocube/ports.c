/*
 * The port table of the RoboCube (boards/include/board_ports.h): its I/O
 * board's ports, the TPU's channels, the motors and the status LED. The
 * drivers that serve each kind (drivers/analog.h, bio.h, binin.h, fastout.h,
 * tpu.h, motor.h) handle exactly these numbers; drivers/tests/test_sai.c
 * checks that they agree.
 */
#include <stddef.h>

#include "boards/include/board_ports.h"

const struct board_port_range board_ports[BOARD_PORT_KINDS] = {
    /* 6 x PCF8591, CubeOS numbering (drivers/analog.h) */
    [BOARD_PORT_ANALOG_IN]  = {"analog in",  "ad",    0, 23, 1, 0, 0, 255, ""},
    [BOARD_PORT_ANALOG_OUT] = {"analog out", "da",    0, 5,  0, 1, 0, 255, ""},
    /* 2 x PCF8574A, quasi-bidirectional */
    [BOARD_PORT_BINARY_IO]  = {"binary io",  "bio",   0, 15, 1, 1, 0, 1, ""},
    /* DUART IP1-IP5 (IP0 is the radio's carrier detect) */
    [BOARD_PORT_BINARY_IN]  = {"binary in",  "bin",   1, 5,  1, 0, 0, 1, ""},
    [BOARD_PORT_FAST_OUT]   = {"fast out",   "fast",  0, 15, 1, 1, 0, 1, ""},
    /* TP0-TP15 */
    [BOARD_PORT_PWM]        = {"pwm",        "pwm",   0, 15, 1, 1, 0, 1000, "per-mille"},
    [BOARD_PORT_MOTOR]      = {"motor",      "motor", 0, 2,  1, 1, -1000, 1000, "per-mille"},
    [BOARD_PORT_ENCODER]    = {"encoder",    "enc",   0, 2,  1, 0, INT32_MIN, INT32_MAX, "counts"},
    [BOARD_PORT_LED]        = {"led",        "led",   0, 0,  1, 1, 0, 1, ""},
};
