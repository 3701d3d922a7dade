/*
 * Console on DUART channel B (57600 baud, 8N1), polled: output waits for
 * TxRDY, input is read only when asked. Safe to call with interrupts
 * masked, so the fault reporter can use it.
 */
#ifndef DRIVERS_DUART_CONSOLE_H
#define DRIVERS_DUART_CONSOLE_H

#include <stddef.h>

#define CONSOLE_BAUD 57600u

/* Programs channel B and the DUART counter/timer (baud source), masks all
 * DUART interrupts and makes the console kprintf's output. */
void console_init(void);

/* Sends one character; '\n' goes out as "\r\n". */
void console_putc(char c);
void console_write(const char *s, size_t len);
void console_puts(const char *s);

/* The next received character (0..255), or -1 if none is waiting. */
int console_getc_nonblocking(void);

#endif /* DRIVERS_DUART_CONSOLE_H */
