/*
 * The board's radio channel: a half-duplex serial link to the radio module,
 * driven by interrupts, for the network's radio driver (net/radio.c), which
 * frames, buffers and keys through it. The RoboCube's is the BiM-433 on DUART
 * channel A (boards/robocube/radio.c).
 *
 * The board calls rx(byte, overrun) in its receive interrupt for every byte
 * received (overrun: the chip lost bytes before this one), and, while a
 * transmission runs, tx() in its transmit interrupt each time it can take a
 * byte: tx returns the next byte, or -1 when the last byte has left (the
 * board then keys the module back to receive and stops calling tx until the
 * next board_radio_transmit).
 */
#ifndef BOARD_RADIO_H
#define BOARD_RADIO_H

#include <stdint.h>

typedef void (*board_radio_rx_fn)(uint8_t byte, int overrun);
typedef int (*board_radio_tx_fn)(void);

/* Sets the channel up (the module keyed to receive) and starts receiving
 * into rx; tx serves the transmissions. 0, or -1 when the channel's
 * interrupt cannot be had. */
int board_radio_start(board_radio_rx_fn rx, board_radio_tx_fn tx);
/* The baud rate board_radio_start chose. */
uint32_t board_radio_baud(void);
/* Keys the module to transmit (the receiver off: half duplex) and starts
 * calling tx. */
void board_radio_transmit(void);
/* Carrier detect: another station is on air. */
int board_radio_carrier(void);

#endif /* BOARD_RADIO_H */
