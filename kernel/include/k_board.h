/*
 * What the nanokernel needs from a board (kernel/README.md, "The board
 * interface"). Each board implements it in its folder (the RoboCube in
 * boards/robocube/k_board_robocube.c, the STM32F405 in
 * boards/stm32f405/k_board_stm32f405.c): its timer drives k_tick, and
 * k_board_init registers the console writers (k_console_register, kernel.h):
 * polled first, then interrupt-driven behind a ring buffer. The image's start-up calls k_board_init;
 * the kernel itself calls nothing of the board.
 */
#ifndef K_BOARD_H
#define K_BOARD_H

#include <stdint.h>

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
