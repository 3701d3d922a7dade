/*
 * The start-up every firmware image shares. An image's main is
 *
 *     board_start("NAME");               kernel, LED, console, tick
 *     ...app-specific set-up...
 *     board_spawn(&t, "name", fn, arg, stack, sizeof stack, prio);
 *     k_start();
 *
 * so the boot sequence and its failure handling live here once. Every board
 * implements this in its folder (boards/robocube/board.c,
 * boards/stm32f405/board.c); boards/common/board_common.c has what is the
 * same on every board.
 */
#ifndef BOARD_H
#define BOARD_H

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
 * kernel's board support (the console, interrupt-driven, and the tick at
 * K_TICK_HZ: on the RoboCube DUART B and the PIT). An image cannot run
 * without its tick, so on failure it writes "IMAGE: board start failed: ..."
 * on the polled console and halts. */
void board_start(const char *image);

/* Writes "IMAGE: WHY" (WHY ends with its own newline) on the polled console,
 * so it gets out even before k_start, and halts the CPU. */
void board_halt(const char *image, const char *why) __attribute__((noreturn));

/* Writes "IMAGE: WHY" like board_halt, then switches the board off, which
 * ends an emulated run: on the RoboCube LPSTOP with the interrupt mask at 7
 * (the board model takes it as the power-off, emu/README.md), on the
 * STM32F405 semihosting's exit. */
void board_power_off(const char *image, const char *why) __attribute__((noreturn));

/* k_thread_create that says so on the console when the thread cannot be
 * created ("cannot create thread 'NAME': error E"); the image then runs
 * without it. Returns k_thread_create's result. */
int board_spawn(struct k_thread *t, const char *name, k_thread_fn entry, void *arg,
                uint32_t *stack, size_t stack_bytes, unsigned prio);

/* Writes "IMAGE: WHY" on the polled console (board_halt's and
 * board_power_off's message; WHY ends with its own newline). */
void board_say(const char *image, const char *why);

/*
 * The console's receiver, which each board drives from its own chip (the
 * RoboCube's DUART channel B, the STM32F405's USART1) for drivers/console_in.c.
 *
 * board_console_rx_start(sink) calls sink(byte, flags) in the receive
 * interrupt for every byte received, flags telling what the chip said of it.
 * When sink returns 0 (its buffer is full) the board stops taking bytes from
 * the chip, which holds the next ones (or overruns) until
 * board_console_rx_resume(). Returns 0, or -1 when the receiver is taken.
 */
#define BOARD_RX_OVERRUN 1u   /* the chip lost bytes before this one */
#define BOARD_RX_ERROR   2u   /* framing or parity error, or a break */
typedef int (*board_console_rx_sink)(uint8_t byte, unsigned flags);
int board_console_rx_start(board_console_rx_sink sink);
void board_console_rx_resume(void);

#endif /* BOARD_H */
