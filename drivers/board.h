/*
 * The start-up every firmware image shares. An image's main is
 *
 *     board_start("NAME");               kernel, LED, console, tick
 *     ...app-specific set-up...
 *     board_spawn(&t, "name", fn, arg, stack, sizeof stack, prio);
 *     k_start();
 *
 * so the boot sequence and its failure handling live here once.
 */
#ifndef DRIVERS_BOARD_H
#define DRIVERS_BOARD_H

#include <stddef.h>
#include <stdint.h>

#include "kernel.h"

/* What the image runs on, for its banner: the board ("RoboCube"), its CPU
 * ("MC68332"), the CPU clock and the console's baud rate. */
extern const char board_name[];
extern const char board_cpu_name[];
extern const uint32_t board_cpu_hz;
extern const uint32_t board_console_baud;

/* Resets the kernel (k_init), switches the status LED off and brings up the
 * kernel's board support (interrupt-driven console on DUART B, the PIT tick
 * at K_TICK_HZ). An image cannot run without its tick, so on failure it
 * writes "IMAGE: board start failed: ..." on the polled console and halts. */
void board_start(const char *image);

/* Writes "IMAGE: WHY" (WHY ends with its own newline) on the polled console,
 * so it gets out even before k_start, and halts the CPU. */
void board_halt(const char *image, const char *why) __attribute__((noreturn));

/* Writes "IMAGE: WHY" like board_halt, then switches the board off: LPSTOP
 * with the interrupt mask at 7, which on the CPU32 stops the CPU and the
 * clocks until a level-7 interrupt or a reset. The board model takes it as
 * the board's power-off and ends the emulation (emu/README.md). */
void board_power_off(const char *image, const char *why) __attribute__((noreturn));

/* k_thread_create that says so on the console when the thread cannot be
 * created ("cannot create thread 'NAME': error E"); the image then runs
 * without it. Returns k_thread_create's result. */
int board_spawn(struct k_thread *t, const char *name, k_thread_fn entry, void *arg,
                uint32_t *stack, size_t stack_bytes, unsigned prio);

#endif /* DRIVERS_BOARD_H */
