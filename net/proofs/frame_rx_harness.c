/* CBMC: the frame receiver stays within its buffers for every byte sequence.
 * By induction over the sequence: from ANY state satisfying the invariant
 * (n <= FRAME_BODY_MAX, state one of the three), one arbitrary byte keeps
 * every access in bounds (--bounds-check --pointer-check) and re-establishes
 * the invariant; frame_rx_init establishes it. So no sequence of any length
 * can drive the receiver out of its buffers. */
#include <stdint.h>
#include "net/frame.h"

uint8_t nondet_u8(void);
uint16_t nondet_u16(void);

void harness(void)
{
    struct frame_rx rx;
    struct frame out;
    unsigned i;
    /* base case */
    frame_rx_init(&rx);
    __CPROVER_assert(rx.n <= FRAME_BODY_MAX && rx.state <= FRAME_RX_ESCAPED, "init");
    /* step: an arbitrary state within the invariant, an arbitrary byte */
    rx.state = nondet_u8();
    rx.n = nondet_u16();
    rx.crc = nondet_u16();
    __CPROVER_assume(rx.state <= FRAME_RX_ESCAPED && rx.n <= FRAME_BODY_MAX);
    for (i = 0; i < FRAME_BODY_MAX; i++)
        rx.body[i] = nondet_u8();
    int got = frame_rx_byte(&rx, nondet_u8(), &out);
    __CPROVER_assert(rx.n <= FRAME_BODY_MAX, "n stays within the body buffer");
    __CPROVER_assert(rx.state <= FRAME_RX_ESCAPED, "state stays valid");
    __CPROVER_assert(!got || out.len <= FRAME_AIR_PAYLOAD_MAX, "accepted payload fits");
}
