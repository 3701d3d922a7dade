/*
 * What the nanokernel needs from a board (kernel/README.md, "The board
 * interface"). The RoboCube implements it in boards/robocube/k_board_robocube.c:
 * the PIT drives k_tick, and k_board_init registers the console writers
 * (k_console_register, kernel.h): polled first, then interrupt-driven on DUART
 * channel B behind a ring buffer. The image's start-up calls k_board_init;
 * the kernel itself calls nothing of the board.
 */
#ifndef K_BOARD_H
#define K_BOARD_H

#include <stdint.h>

/* DUART interrupt vector (written to IVR); level 5 is wired on the board. */
#define K_BOARD_DUART_VECTOR 72u
#define K_BOARD_DUART_LEVEL   5u
/* Console transmit ring, bytes (power of two). */
#define K_BOARD_CONSOLE_RING 1024u

/* Called by the image's start-up after k_init: programs the console,
 * registers its writers with the kernel (interrupt-driven output) and starts
 * the PIT at K_TICK_HZ. Ticks are counted once interrupts are enabled,
 * i.e. when k_start runs the first thread. Returns 0, or -1 when the PIT
 * cannot make K_TICK_HZ. */
int k_board_init(void);

/* Called in the tick interrupt after k_tick (tests and measurements). */
extern void (*volatile k_board_tick_callback)(void);

/* Console bytes dropped because the ring was full where waiting is not
 * allowed (interrupt handlers, before k_start). */
uint32_t k_board_console_dropped(void);

#endif /* K_BOARD_H */
