/*
 * The network stack of a RoboCube: a kernel service thread above the
 * applications (paper, section 3) running the layers of this folder:
 *   radio.c   interrupt-driven byte stream <-> frames (frame.c, crc16.c;
 *             with NET_FEC fec.c and rs.c, Reed-Solomon)
 *   mac.c     listen before talk, random backoff, bounded attempts
 *   link.c    reliable channel per peer, datagrams, broadcast
 *   packet.c  messages <-> fragments, ports
 *   xdr.c     data encoding for the applications (used by them directly)
 * Applications talk to the thread through kernel queues: net_send posts a
 * request and waits for its result; received messages wait in one message
 * queue per port for net_recv.
 */
#ifndef NET_NET_H
#define NET_NET_H

#include <stddef.h>
#include <stdint.h>
#include "link.h"

#define NET_BROADCAST  FRAME_BROADCAST
#define NET_RELIABLE   LINK_RELIABLE     /* flags of net_send */
#define NET_PORT_QUEUE 4u                /* messages waiting per port */
#define NET_PRIO       24u               /* service thread: above the applications */

/* Results (besides K_E* codes of the kernel, e.g. K_ETIMEDOUT, K_EINVAL). */
#define NET_EUNREACH LINK_EUNREACH       /* reliable send: no ACK after all retries */
#define NET_ENOBUFS  LINK_ENOBUFS        /* datagram: the transmit queue is full */

/* What the queues did when full or superseded (net/README.md, "Queues"). */
struct net_queue_stats {
    uint32_t acks_replaced;     /* a newer ACK to the same station took the queued one's place */
    uint32_t acks_dropped;      /* ACK queue full (one entry per station: never) */
    uint32_t data_replaced;     /* the link's next DATA frame took a waiting one's place */
    uint32_t data_obsolete;     /* a waiting retransmission whose fragment was since acknowledged */
    uint32_t dgrams_refused;    /* datagram queue full: net_send returned NET_ENOBUFS */
};

struct net_stats {
    uint32_t frames_sent, frames_received;
    uint32_t crc_errors, malformed;
    uint32_t retransmissions, collisions, deferrals, mac_drops;
    uint32_t duplicates, delivered, unreachable;
    uint32_t port_refused;       /* reliable messages not acknowledged: their port was full */
    uint32_t port_overflows;     /* datagrams dropped: their port was full */
    uint32_t rx_overruns;        /* characters lost in the DUART */
    uint32_t rx_ring_full;       /* good frames dropped: the radio's receive ring was full */
    uint32_t stale_acks;         /* ACKs for no outstanding frame, ignored */
    uint32_t new_sessions;       /* peers seen restarting (a new session) */
    struct net_queue_stats txq;
    uint32_t fec_corrected, fec_failed;  /* NET_FEC: bytes corrected; frames beyond the code */
    /* Authentication (net/auth.h): frames to us or broadcast refused before
     * the link saw them, and our own frames not sent because sealing failed. */
    uint32_t auth_forged, auth_replayed, auth_malformed, auth_seal_failed;
};

/* net_init_flags: forward error correction on air (fec.h). Every station of a
 * network must agree on it (a FEC frame is noise to a station without). */
#define NET_FEC 0x1u

/* Frame authentication (net/auth.h, net/README.md "Authentication"): every
 * frame this station sends is sealed with the 16-byte network key and a
 * counter of this boot's epoch, and every frame to it or broadcast is opened
 * before the link sees it; forged, replayed and malformed ones are dropped
 * and counted. epoch (0..AUTH_EPOCH_MAX) must grow from boot to boot (the
 * station's receivers refuse a boot whose epoch did not), and epoch %
 * LINK_SESSIONS is also the link's session (link.h). key NULL switches
 * authentication off (only to measure its cost: every station of a network
 * must agree, as on NET_FEC). Call before net_init_flags, which refuses to
 * start without it: K_OK, or K_EINVAL (epoch too big, or the stack runs). */
#define NET_AUTH_KEY_LEN 16u
int net_auth_setup(const uint8_t *key, uint32_t epoch);
/* The development key, "bsched-dev-key!!" (tools/netpeer/auth.py's DEV_KEY):
 * public, in every image and in git, so it protects nothing; for the shell's
 * `net start` and the tests. A network that wants protection needs a key of
 * its own (netnode: patched into its NETAUTH block; net/README.md). */
extern const uint8_t net_auth_dev_key[NET_AUTH_KEY_LEN];

/* Starts the stack as station `station` (0..LINK_MAX_STATIONS-1); seed makes
 * the backoffs of different stations differ (the session comes from
 * net_auth_setup's epoch). Call once after k_init and net_auth_setup;
 * K_EINVAL without net_auth_setup. */
int net_init(uint8_t station, uint32_t seed);
/* The same with options: NET_FEC. */
int net_init_flags(uint8_t station, uint32_t seed, unsigned flags);
uint8_t net_station(void);
/* Sends len bytes to port of dst (a station or NET_BROADCAST). With
 * NET_RELIABLE (unicast only) it returns when dst acknowledged the whole
 * message (K_OK) or NET_EUNREACH when it never did (about 8 s of retries);
 * without, the datagram (at most PACKET_DATA_MAX bytes) is queued and it
 * returns at once (NET_ENOBUFS when NET_DGRAM_QUEUE datagrams wait already). Never blocks longer than 60 s (then K_ETIMEDOUT). */
int net_send(uint8_t dst, uint8_t port, const void *data, size_t len, unsigned flags);
/* Waits up to timeout_ms for a message on port; copies at most size bytes,
 * returns the message length (>= 0, truncated to size), *src = its sender
 * (may be NULL), or K_ETIMEDOUT / K_EINVAL. One reader per port at a time. */
int net_recv(uint8_t port, void *buf, size_t size, uint8_t *src, uint32_t timeout_ms);
void net_stats_get(struct net_stats *out);
/* Prints the statistics on the console (the shell's `net` command); 0. */
int net_stats_print(void);

#endif /* NET_NET_H */
