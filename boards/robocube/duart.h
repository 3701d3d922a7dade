/*
 * Shared services of the MC68681 DUART. One chip serves several drivers: the
 * console (channel B, in k_board_robocube.c), the radio (channel A, radio.c), the
 * binary inputs (IP1-IP5) and carrier detect (IP0), and the output port
 * (motor direction OP2-OP7, radio enables OP0/OP1). Its interrupt mask (IMR)
 * and the auxiliary control register (ACR) are write-only and its single
 * interrupt is shared, so those live here, once, and drivers attach to them.
 */
#ifndef ROBOCUBE_DUART_H
#define ROBOCUBE_DUART_H

#include <stdint.h>

#include "boards/include/board_io.h"

/* ISR / IMR bits. */
#define DUART_INT_TXRDYA   0x01u
#define DUART_INT_RXRDYA   0x02u
#define DUART_INT_BREAKA   0x04u
#define DUART_INT_COUNTER  0x08u
#define DUART_INT_TXRDYB   0x10u
#define DUART_INT_RXRDYB   0x20u
#define DUART_INT_BREAKB   0x40u
#define DUART_INT_IPCHANGE 0x80u

/* The DUART's interrupt: the vector the chip gives (written to IVR) and the
 * level the board wires it to. */
#define DUART_IRQ_VECTOR 72u
#define DUART_IRQ_LEVEL   5u

/* Handlers the DUART interrupt can call, besides the console's. */
#define DUART_MAX_HANDLERS 4u

/*
 * Called from the DUART interrupt (level 5, interrupts at that level masked)
 * with the ISR bits that are both pending and enabled and that the handler
 * asked for. It must clear its own sources (read the receive buffer, feed or
 * mask the transmitter, read IPCR) before it returns.
 */
typedef void (*duart_irq_handler)(uint8_t pending, void *arg);

/* Attaches fn for the ISR bits in mask. 0, or -1 when mask is 0, overlaps the
 * console's or another handler's bits, or all DUART_MAX_HANDLERS are taken. */
int duart_irq_attach(uint8_t mask, duart_irq_handler fn, void *arg);

/* Sets, then clears, bits of the interrupt mask; safe from threads and handlers. */
void duart_imr_update(uint8_t set, uint8_t clear);
uint8_t duart_imr(void);

/* Output port: bit n set = OPn asserted (pin low), as OPR-set/OPR-reset do:
 * the board's output lines, board_outputs_assert and _negate
 * (boards/include/board_io.h). */
uint8_t duart_op(void);   /* the shadow of OPR (the register is write-only) */

/* ACR bits 3-0 enable the input-change interrupt for IP3-IP0 (IPCR). ACR's
 * upper bits belong to the console's baud setup and are kept. */
void duart_acr_ipchange(uint8_t ip_mask);

/* Runs the counter/timer as a baud clock: timer mode from the X1 crystal
 * (3.6864 MHz; ACR bits 6-4 = 110), CTUR:CTLR = preload, started. Its square
 * wave is X1 / (2 x preload), and CSR code 0xD takes it as the 16x clock, so
 * preload 6 gives 19200 baud. 0, or -1 when preload is 0 or the counter/timer
 * is already in use (ACR bits 6-4 not 000, e.g. the 57600 console's clock). */
int duart_ct_baud_clock(uint16_t preload);

#endif /* ROBOCUBE_DUART_H */
