/*
 * The board's port table: every kind of port the firmware knows and, for
 * each, the numbers, direction and value range it has on this board. The one
 * place these are written is the board's folder (boards/NAME/ports.c); the
 * uniform access layer (drivers/sai.c) takes its names and checks from it,
 * and PDL (pdl/pdl_bind.c, on the board and on the host) its port ranges.
 * A kind the board lacks is neither readable nor writable and has no numbers
 * (first > last).
 */
#ifndef BOARD_PORTS_H
#define BOARD_PORTS_H

#include <stdint.h>

enum board_port_kind {
    BOARD_PORT_ANALOG_IN,
    BOARD_PORT_ANALOG_OUT,
    BOARD_PORT_BINARY_IO,
    BOARD_PORT_BINARY_IN,
    BOARD_PORT_FAST_OUT,
    BOARD_PORT_PWM,
    BOARD_PORT_MOTOR,
    BOARD_PORT_ENCODER,
    BOARD_PORT_LED,
    BOARD_PORT_KINDS
};

struct board_port_range {
    const char *name;       /* "analog in" */
    const char *short_name; /* "ad" */
    uint8_t first, last;    /* port numbers */
    uint8_t readable, writable;
    int32_t min, max;       /* write range (read range for read-only kinds) */
    const char *unit;       /* "", "per-mille", "counts" */
};

/* One row per kind, in enum board_port_kind's order. */
extern const struct board_port_range board_ports[BOARD_PORT_KINDS];

/*
 * Port access on a board whose ports are its own registers, with no driver
 * between (the STM32F405: boards/stm32f405/ports.c; PDL reaches them through
 * pdl/ports/board.c). A board whose ports are its drivers' (the RoboCube:
 * drivers/sai.h) does not define these. Index and value are in the kind's
 * range. Each returns 0, or a negative code when the board cannot.
 */
int board_port_start(enum board_port_kind kind);   /* before the first read or write */
int board_port_read(enum board_port_kind kind, unsigned index, int32_t *value);
int board_port_write(enum board_port_kind kind, unsigned index, int32_t value);

#endif /* BOARD_PORTS_H */
