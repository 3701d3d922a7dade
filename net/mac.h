/*
 * Media arbitration: listen before talk on carrier detect with random
 * backoff, bounded attempts (non-persistent CSMA with binary exponential
 * backoff). Pure logic, the clock and the carrier come from the caller.
 *
 * A data frame first waits a random 0..cw slots (so stations that all saw
 * the channel go idle do not all start at once), then sends if the carrier
 * is off; if the carrier is on it defers for a random backoff, the window
 * doubling per deferral up to MAC_CW_MAX, and gives up after
 * MAC_MAX_ATTEMPTS. Acknowledgements skip the initial wait and, while the
 * carrier is on, retry every MAC_ACK_RETRY_MS instead of backing off: they
 * follow the frame they answer at once and so win the channel against new data.
 */
#ifndef NET_MAC_H
#define NET_MAC_H

#include <stdint.h>

#define MAC_SLOT_MS       3u     /* about 6 characters at 19200 baud */
#define MAC_CW_MIN        4u     /* slots */
#define MAC_CW_MAX        64u
#define MAC_MAX_ATTEMPTS  12u
#define MAC_ACK_RETRY_MS  1u     /* an ACK waits out the tail of the frame it answers */
#define MAC_BURST_RETRIES 3u     /* ... and so does the next fragment of a burst */

enum mac_action { MAC_SEND = 0, MAC_WAIT = 1, MAC_DROP = 2 };

struct mac {
    uint32_t rng;            /* xorshift32 state, never 0 */
    uint8_t attempt;         /* deferrals of the current frame */
    uint8_t waited;          /* the initial wait of the current frame is done */
    uint8_t burst;           /* the current frame continues a burst */
    uint32_t deferrals;      /* carrier busy when we wanted to send */
    uint32_t drops;          /* frames given up (channel never free) */
};

void mac_init(struct mac *m, uint32_t seed);
/* Starts arbitration for a new frame. */
void mac_begin(struct mac *m);
/* The same for a frame that continues a burst (link_is_burst): no initial
 * random wait, and while the carrier is on (the tail of the ACK it follows:
 * its pad character) it retries every MAC_ACK_RETRY_MS for its first
 * MAC_BURST_RETRIES deferrals, then backs off as any data frame. */
void mac_begin_burst(struct mac *m);
/* What to do now for the current frame: MAC_SEND; MAC_WAIT (*wait_ms set,
 * ask again after it); MAC_DROP (attempts exhausted, counted). */
int mac_decide(struct mac *m, int carrier, int is_ack, uint32_t *wait_ms);
/* Pseudo-random number (xorshift32), also used for retransmission jitter. */
uint32_t mac_random(struct mac *m);

#endif /* NET_MAC_H */
