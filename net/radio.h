/*
 * The radio driver on the board's radio channel (boards/include/board_radio.h;
 * on the RoboCube the BiM-433 on DUART channel A): interrupt-driven, no
 * polling and no busy transmit.
 *
 * Receive: the channel's receive interrupt feeds every character to the
 * frame state machine (frame.h); good frames go into a ring of
 * RADIO_RX_FRAMES and the owner's event bit is set. Transmit: radio_transmit
 * keys the module to transmit and the channel's transmit interrupt takes the
 * encoded frame; a pad character follows the closing flag, and the request
 * after the pad (the pad entered the shift register, so the flag has left)
 * sets the owner's done bit while the board keys the module back to receive.
 */
#ifndef NET_RADIO_H
#define NET_RADIO_H

#include <stddef.h>
#include <stdint.h>
#include "kernel.h"
#include "frame.h"
#include "fec.h"

#define RADIO_RX_FRAMES 6u
#define RADIO_ENCODED_MAX (FRAME_ENCODED_MAX > FEC_ENCODED_MAX ? FRAME_ENCODED_MAX \
                                                               : FEC_ENCODED_MAX)
#define RADIO_TX_MAX    (RADIO_ENCODED_MAX + 1u)   /* + the pad */

struct radio_stats {
    uint32_t rx_overruns;      /* characters lost in the board's receiver (FIFO overrun) */
    uint32_t rx_ring_full;     /* good frames dropped: the ring was full */
    uint32_t collisions;       /* carrier from another station during our transmission */
    struct fec_stats fec;      /* with FEC: decoding */
    uint32_t fec_bad_count;    /* with FEC: no agreed codeword count */
};

/* Sets up the board's radio channel (on the RoboCube: 19200 baud from
 * baud-rate set 2 if the console chose it, else the counter/timer; 9600 only
 * if that is taken too), keyed to receive; good frames set rx_bit in ev, finished
 * transmissions set tx_bit; fec: frames are fec.h's (the interrupt collects
 * codewords, radio_receive corrects them). 0, or a negative K_E* code. */
int radio_init(struct k_event *ev, uint32_t rx_bit, uint32_t tx_bit, int fec);
/* Starts sending len encoded bytes (copied); K_EBUSY while one is on air. */
int radio_transmit(const uint8_t *bytes, size_t len);
int radio_tx_busy(void);
/* The baud rate radio_init chose (19200, or 9600 when no 19200 clock is free). */
uint32_t radio_baud(void);
/* Carrier detect: another station is on air. */
int radio_carrier(void);
/* Takes the oldest received frame: 1, or 0 when there is none. */
int radio_receive(struct frame *out);
void radio_stats_get(struct radio_stats *out, struct frame_rx_stats *framing);

#endif /* NET_RADIO_H */
