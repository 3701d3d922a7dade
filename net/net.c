/* The network service thread and the application interface; see net.h. */
#include "net.h"
#include "kernel.h"
#include "mac.h"
#include "radio.h"
#include "fec.h"
#include "auth.h"

#if FRAME_TRAILER_MAX != AUTH_TRAILER_LEN || FRAME_PAYLOAD_MAX != AUTH_PAYLOAD_MAX
#error "frame.h's room for the trailer must be auth.h's trailer after the link's payload"
#endif
#if LINK_MAX_STATIONS > AUTH_STATIONS
#error "auth.h keeps a counter for every station of the link"
#endif

#define NET_EV_RX   0x1u
#define NET_EV_TX   0x2u
#define NET_EV_REQ  0x4u
/* Datagrams waiting for the air; a full queue refuses the next (NET_ENOBUFS). */
#define NET_DGRAM_QUEUE 4u
#define NET_SEND_TIMEOUT_MS 60000u   /* far above the link's ~8 s of retries */

struct net_msg {
    uint8_t src;
    uint8_t port;
    uint16_t len;
    uint8_t data[NET_MSG_MAX];
};

struct net_request {
    uint8_t dst, port;
    const uint8_t *data;
    size_t len;
    unsigned flags;
    int result;
    uint32_t generation;             /* of the net_send call it belongs to */
};

static struct k_thread net_thread;
K_STACK_DEFINE(net_stack, 3072);
static struct k_event net_ev;
static struct k_mutex net_send_lock;  /* one application request at a time */
static struct k_sem net_send_done;
static struct net_request net_req;
static volatile uint8_t net_req_pending;
static volatile uint32_t net_req_generation;
static uint32_t net_active_generation;

static struct k_mq net_port_q[NET_PORTS];
static struct net_msg net_port_store[NET_PORTS][NET_PORT_QUEUE];
static struct net_msg net_rx_msg;     /* the service thread's scratch */

static struct link net_link;
static struct mac net_mac;
/* The transmit side (policies in net/README.md, "Queues"): three queues, so
 * that no kind of frame can crowd out another.
 *   ACKs      one entry per station: a newer ACK to a station replaces its
 *             queued one (stop and wait: the peer waits for its latest frame
 *             only), so the queue is never full;
 *   DATA      the link's frame in flight: one slot, a newer one replaces it
 *             (the older is obsolete: its fragment was acknowledged or given up);
 *   datagrams NET_DGRAM_QUEUE entries; when full, net_send gets NET_ENOBUFS.
 * net_cur points at the frame in arbitration or on air, taken from them in
 * that order; it stays in its queue until it has left (net_pop_tx), so a
 * frame is copied once on its way, header and payload only (copying whole
 * frames twice, byte by byte as the kernel's memcpy does, made net-bench's
 * 16 fragments take 1399-1401 ms instead of 1395 ms). */
enum net_cur_from { NET_CUR_NONE = 0, NET_CUR_ACK, NET_CUR_DATA, NET_CUR_DGRAM };
static struct frame net_ackq[LINK_MAX_STATIONS];
static unsigned net_ackq_head, net_ackq_count;
static struct frame net_data;
static uint8_t net_data_queued;
static struct frame net_dgramq[NET_DGRAM_QUEUE];
static unsigned net_dgramq_head, net_dgramq_count;
static const struct frame *net_cur;
static uint8_t net_cur_from;          /* enum net_cur_from */
static uint8_t net_on_air;            /* net_cur is being transmitted */
static struct net_queue_stats net_qstats;
static uint32_t net_mac_wake;         /* ms; valid while net_mac_waiting */
static uint8_t net_mac_waiting, net_mac_started;
static uint8_t net_encoded[FRAME_ENCODED_MAX > FEC_ENCODED_MAX ? FRAME_ENCODED_MAX
                                                                : FEC_ENCODED_MAX];
static uint32_t net_port_overflows;
static uint8_t net_self;
static uint8_t net_running;
static uint8_t net_fec;
/* Authentication: net_auth_setup's key (the module's) and this boot's counters. */
static struct auth net_auth;
static uint8_t net_auth_on, net_auth_set;
static uint32_t net_auth_epoch;
static uint32_t net_seal_failed;
static struct frame net_sealed;       /* the copy of net_cur that goes on air */
static size_t net_encoded_len;        /* net_encoded holds net_cur's bytes: valid while */
static uint8_t net_prepared;          /* ... this is set (see net_prepare) */

/* The header and the payload's len bytes only: an ACK has none. */
static void net_frame_copy(struct frame *dst, const struct frame *src)
{
    uint16_t i;
    dst->len = src->len;
    dst->src = src->src;
    dst->dst = src->dst;
    dst->type = src->type;
    dst->seq = src->seq;
    for (i = 0; i < src->len && i < FRAME_PAYLOAD_MAX; i++)
        dst->payload[i] = src->payload[i];
}

static int net_queue_ack(const struct frame *f)
{
    /* The head may be net_cur: it is not changed under the transmitter. */
    unsigned i = net_cur_from == NET_CUR_ACK ? 1u : 0u;
    for (; i < net_ackq_count; i++) {
        struct frame *q = &net_ackq[(net_ackq_head + i) % LINK_MAX_STATIONS];
        if (q->dst == f->dst) {
            net_frame_copy(q, f);
            net_qstats.acks_replaced++;
            return 0;
        }
    }
    /* At most one entry per peer and the one on its way: not reached. */
    if (net_ackq_count == LINK_MAX_STATIONS) {
        net_qstats.acks_dropped++;
        return -1;
    }
    net_frame_copy(&net_ackq[(net_ackq_head + net_ackq_count) % LINK_MAX_STATIONS], f);
    net_ackq_count++;
    return 0;
}

static int net_transmit_cb(void *ctx, const struct frame *f)
{
    (void)ctx;
    switch (LINK_KIND(f->type)) {
    case LINK_ACK:
        return net_queue_ack(f);
    case LINK_DATA:
        /* The link hands over a DATA frame only after its previous one has
         * left, except when a late ACK moves it on while a retransmission
         * still waits for the channel: then the next fragment goes instead. */
        if (net_data_queued)
            net_qstats.data_replaced++;
        net_frame_copy(&net_data, f);
        if (net_cur_from == NET_CUR_DATA)
            net_prepared = 0;         /* in arbitration: its on-air bytes are stale */
        net_data_queued = 1;
        return 0;
    default:
        if (net_dgramq_count == NET_DGRAM_QUEUE) {
            net_qstats.dgrams_refused++;
            return -1;
        }
        net_frame_copy(&net_dgramq[(net_dgramq_head + net_dgramq_count) % NET_DGRAM_QUEUE], f);
        net_dgramq_count++;
        return 0;
    }
}

/* Points net_cur at the next frame for the air: ACKs first (they answer a
 * frame just heard and win the channel), then the link's DATA frame, then
 * datagrams. 0 when there is none. */
static int net_take_next(void)
{
    if (net_ackq_count > 0u) {
        net_cur = &net_ackq[net_ackq_head];
        net_cur_from = NET_CUR_ACK;
    } else if (net_data_queued) {
        net_cur = &net_data;
        net_cur_from = NET_CUR_DATA;
    } else if (net_dgramq_count > 0u) {
        net_cur = &net_dgramq[net_dgramq_head];
        net_cur_from = NET_CUR_DGRAM;
    } else {
        return 0;
    }
    net_mac_started = 0;
    net_mac_waiting = 0;
    net_prepared = 0;
    return 1;
}

/* Takes net_cur out of its queue. */
static void net_drop_cur(void)
{
    if (net_cur_from == NET_CUR_ACK) {
        net_ackq_head = (net_ackq_head + 1u) % LINK_MAX_STATIONS;
        net_ackq_count--;
    } else if (net_cur_from == NET_CUR_DATA) {
        net_data_queued = 0;
    } else if (net_cur_from == NET_CUR_DGRAM) {
        net_dgramq_head = (net_dgramq_head + 1u) % NET_DGRAM_QUEUE;
        net_dgramq_count--;
    }
    net_cur_from = NET_CUR_NONE;
    net_mac_started = 0;
    net_mac_waiting = 0;
    net_prepared = 0;
}

static void net_deliver_cb(void *ctx, uint8_t src, uint8_t port, const uint8_t *msg, size_t len)
{
    size_t i;
    (void)ctx;
    net_rx_msg.src = src;
    net_rx_msg.port = port;
    net_rx_msg.len = (uint16_t)len;
    for (i = 0; i < len; i++)
        net_rx_msg.data[i] = msg[i];
    if (k_mq_send_ticks(&net_port_q[port], &net_rx_msg, K_NO_WAIT) != K_OK)
        net_port_overflows++;
}

static int net_can_deliver_cb(void *ctx, uint8_t port)
{
    (void)ctx;
    return port < NET_PORTS && k_mq_count(&net_port_q[port]) < (int)NET_PORT_QUEUE;
}

static void net_send_done_cb(void *ctx, int result)
{
    (void)ctx;
    if (net_active_generation == net_req_generation) {
        net_req.result = result;
        (void)k_sem_post(&net_send_done);
    }
}

/* net_cur has left, or was given up: a DATA frame's timer starts now. */
static void net_pop_tx(uint32_t now)
{
    link_frame_done(&net_link, net_cur, now);
    net_drop_cur();
}

/* Seals a copy of f and encodes it into net_encoded, before arbitration:
 * sealing costs 1.3-4.6 ms on the CPU32 (net/README.md), and done between
 * the carrier check and the transmitter it let another station find the
 * channel idle and collide. net_cur stays as the link made it
 * (link_frame_current compares it), and each transmission, a retransmission
 * too, gets a fresh counter: a receiver that took the first copy but whose
 * ACK was lost refuses the old counter as a replay. 0 when sealing or
 * encoding failed (the frame is dropped, counted in net_seal_failed). */
static int net_prepare(const struct frame *f)
{
    if (net_auth_on) {
        uint8_t header[AUTH_HEADER_LEN];
        int sealed;
        net_frame_copy(&net_sealed, f);
        header[0] = f->src;
        header[1] = f->dst;
        header[2] = f->type;
        header[3] = f->seq;
        sealed = auth_seal(&net_auth, header, net_sealed.payload, net_sealed.len,
                           sizeof net_sealed.payload);
        if (sealed < 0)
            return 0;
        net_sealed.len = (uint16_t)sealed;
        f = &net_sealed;
    }
    net_encoded_len = net_fec ? fec_frame_encode(f, net_encoded, sizeof net_encoded)
                              : frame_encode(f, net_encoded, sizeof net_encoded);
    net_prepared = net_encoded_len > 0u;
    return net_prepared;
}

/* Arbitration and transmission of net_cur; returns ms to wait. */
static uint32_t net_pump_tx(uint32_t now)
{
    while (!net_on_air && (net_cur_from != NET_CUR_NONE || net_take_next())) {
        const struct frame *f = net_cur;
        uint32_t wait = 0;
        int action;
        if (net_cur_from == NET_CUR_DATA && !link_frame_current(&net_link, f)) {
            /* A retransmission whose fragment was acknowledged meanwhile. */
            net_qstats.data_obsolete++;
            net_drop_cur();
            continue;
        }
        if (!net_prepared && !net_prepare(f)) {
            net_seal_failed++;
            net_pop_tx(now);
            continue;
        }
        if (net_mac_waiting) {
            if ((int32_t)(now - net_mac_wake) < 0)
                return net_mac_wake - now;
            net_mac_waiting = 0;
        }
        if (!net_mac_started) {
            if (link_is_burst(&net_link, f))
                mac_begin_burst(&net_mac);
            else
                mac_begin(&net_mac);
            net_mac_started = 1;
        }
        action = mac_decide(&net_mac, radio_carrier(), LINK_KIND(f->type) == LINK_ACK, &wait);
        if (action == MAC_WAIT) {
            net_mac_waiting = 1;
            net_mac_wake = now + wait;
            return wait;
        }
        if (action == MAC_DROP) {
            net_pop_tx(now);
            continue;
        }
        if (radio_transmit(net_encoded, net_encoded_len) != K_OK) {
            net_pop_tx(now);
            continue;
        }
        net_on_air = 1;
        return UINT32_MAX;        /* the TX-done event comes back */
    }
    return UINT32_MAX;
}

/* A received frame for the link? Frames to another station pass untouched
 * (the link ignores them; opening them would cost the time of a MIC each).
 * Frames to this station or broadcast must open with the key and a counter
 * above the last taken from their source; the trailer is then cut off.
 * Refused frames are counted in net_auth.stats and dropped. */
static int net_open(struct frame *f)
{
    uint8_t header[AUTH_HEADER_LEN];
    int rc;
    if (!net_auth_on)
        return f->len <= FRAME_PAYLOAD_MAX;   /* a sealed frame's length: not for us */
    if (f->dst != net_self && f->dst != FRAME_BROADCAST)
        return 1;
    header[0] = f->src;
    header[1] = f->dst;
    header[2] = f->type;
    header[3] = f->seq;
    rc = auth_open(&net_auth, header, f->payload, f->len);
    if (rc < 0)
        return 0;
    f->len = (uint16_t)rc;
    return 1;
}

static void *net_main(void *arg)
{
    (void)arg;
    for (;;) {
        uint32_t now = k_uptime_ms(), wait, w, matched = 0;
        struct frame f;
        k_ticks_t ticks;

        while (radio_receive(&f))
            if (net_open(&f))
                link_receive(&net_link, &f, now);
        if (net_req_pending && !link_busy(&net_link)) {
            int rc;
            net_req_pending = 0;
            net_active_generation = net_req_generation;
            rc = link_send(&net_link, net_req.dst, net_req.port, net_req.data, net_req.len,
                           net_req.flags, now);
            if (rc != LINK_OK || (net_req.flags & NET_RELIABLE) == 0u ||
                net_req.dst == NET_BROADCAST) {
                net_req.result = rc;
                (void)k_sem_post(&net_send_done);
            }
        }
        wait = link_poll(&net_link, now);
        w = net_pump_tx(now);
        if (w < wait)
            wait = w;
        ticks = wait == UINT32_MAX ? k_ms_to_ticks(1000) : k_ms_to_ticks(wait);
        if (ticks == 0u)
            ticks = 1;
        (void)k_event_wait(&net_ev, NET_EV_RX | NET_EV_TX | NET_EV_REQ,
                           K_EVENT_ANY | K_EVENT_CLEAR, ticks, &matched);
        if ((matched & NET_EV_TX) != 0u && net_on_air && !radio_tx_busy()) {
            net_on_air = 0;
            net_pop_tx(k_uptime_ms());
        }
    }
    return NULL;
}

const uint8_t net_auth_dev_key[NET_AUTH_KEY_LEN] = {
    'b', 's', 'c', 'h', 'e', 'd', '-', 'd', 'e', 'v', '-', 'k', 'e', 'y', '!', '!'
};

int net_auth_setup(const uint8_t *key, uint32_t epoch)
{
    if (net_running || epoch > AUTH_EPOCH_MAX)
        return K_EINVAL;
    if (key != NULL && net_auth_init(key) != AUTH_OK)
        return K_EINVAL;
    net_auth_on = key != NULL;
    net_auth_epoch = epoch;
    net_auth_set = 1;
    return K_OK;
}

int net_init(uint8_t station, uint32_t seed)
{
    return net_init_flags(station, seed, 0u);
}

int net_init_flags(uint8_t station, uint32_t seed, unsigned flags)
{
    static const struct link_env env = {
        net_transmit_cb, net_deliver_cb, net_send_done_cb, net_can_deliver_cb, NULL
    };
    unsigned i;
    int rc;
    if (net_running || station >= LINK_MAX_STATIONS || !net_auth_set ||
        auth_init(&net_auth, net_auth_epoch) != AUTH_OK)
        return K_EINVAL;
    net_self = station;
    if ((rc = k_event_init(&net_ev)) != K_OK || (rc = k_mutex_init(&net_send_lock)) != K_OK ||
        (rc = k_sem_init(&net_send_done, 0, 1)) != K_OK)
        return rc;
    for (i = 0; i < NET_PORTS; i++) {
        rc = k_mq_init(&net_port_q[i], net_port_store[i], sizeof(struct net_msg), NET_PORT_QUEUE);
        if (rc != K_OK)
            return rc;
    }
    /* The session is the epoch's remainder: the epoch grows per boot (net.h). */
    link_init(&net_link, station, &env, seed * 2654435761u + station + 1u,
              (uint8_t)(net_auth_epoch % LINK_SESSIONS));
    mac_init(&net_mac, seed * 40503u + station * 7919u + 1u);
    net_ackq_head = net_ackq_count = 0;
    net_dgramq_head = net_dgramq_count = 0;
    net_data_queued = 0;
    net_cur_from = NET_CUR_NONE;
    net_on_air = 0;
    net_fec = (flags & NET_FEC) != 0u;
    if (net_fec && fec_init() != 0)
        return K_EINVAL;
    if ((rc = radio_init(&net_ev, NET_EV_RX, NET_EV_TX, net_fec)) != K_OK)
        return rc;
    rc = k_thread_create(&net_thread, "net", net_main, NULL, net_stack, sizeof net_stack,
                         NET_PRIO);
    if (rc == K_OK)
        net_running = 1;
    return rc;
}

uint8_t net_station(void)
{
    return net_self;
}

int net_send(uint8_t dst, uint8_t port, const void *data, size_t len, unsigned flags)
{
    int rc;
    if (!net_running)
        return K_EINVAL;
    rc = k_mutex_lock_ticks(&net_send_lock, k_ms_to_ticks(NET_SEND_TIMEOUT_MS));
    if (rc != K_OK && rc != K_EOWNERDEAD)
        return rc;
    (void)k_sem_trywait(&net_send_done);          /* a stale post of an abandoned call */
    net_req.dst = dst;
    net_req.port = port;
    net_req.data = data;
    net_req.len = len;
    net_req.flags = flags;
    net_req.result = K_ETIMEDOUT;
    net_req_generation++;
    net_req_pending = 1;
    (void)k_event_set(&net_ev, NET_EV_REQ);
    rc = k_sem_wait_ticks(&net_send_done, k_ms_to_ticks(NET_SEND_TIMEOUT_MS));
    if (rc == K_OK) {
        rc = net_req.result;
    } else {
        /* Abandoned: the service thread must not report into the next call. */
        net_req_pending = 0;
        net_req_generation++;
        rc = K_ETIMEDOUT;
    }
    (void)k_mutex_unlock(&net_send_lock);
    return rc;
}

int net_recv(uint8_t port, void *buf, size_t size, uint8_t *src, uint32_t timeout_ms)
{
    /* Static, one per port: a message is 516 bytes, too big for application
     * stacks; one reader at a time per port is the contract (net.h). */
    static struct net_msg msgs[NET_PORTS];
    struct net_msg *m;
    size_t i, n;
    int rc;
    if (!net_running || port >= NET_PORTS || (buf == NULL && size > 0u))
        return K_EINVAL;
    m = &msgs[port];
    rc = k_mq_receive_ticks(&net_port_q[port], m,
                            timeout_ms == 0u ? K_NO_WAIT : k_ms_to_ticks(timeout_ms));
    if (rc == K_EAGAIN)
        return K_ETIMEDOUT;
    if (rc != K_OK)
        return rc;
    n = m->len < size ? m->len : size;
    for (i = 0; i < n; i++)
        ((uint8_t *)buf)[i] = m->data[i];
    if (src != NULL)
        *src = m->src;
    return (int)m->len;
}

void net_stats_get(struct net_stats *out)
{
    struct radio_stats r;
    struct frame_rx_stats fr;
    radio_stats_get(&r, &fr);
    out->frames_sent = net_link.stats.frames_sent;
    out->frames_received = fr.frames;
    out->crc_errors = fr.crc_errors;
    out->malformed = fr.malformed;
    out->retransmissions = net_link.stats.retransmissions;
    out->collisions = r.collisions;
    out->deferrals = net_mac.deferrals;
    out->mac_drops = net_mac.drops;
    out->duplicates = net_link.stats.duplicates;
    out->delivered = net_link.stats.delivered;
    out->unreachable = net_link.stats.unreachable;
    out->port_refused = net_link.stats.rx_busy;
    out->port_overflows = net_port_overflows;
    out->rx_overruns = r.rx_overruns;
    out->rx_ring_full = r.rx_ring_full;
    out->stale_acks = net_link.stats.stale_acks;
    out->new_sessions = net_link.stats.new_sessions;
    out->txq = net_qstats;
    out->fec_corrected = r.fec.corrected;
    out->fec_failed = r.fec.uncorrectable + r.fec.bad_frames + r.fec_bad_count;
    out->auth_forged = net_auth.stats.forged;
    out->auth_replayed = net_auth.stats.replayed;
    out->auth_malformed = net_auth.stats.malformed;
    out->auth_seal_failed = net_seal_failed;
}

int net_stats_print(void)
{
    struct net_stats s;
    net_stats_get(&s);
    k_printf("net: station %u\n", (unsigned)net_self);
    k_printf("  frames sent %lu, received %lu, crc errors %lu, malformed %lu\n",
             (unsigned long)s.frames_sent, (unsigned long)s.frames_received,
             (unsigned long)s.crc_errors, (unsigned long)s.malformed);
    k_printf("  retransmissions %lu, collisions %lu, deferrals %lu, mac drops %lu\n",
             (unsigned long)s.retransmissions, (unsigned long)s.collisions,
             (unsigned long)s.deferrals, (unsigned long)s.mac_drops);
    k_printf("  messages delivered %lu, duplicates dropped %lu, unreachable %lu, "
             "stale acks %lu, new sessions %lu\n",
             (unsigned long)s.delivered, (unsigned long)s.duplicates,
             (unsigned long)s.unreachable, (unsigned long)s.stale_acks,
             (unsigned long)s.new_sessions);
    k_printf("  rx full: port refused %lu, port overflows %lu, ring full %lu, overruns %lu\n",
             (unsigned long)s.port_refused, (unsigned long)s.port_overflows,
             (unsigned long)s.rx_ring_full, (unsigned long)s.rx_overruns);
    k_printf("  tx queues: acks replaced %lu, acks dropped %lu, data replaced %lu, "
             "data obsolete %lu, datagrams refused %lu\n",
             (unsigned long)s.txq.acks_replaced, (unsigned long)s.txq.acks_dropped,
             (unsigned long)s.txq.data_replaced, (unsigned long)s.txq.data_obsolete,
             (unsigned long)s.txq.dgrams_refused);
    k_printf("  radio %lu baud%s%s\n", (unsigned long)radio_baud(), net_fec ? ", fec" : "",
             net_auth_on ? ", auth" : ", auth off");
    if (net_auth_on)
        k_printf("  auth: epoch %lu, forged %lu, replayed %lu, malformed %lu, seal failed %lu\n",
                 (unsigned long)net_auth_epoch, (unsigned long)s.auth_forged,
                 (unsigned long)s.auth_replayed, (unsigned long)s.auth_malformed,
                 (unsigned long)s.auth_seal_failed);
    if (net_fec)
        k_printf("  fec: bytes corrected %lu, frames beyond the code %lu\n",
                 (unsigned long)s.fec_corrected, (unsigned long)s.fec_failed);
    return 0;
}
