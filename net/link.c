/* Reliable channel, datagrams and broadcast; the protocol is in link.h. */
#include "link.h"

static uint32_t link_random(struct link *l)
{
    uint32_t x = l->rng;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    l->rng = x;
    return x;
}

/* a is at or after b on the wrapping ms clock. */
static int link_time_reached(uint32_t now, uint32_t deadline)
{
    return (int32_t)(now - deadline) >= 0;
}

void link_init(struct link *l, uint8_t self, const struct link_env *env, uint32_t seed,
               uint8_t session)
{
    unsigned i;
    l->self = self;
    l->session = (uint8_t)(session % LINK_SESSIONS);
    l->env = *env;
    l->rng = seed != 0u ? seed : 0x2545F491u;
    for (i = 0; i < LINK_MAX_STATIONS; i++) {
        l->peers[i].tx_seq = 0;
        l->peers[i].rx_last_seq = 0;
        l->peers[i].rx_valid = 0;
        l->peers[i].rx_session = 0;
        packet_reasm_init(&l->peers[i].reasm);
    }
    l->tx_active = 0;
    l->tx_on_air = 0;
    l->tx_burst = 0;
    l->stats = (struct link_stats){ 0 };
}

/* 0 when the frame was queued for the air. */
static int link_emit(struct link *l, const struct frame *f)
{
    l->stats.frames_sent++;
    return l->env.transmit(l->env.ctx, f);
}

static void link_send_fragment(struct link *l, uint32_t now_ms)
{
    struct frame *f = &l->tx_frame;
    f->src = l->self;
    f->dst = l->tx_dst;
    f->type = LINK_TYPE(LINK_DATA, l->session);
    f->seq = l->peers[l->tx_dst].tx_seq;
    (void)packet_fragment(l->tx_msg, l->tx_len, l->tx_port, l->tx_index, f);
    l->tx_on_air = 0;   /* the timer starts when it has left (link_frame_done) */
    l->tx_burst = 0;    /* link_acked sets it for a continuation */
    /* Refused: as if sent and lost, so the timer still brings it back. */
    if (link_emit(l, f) != 0)
        link_frame_done(l, f, now_ms);
}

int link_send(struct link *l, uint8_t dst, uint8_t port, const uint8_t *msg, size_t len,
              unsigned flags, uint32_t now_ms)
{
    struct frame f;
    if (port >= NET_PORTS || len > NET_MSG_MAX || (msg == NULL && len > 0u) ||
        (dst >= LINK_MAX_STATIONS && dst != FRAME_BROADCAST) || dst == l->self)
        return LINK_EINVAL;
    if ((flags & LINK_RELIABLE) != 0u && dst != FRAME_BROADCAST) {
        if (l->tx_active)
            return LINK_EBUSY;
        l->tx_active = 1;
        l->tx_dst = dst;
        l->tx_port = port;
        l->tx_msg = msg;
        l->tx_len = len;
        l->tx_index = 0;
        l->tx_retries = 0;
        l->tx_rto = LINK_RTO_MS;
        link_send_fragment(l, now_ms);
        return LINK_OK;
    }
    if (len > PACKET_DATA_MAX)
        return LINK_EINVAL;
    f.src = l->self;
    f.dst = dst;
    f.type = LINK_TYPE(LINK_DGRAM, l->session);
    f.seq = 0;
    (void)packet_fragment(msg, len, port, 0, &f);
    return link_emit(l, &f) == 0 ? LINK_OK : LINK_ENOBUFS;
}

static void link_finish(struct link *l, int result)
{
    l->tx_active = 0;
    l->tx_on_air = 0;
    if (result != LINK_OK) {
        /* The peer may have the fragment without us having its ACK: the next
         * message must not reuse the number, or it would be taken for a repeat. */
        l->peers[l->tx_dst].tx_seq++;
        l->stats.unreachable++;
    }
    l->env.send_done(l->env.ctx, result);
}

static void link_acked(struct link *l, const struct frame *f, uint32_t now_ms)
{
    struct link_peer *p = &l->peers[l->tx_dst];
    if (!l->tx_active || f->src != l->tx_dst || f->seq != p->tx_seq ||
        LINK_SESSION(f->type) != l->session) {
        l->stats.stale_acks++;          /* late, stray, or for a previous boot */
        return;
    }
    p->tx_seq++;
    l->tx_index++;
    l->tx_retries = 0;
    l->tx_rto = LINK_RTO_MS;
    if (l->tx_index >= packet_count(l->tx_len)) {
        link_finish(l, LINK_OK);
    } else {
        link_send_fragment(l, now_ms);
        l->tx_burst = 1;
    }
}

static void link_deliver_fragment(struct link *l, struct link_peer *p, const struct frame *f)
{
    int r = packet_reasm_add(&p->reasm, f->payload, f->len);
    if (r == PACKET_COMPLETE) {
        l->stats.delivered++;
        l->env.deliver(l->env.ctx, f->src, p->reasm.port, p->reasm.data, p->reasm.len);
    } else if (r == PACKET_ERROR) {
        l->stats.reasm_errors++;
    }
}

void link_receive(struct link *l, const struct frame *f, uint32_t now_ms)
{
    struct link_peer *p;
    struct frame ack;
    uint8_t session = LINK_SESSION(f->type);
    if ((f->dst != l->self && f->dst != FRAME_BROADCAST) || f->src >= LINK_MAX_STATIONS ||
        f->src == l->self)
        return;
    l->stats.frames_received++;
    p = &l->peers[f->src];
    switch (LINK_KIND(f->type)) {
    case LINK_ACK:
        if (f->dst == l->self)
            link_acked(l, f, now_ms);
        break;
    case LINK_DATA:
        if (f->dst != l->self)
            break;
        if (p->rx_valid && p->rx_session != session) {
            /* The peer restarted: its numbers begin again, and a message it
             * had half sent is gone. */
            p->rx_valid = 0;
            packet_reasm_init(&p->reasm);
            l->stats.new_sessions++;
        }
        if ((f->len >= PACKET_HDR_LEN && (f->payload[1] & PACKET_LAST) != 0u) &&
            !(p->rx_valid && p->rx_last_seq == f->seq) && l->env.can_deliver != NULL &&
            !l->env.can_deliver(l->env.ctx, f->payload[0])) {
            l->stats.rx_busy++;         /* no room at the port: no ACK, the sender retries */
            break;
        }
        ack.src = l->self;
        ack.dst = f->src;
        ack.type = LINK_TYPE(LINK_ACK, session);
        ack.seq = f->seq;
        ack.len = 0;
        l->stats.acks_sent++;
        (void)link_emit(l, &ack);       /* refused: lost as on air, the sender retries */
        if (p->rx_valid && p->rx_last_seq == f->seq) {
            l->stats.duplicates++;
            break;
        }
        p->rx_valid = 1;
        p->rx_session = session;
        p->rx_last_seq = f->seq;
        link_deliver_fragment(l, p, f);
        break;
    case LINK_DGRAM: {
        /* Datagrams are single fragments; their own reassembly slot would only
         * hold one, so use a local one and leave the reliable stream's alone. */
        struct packet_reasm one;
        packet_reasm_init(&one);
        if (packet_reasm_add(&one, f->payload, f->len) == PACKET_COMPLETE) {
            l->stats.delivered++;
            l->env.deliver(l->env.ctx, f->src, one.port, one.data, one.len);
        } else {
            l->stats.reasm_errors++;
        }
        break;
    }
    default:
        break;
    }
}

int link_frame_current(const struct link *l, const struct frame *f)
{
    return l->tx_active && f->type == LINK_TYPE(LINK_DATA, l->session) &&
           f->src == l->self && f->dst == l->tx_dst && f->seq == l->peers[l->tx_dst].tx_seq;
}

void link_frame_done(struct link *l, const struct frame *f, uint32_t now_ms)
{
    if (link_frame_current(l, f) && !l->tx_on_air) {
        l->tx_on_air = 1;
        l->tx_deadline = now_ms + l->tx_rto + link_random(l) % (l->tx_rto / 4u + 1u);
    }
}

uint32_t link_poll(struct link *l, uint32_t now_ms)
{
    if (!l->tx_active || !l->tx_on_air)
        return UINT32_MAX;
    if (!link_time_reached(now_ms, l->tx_deadline))
        return l->tx_deadline - now_ms;
    if (++l->tx_retries > LINK_MAX_RETRIES) {
        link_finish(l, LINK_EUNREACH);
        return UINT32_MAX;
    }
    l->stats.retransmissions++;
    l->tx_rto = l->tx_rto * 2u > LINK_RTO_MAX_MS ? LINK_RTO_MAX_MS : l->tx_rto * 2u;
    link_send_fragment(l, now_ms);
    /* A refused frame armed its timer again at once. */
    return l->tx_active && l->tx_on_air ? l->tx_deadline - now_ms : UINT32_MAX;
}

int link_busy(const struct link *l)
{
    return l->tx_active;
}

int link_is_burst(const struct link *l, const struct frame *f)
{
    return l->tx_burst && link_frame_current(l, f);
}
