/*
 * Console on DUART channel B (8N1, CONSOLE_BAUD baud), polled: output waits
 * for TxRDY, input is read only when asked. Safe to call with interrupts
 * masked, so the fault reporter can use it.
 */
#ifndef DRIVERS_DUART_CONSOLE_H
#define DRIVERS_DUART_CONSOLE_H

#include <stddef.h>
#include <stdint.h>

/*
 * 38400 (default) or 9600 come from the DUART baud-rate generator; 57600,
 * CubeOS's console rate, needs the DUART counter/timer as baud clock
 * (-DCONSOLE_BAUD=57600). The default avoids that because the emulator
 * (emu/hw/mc68681_duart.c) then runs a 921.6 kHz timer event stream for as
 * long as the board runs, which costs a host core and slows the virtual
 * clock under -icount about fourfold (measured: LED period 0.5 s -> ~2 s).
 */
#ifndef CONSOLE_BAUD
#define CONSOLE_BAUD 38400
#endif

/* Programs channel B and the DUART counter/timer (baud source), masks all
 * DUART interrupts and makes the console kprintf's output. */
void console_init(void);

/* The ACR value console_init wrote (baud-rate set, counter/timer mode): a
 * driver that changes ACR's input-change bits must keep these. */
uint8_t console_acr(void);

/* Sends one character; '\n' goes out as "\r\n". */
void console_putc(char c);
void console_write(const char *s, size_t len);
void console_puts(const char *s);

/* The next received character (0..255), or -1 if none is waiting. */
int console_getc_nonblocking(void);

#endif /* DRIVERS_DUART_CONSOLE_H */
