/*
 * The link protocol above framing: a reliable channel per peer, unreliable
 * datagrams and broadcast, on the packetizing of packet.h. Pure logic: the
 * caller supplies the clock (ms), sends the frames the link hands it (after
 * media arbitration) and feeds it the frames received. net.c runs it in the
 * network service thread; the host tests run several links on a simulated
 * lossy channel; the host peer (tools/netpeer) implements the same protocol.
 *
 * Frame types (frame.type):
 *   LINK_DATA   reliable fragment, seq = per-peer sequence number
 *   LINK_ACK    acknowledges the DATA frame with the same seq, no payload
 *   LINK_DGRAM  unreliable datagram (one fragment), unicast or broadcast
 * Reliable channel: stop and wait per sender (one fragment in flight): a
 * fragment is retransmitted when no ACK came within the retransmission
 * timeout, which doubles per retry (LINK_RTO_MS .. LINK_RTO_MAX_MS, with
 * random jitter); after LINK_MAX_RETRIES the send fails with
 * LINK_EUNREACH. The receiver acknowledges every DATA frame, delivers a
 * fragment only if its seq differs from the last one delivered from that
 * peer (a repeat is a duplicate: acknowledged again, counted, dropped), and
 * reassembles messages in order. The fragments of one message go out as a
 * burst: each right after the ACK of the one before (link_is_burst).
 */
#ifndef NET_LINK_H
#define NET_LINK_H

#include <stddef.h>
#include <stdint.h>
#include "frame.h"
#include "packet.h"

#define LINK_DATA   1u
#define LINK_ACK    2u
#define LINK_DGRAM  3u

#define LINK_MAX_STATIONS 16u   /* station numbers 0..15; FRAME_BROADCAST = all */
#define LINK_RTO_MS       250u
#define LINK_RTO_MAX_MS   1000u
#define LINK_MAX_RETRIES  8u

#define LINK_OK          0
#define LINK_EINVAL    (-22)
#define LINK_EBUSY     (-16)
#define LINK_EUNREACH (-113)

#define LINK_RELIABLE 0x1u      /* flags of link_send */

struct link_stats {
    uint32_t frames_sent;       /* handed to the air */
    uint32_t frames_received;   /* good frames for this station (or broadcast) */
    uint32_t retransmissions;
    uint32_t duplicates;        /* reliable fragments received twice, dropped */
    uint32_t delivered;         /* messages delivered to ports */
    uint32_t unreachable;       /* reliable sends that failed */
    uint32_t reasm_errors;      /* fragments out of place, messages dropped */
    uint32_t acks_sent;
    uint32_t rx_busy;           /* last fragments refused: the port's queue was full */
};

struct link_env {
    /* Queue f for the air (media arbitration follows); the link may reuse f. */
    void (*transmit)(void *ctx, const struct frame *f);
    /* A complete message for port. */
    void (*deliver)(void *ctx, uint8_t src, uint8_t port, const uint8_t *msg, size_t len);
    /* The send started by link_send is over: LINK_OK or LINK_EUNREACH. */
    void (*send_done)(void *ctx, int result);
    /* Optional (NULL: always): is there room at port for a message? If not,
     * its last fragment is not acknowledged, so the sender tries again. */
    int (*can_deliver)(void *ctx, uint8_t port);
    void *ctx;
};

struct link_peer {
    uint8_t tx_seq;             /* next sequence number to this peer */
    uint8_t rx_last_seq;        /* last fragment delivered from this peer */
    uint8_t rx_valid;           /* rx_last_seq means something */
    struct packet_reasm reasm;
};

struct link {
    uint8_t self;
    struct link_env env;
    uint32_t rng;
    struct link_peer peers[LINK_MAX_STATIONS];
    /* The reliable send in progress. */
    uint8_t tx_active, tx_dst, tx_port, tx_on_air;
    const uint8_t *tx_msg;
    size_t tx_len;
    unsigned tx_index, tx_retries;
    uint32_t tx_rto, tx_deadline;
    /* The fragment in flight follows its predecessor's ACK. 32 bits, between
     * 32-bit fields: GCC 12 merges stores to adjacent bytes into one word
     * store even at an odd address, an address error on the CPU32. */
    uint32_t tx_burst;
    struct frame tx_frame;
    struct link_stats stats;
};

void link_init(struct link *l, uint8_t self, const struct link_env *env, uint32_t seed);
/* Starts a send. Reliable (flags LINK_RELIABLE, dst a station): msg must stay
 * valid until send_done; LINK_EBUSY while another reliable send runs.
 * Datagram (no flag, or dst FRAME_BROADCAST): at most PACKET_DATA_MAX bytes,
 * queued at once, no send_done. LINK_EINVAL for bad arguments. */
int link_send(struct link *l, uint8_t dst, uint8_t port, const uint8_t *msg, size_t len,
              unsigned flags, uint32_t now_ms);
/* A good frame from the air. */
void link_receive(struct link *l, const struct frame *f, uint32_t now_ms);
/* The frame of the given type has left (or been dropped by arbitration):
 * the retransmission timer of a DATA frame starts now. */
void link_frame_done(struct link *l, uint8_t type, uint32_t now_ms);
/* Timers; returns the ms until the next deadline (UINT32_MAX: none). */
uint32_t link_poll(struct link *l, uint32_t now_ms);
int link_busy(const struct link *l);
/* f is the next fragment of the message being sent, handed over right after
 * its predecessor's ACK (not a first fragment, not a retransmission): it may
 * skip the MAC's initial random wait (mac_begin_burst), as a fragment burst
 * in IEEE 802.11 follows its ACK after the short interframe space. */
int link_is_burst(const struct link *l, const struct frame *f);

#endif /* NET_LINK_H */
