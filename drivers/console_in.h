/*
 * Interrupt-driven console input on DUART channel B (the console's receiver;
 * output is the kernel's console in k_board_robocube.c).
 *
 * The RxRDYB interrupt (attached through boards/robocube/duart.h) moves received
 * bytes into a ring; a reading thread waits on a semaphore with a bounded
 * timeout. When the ring is full the interrupt masks itself and leaves the
 * bytes in the DUART's receive FIFO until the reader has made room, so a
 * slow reader loses nothing to the ring (a sender that keeps typing past the
 * 3-byte FIFO still overruns the chip; those losses are counted).
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

/* Attaches the receive interrupt and unmasks it; call after k_board_init.
 * DRV_OK, or DRV_ERR_STATE if the DUART handler slots are taken or it was
 * already initialised. */
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
    uint32_t overruns;       /* DUART receive overruns (characters lost in the chip) */
    uint32_t errors;         /* framing / parity errors / received breaks */
    uint32_t ring_full;      /* times the ring filled and reception paused */
    uint32_t lines;          /* lines returned */
    uint32_t too_long;       /* lines refused for length */
};
void console_in_stats(struct console_in_stats *out);

#endif /* DRIVERS_CONSOLE_IN_H */
