/* CBMC: the FEC receiver (fec_rx_byte, run in the DUART interrupt on every
 * radio character) stays within its buffers for every byte sequence. As for
 * frame_rx_harness.c, by induction: from ANY state within the invariant one
 * arbitrary byte keeps every access in bounds and re-establishes the
 * invariant; fec_rx_init establishes it. */
#include <stdint.h>
#include "net/fec.h"

uint8_t nondet_u8(void);
uint16_t nondet_u16(void);

static int invariant(const struct fec_rx *rx)
{
    return rx->state <= FEC_RX_DATA && rx->ncopies <= FEC_COPIES &&
           (rx->state != FEC_RX_COUNT || rx->ncopies < FEC_COPIES) &&
           (rx->state != FEC_RX_DATA ||
            (rx->raw.ncw >= 1u && rx->raw.ncw <= FEC_CW_MAX &&
             rx->need == rx->raw.ncw * FEC_N && rx->n < rx->need));
}

void harness(void)
{
    struct fec_rx rx;
    struct fec_raw out;
    unsigned i;
    int got;
    fec_rx_init(&rx);
    __CPROVER_assert(invariant(&rx), "init");
    rx.state = nondet_u8();
    rx.ncopies = nondet_u8();
    rx.need = nondet_u16();
    rx.n = nondet_u16();
    rx.raw.ncw = nondet_u16();
    for (i = 0; i < FEC_COPIES; i++)
        rx.copies[i] = nondet_u8();
    __CPROVER_assume(invariant(&rx));
    got = fec_rx_byte(&rx, nondet_u8(), &out);
    __CPROVER_assert(invariant(&rx), "the invariant holds after any byte");
    __CPROVER_assert(!got || (out.ncw >= 1u && out.ncw <= FEC_CW_MAX),
                     "a completed frame has a codeword count in range");
}
