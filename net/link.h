/*
 * The link protocol above framing: a reliable channel per peer, unreliable
 * datagrams and broadcast, on the packetizing of packet.h. Pure logic: the
 * caller supplies the clock (ms), sends the frames the link hands it (after
 * media arbitration) and feeds it the frames received. net.c runs it in the
 * network service thread; the host tests run several links on a simulated
 * lossy channel; the host peer (tools/netpeer) implements the same protocol.
 *
 * Frame types: frame.type holds the kind (bits 1-0) and the sender's
 * session (bits 7-2, LINK_TYPE):
 *   LINK_DATA   reliable fragment, seq = per-peer sequence number
 *   LINK_ACK    acknowledges the DATA frame with the same seq and session,
 *               no payload
 *   LINK_DGRAM  unreliable datagram (one fragment), unicast or broadcast
 *   kind 0      reserved (room for an extended header: net/README.md)
 * Sessions: sequence numbers restart at 0 when a station restarts, so a
 * receiver that still holds the last number of the station's previous boot
 * would take the first message of the new one for a repeat. Every station
 * carries a per-boot session number (link_init's session; net_init derives
 * it from its seed) in its DATA frames; a DATA frame with another session
 * than the last one from that peer starts the peer's receive state afresh.
 * An ACK carries the session of the DATA frame it answers, so the sender
 * counts only an ACK for its outstanding frame: right station, seq, session.
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
#define LINK_KIND_MASK     0x03u
#define LINK_SESSION_SHIFT 2u
#define LINK_SESSIONS      64u      /* session numbers 0..63 */
#define LINK_TYPE(kind, session) \
    ((uint8_t)((kind) | (((unsigned)(session) % LINK_SESSIONS) << LINK_SESSION_SHIFT)))
#define LINK_KIND(type)    ((uint8_t)((type) & LINK_KIND_MASK))
#define LINK_SESSION(type) ((uint8_t)((type) >> LINK_SESSION_SHIFT))

#define LINK_MAX_STATIONS 16u   /* station numbers 0..15; FRAME_BROADCAST = all */
#define LINK_RTO_MS       250u
#define LINK_RTO_MAX_MS   1000u
#define LINK_MAX_RETRIES  8u

#define LINK_OK          0
#define LINK_EINVAL    (-22)
#define LINK_EBUSY     (-16)
#define LINK_EUNREACH (-113)
#define LINK_ENOBUFS  (-105)     /* a datagram the transmit queue refused */

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
    uint32_t stale_acks;        /* ACKs for no outstanding frame (station, seq, session) */
    uint32_t new_sessions;      /* a peer restarted: its receive state began afresh */
};

struct link_env {
    /* Queue f for the air (media arbitration follows); the link may reuse f.
     * 0 when queued. Non-zero when refused (a full queue): a refused DATA
     * frame counts as sent and lost, so its retransmission timer runs; a
     * refused datagram makes link_send fail with LINK_ENOBUFS; a refused
     * ACK is lost (its sender retransmits). The link never loses its own
     * frame silently. */
    int (*transmit)(void *ctx, const struct frame *f);
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
    uint8_t rx_valid;           /* rx_last_seq and rx_session mean something */
    uint8_t rx_session;         /* the peer's session of rx_last_seq */
    struct packet_reasm reasm;
};

struct link {
    uint8_t self;
    uint8_t session;            /* this boot's, 0..LINK_SESSIONS-1 */
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

/* session: this boot's session number (taken modulo LINK_SESSIONS); it must
 * differ from the station's previous boot's (see Sessions above). */
void link_init(struct link *l, uint8_t self, const struct link_env *env, uint32_t seed,
               uint8_t session);
/* Starts a send. Reliable (flags LINK_RELIABLE, dst a station): msg must stay
 * valid until send_done; LINK_EBUSY while another reliable send runs.
 * Datagram (no flag, or dst FRAME_BROADCAST): at most PACKET_DATA_MAX bytes,
 * queued at once, no send_done; LINK_ENOBUFS when transmit refused it.
 * LINK_EINVAL for bad arguments. */
int link_send(struct link *l, uint8_t dst, uint8_t port, const uint8_t *msg, size_t len,
              unsigned flags, uint32_t now_ms);
/* A good frame from the air. */
void link_receive(struct link *l, const struct frame *f, uint32_t now_ms);
/* Frame f has left (or been dropped by arbitration): if it is the link's
 * DATA frame in flight (link_frame_current), its retransmission timer starts now. */
void link_frame_done(struct link *l, const struct frame *f, uint32_t now_ms);
/* f is the DATA frame the link is waiting to send (not an older copy of a
 * fragment since acknowledged): the transmit queue drops obsolete copies. */
int link_frame_current(const struct link *l, const struct frame *f);
/* Timers; returns the ms until the next deadline (UINT32_MAX: none). */
uint32_t link_poll(struct link *l, uint32_t now_ms);
int link_busy(const struct link *l);
/* f is the next fragment of the message being sent, handed over right after
 * its predecessor's ACK (not a first fragment, not a retransmission): it may
 * skip the MAC's initial random wait (mac_begin_burst), as a fragment burst
 * in IEEE 802.11 follows its ACK after the short interframe space. */
int link_is_burst(const struct link *l, const struct frame *f);

#endif /* NET_LINK_H */
