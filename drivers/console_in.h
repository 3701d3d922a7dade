/*
 * Interrupt-driven console input, on any board: the board's receiver
 * (board_console_rx_start in boards/include/board.h: the RoboCube's DUART channel B,
 * the STM32F405's USART1) hands each received byte to this module in its
 * interrupt; output is the kernel's console (k_console_write).
 *
 * The bytes go into a ring; a reading thread waits on a semaphore with a
 * bounded timeout. When the ring is full the board stops taking bytes and
 * leaves them in its chip until the reader has drained half the ring, so a
 * slow reader loses nothing to the ring (a sender that keeps typing past the
 * chip's FIFO, 3 bytes on the DUART, still overruns the chip; those losses
 * are counted).
 *
 * One reader thread at a time (the shell); lines are assembled and edited by
 * drivers/line_edit.h and echoed to the console while echo is on.
 */
#ifndef DRIVERS_CONSOLE_IN_H
#define DRIVERS_CONSOLE_IN_H

#include <stddef.h>
#include <stdint.h>

/* Receive ring (bytes, a power of two) and the longest line, in characters. */
#define CONSOLE_IN_RING     256u
#define CONSOLE_IN_LINE_MAX 120u
/* The longest wait console_read_line accepts (one day; keeps the tick
 * arithmetic far from wrapping). */
#define CONSOLE_IN_TIMEOUT_MAX_MS 86400000u

/* Starts the board's receiver; call after k_board_init. DRV_OK, or
 * DRV_ERR_STATE if the receiver is taken (on the RoboCube: the DUART's
 * handler slots) or it was already initialised. */
int console_in_init(void);

/* Echo of typed characters (and line editing) to the console: on by default. */
void console_in_set_echo(int on);

/*
 * Reads one line into buf (without its end of line, NUL-terminated), waiting
 * at most timeout_ms (at most CONSOLE_IN_TIMEOUT_MAX_MS, larger values are
 * clamped) for it to be finished. Returns its length (0 for an
 * empty line or one cancelled with Ctrl-C / Ctrl-U), or
 *   DRV_ERR_RANGE    the line had more than size - 1 (or CONSOLE_IN_LINE_MAX)
 *                    characters: it was discarded whole, up to its end;
 *   DRV_ERR_TIMEOUT  no complete line yet: what was typed so far is kept and
 *                    the next call goes on with it;
 *   DRV_ERR_PARAM    buf NULL or size 0;
 *   DRV_ERR_STATE    console_in_init was not called.
 */
int console_read_line(char *buf, size_t size, uint32_t timeout_ms);

/* Counters since init. */
struct console_in_stats {
    uint32_t bytes;          /* received into the ring */
    uint32_t overruns;       /* receive overruns (characters lost in the chip) */
    uint32_t errors;         /* framing / parity errors / received breaks */
    uint32_t ring_full;      /* times the ring filled and reception paused */
    uint32_t lines;          /* lines returned */
    uint32_t too_long;       /* lines refused for length */
};
void console_in_stats(struct console_in_stats *out);

#endif /* DRIVERS_CONSOLE_IN_H */
