/*
 * The MPS2 AN385's ports (boards/include/board_ports.h): a minimal table.
 * The board's only output a program can reach by name is the status LED;
 * QEMU's AN385 models no ADC, PWM or motor, and this board simulates none,
 * so every other kind has no numbers (first > last) and a PDL binding to one
 * is refused (pdl/pdl_bind.c: PDL_ERR_PORT).
 */
#include <stddef.h>

#include "boards/include/board_led.h"
#include "boards/include/board_ports.h"

const struct board_port_range board_ports[BOARD_PORT_KINDS] = {
    [BOARD_PORT_ANALOG_IN]  = {"analog in",  "ad",    1, 0, 0, 0, 0, 0, ""},
    [BOARD_PORT_ANALOG_OUT] = {"analog out", "da",    1, 0, 0, 0, 0, 0, ""},
    [BOARD_PORT_BINARY_IO]  = {"binary io",  "bio",   1, 0, 0, 0, 0, 0, ""},
    [BOARD_PORT_BINARY_IN]  = {"binary in",  "bin",   1, 0, 0, 0, 0, 0, ""},
    [BOARD_PORT_FAST_OUT]   = {"fast out",   "fast",  1, 0, 0, 0, 0, 0, ""},
    [BOARD_PORT_PWM]        = {"pwm",        "pwm",   1, 0, 0, 0, 0, 0, "per-mille"},
    [BOARD_PORT_MOTOR]      = {"motor",      "motor", 1, 0, 0, 0, 0, 0, "per-mille"},
    [BOARD_PORT_ENCODER]    = {"encoder",    "enc",   1, 0, 0, 0, 0, 0, "counts"},
    [BOARD_PORT_LED]        = {"led",        "led",   0, 0, 1, 1, 0, 1, ""},
};

int board_port_start(enum board_port_kind kind)
{
    return kind == BOARD_PORT_LED ? 0 : -1;
}

int board_port_read(enum board_port_kind kind, unsigned index, int32_t *value)
{
    if (kind != BOARD_PORT_LED || index != 0u)
        return -1;
    *value = led_is_on() ? 1 : 0;
    return 0;
}

int board_port_write(enum board_port_kind kind, unsigned index, int32_t value)
{
    if (kind != BOARD_PORT_LED || index != 0u)
        return -1;
    led_set(value != 0);
    return 0;
}
