/* Host tests of the reliable channel (link.c) and packetizing (packet.c):
 * stations on a simulated channel that loses frames deterministically. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "net/link.h"
#include "net/packet.h"

#define STATIONS 3
#define QMAX 64

struct station {
    struct link link;
    struct frame q[QMAX];         /* frames on their way */
    unsigned nq;
    uint8_t got[8][NET_MSG_MAX];
    size_t got_len[8];
    uint8_t got_src[8];
    unsigned ngot;
    int done, result;
};

static struct station st[STATIONS];
static unsigned loss_every;       /* drop every n-th frame on the air (0: none) */
static unsigned air_count;
static int down[STATIONS];        /* station switched off */
static unsigned refuse;           /* the transmit queue refuses the next n frames */

static int tx(void *ctx, const struct frame *f)
{
    struct station *s = ctx;
    if (refuse > 0u) {
        refuse--;
        return -1;
    }
    assert_true(s->nq < QMAX);
    s->q[s->nq++] = *f;
    return 0;
}

static void deliver(void *ctx, uint8_t src, uint8_t port, const uint8_t *msg, size_t len)
{
    struct station *s = ctx;
    (void)port;
    if (s->ngot < 8) {
        memcpy(s->got[s->ngot], msg, len);
        s->got_len[s->ngot] = len;
        s->got_src[s->ngot] = src;
    }
    s->ngot++;
}

static void done(void *ctx, int result)
{
    struct station *s = ctx;
    s->done = 1;
    s->result = result;
}

static int setup(void **state)
{
    unsigned i;
    (void)state;
    memset(st, 0, sizeof st);
    memset(down, 0, sizeof down);
    loss_every = 0;
    air_count = 0;
    refuse = 0;
    for (i = 0; i < STATIONS; i++) {
        struct link_env env = { tx, deliver, done, NULL, &st[i] };
        link_init(&st[i].link, (uint8_t)i, &env, i + 1u, (uint8_t)(10u + i));
    }
    return 0;
}

/* Runs the air for up to ms milliseconds of simulated time, 1 ms per step. */
static void run(uint32_t *now, uint32_t ms)
{
    uint32_t end = *now + ms;
    while (*now < end) {
        unsigned i, j, k;
        for (i = 0; i < STATIONS; i++) {
            for (k = 0; k < st[i].nq; k++) {
                struct frame f = st[i].q[k];
                air_count++;
                link_frame_done(&st[i].link, &f, *now);
                if (down[i] || (loss_every && air_count % loss_every == 0u))
                    continue;
                for (j = 0; j < STATIONS; j++)
                    if (j != i && !down[j])
                        link_receive(&st[j].link, &f, *now);
            }
            st[i].nq = 0;
            (void)link_poll(&st[i].link, *now);
        }
        (*now)++;
    }
}

static void test_reliable_multi_fragment(void **state)
{
    uint8_t msg[300];
    uint32_t now = 0;
    unsigned i;
    (void)state;
    for (i = 0; i < sizeof msg; i++)
        msg[i] = (uint8_t)(i * 3u);
    assert_int_equal(link_send(&st[0].link, 1, 4, msg, sizeof msg, LINK_RELIABLE, now), LINK_OK);
    assert_int_equal(link_send(&st[0].link, 2, 4, msg, 5, LINK_RELIABLE, now), LINK_EBUSY);
    run(&now, 100);
    assert_true(st[0].done);
    assert_int_equal(st[0].result, LINK_OK);
    assert_int_equal(st[1].ngot, 1);
    assert_int_equal(st[1].got_len[0], sizeof msg);
    assert_memory_equal(st[1].got[0], msg, sizeof msg);
    assert_int_equal(st[2].ngot, 0);                   /* not for station 2 */
    assert_int_equal(st[0].link.stats.retransmissions, 0);
}

static void test_loss_retransmits_without_duplicates(void **state)
{
    uint8_t msg[4] = { 1, 2, 3, 4 };
    uint32_t now = 0;
    unsigned m;
    (void)state;
    loss_every = 4;                                    /* a quarter of all frames lost */
    for (m = 0; m < 6; m++) {
        msg[0] = (uint8_t)m;
        st[0].done = 0;
        assert_int_equal(link_send(&st[0].link, 1, 0, msg, 4, LINK_RELIABLE, now), LINK_OK);
        run(&now, 20000);
        assert_true(st[0].done);
        assert_int_equal(st[0].result, LINK_OK);
    }
    assert_int_equal(st[1].ngot, 6);
    for (m = 0; m < 6; m++)
        assert_int_equal(st[1].got[m][0], m);          /* in order, each once */
    assert_true(st[0].link.stats.retransmissions > 0);
    assert_true(st[1].link.stats.duplicates > 0);      /* lost ACKs caused repeats */
}

static void test_unreachable_then_recovers(void **state)
{
    uint8_t msg[2] = { 9, 9 };
    uint32_t now = 0;
    (void)state;
    down[1] = 1;
    assert_int_equal(link_send(&st[0].link, 1, 0, msg, 2, LINK_RELIABLE, now), LINK_OK);
    run(&now, 30000);
    assert_true(st[0].done);
    assert_int_equal(st[0].result, LINK_EUNREACH);
    assert_int_equal(st[0].link.stats.retransmissions, LINK_MAX_RETRIES);
    /* Station 2 is still served. */
    st[0].done = 0;
    assert_int_equal(link_send(&st[0].link, 2, 0, msg, 2, LINK_RELIABLE, now), LINK_OK);
    run(&now, 100);
    assert_int_equal(st[0].result, LINK_OK);
    assert_int_equal(st[2].ngot, 1);
    /* Station 1 back: the next message gets through. */
    down[1] = 0;
    st[0].done = 0;
    assert_int_equal(link_send(&st[0].link, 1, 0, msg, 2, LINK_RELIABLE, now), LINK_OK);
    run(&now, 100);
    assert_int_equal(st[0].result, LINK_OK);
    assert_int_equal(st[1].ngot, 1);
}

static void test_broadcast_and_datagram(void **state)
{
    uint8_t big[PACKET_DATA_MAX + 1];
    uint32_t now = 0;
    (void)state;
    memset(big, 1, sizeof big);
    assert_int_equal(link_send(&st[0].link, FRAME_BROADCAST, 3, (const uint8_t *)"hi", 2, 0, now),
                     LINK_OK);
    assert_int_equal(link_send(&st[0].link, 2, 3, (const uint8_t *)"dg", 2, 0, now), LINK_OK);
    assert_int_equal(link_send(&st[0].link, 2, 3, big, sizeof big, 0, now), LINK_EINVAL);
    run(&now, 5);
    assert_int_equal(st[1].ngot, 1);
    assert_int_equal(st[2].ngot, 2);
    assert_false(st[0].done);                           /* datagrams have no send_done */
}

static void test_bad_arguments(void **state)
{
    uint8_t msg[NET_MSG_MAX + 1] = { 0 };
    (void)state;
    assert_int_equal(link_send(&st[0].link, 1, NET_PORTS, msg, 1, LINK_RELIABLE, 0), LINK_EINVAL);
    assert_int_equal(link_send(&st[0].link, 0, 0, msg, 1, LINK_RELIABLE, 0), LINK_EINVAL);
    assert_int_equal(link_send(&st[0].link, 40, 0, msg, 1, LINK_RELIABLE, 0), LINK_EINVAL);
    assert_int_equal(link_send(&st[0].link, 1, 0, msg, sizeof msg, LINK_RELIABLE, 0), LINK_EINVAL);
}

static void test_packet_reassembly_errors(void **state)
{
    struct packet_reasm r;
    struct frame f;
    uint8_t msg[300];
    (void)state;
    memset(msg, 7, sizeof msg);
    packet_reasm_init(&r);
    assert_int_equal(packet_count(0), 1);
    assert_int_equal(packet_count(300), 3);
    assert_true(packet_fragment(msg, 300, 1, 1, &f));
    assert_int_equal(packet_reasm_add(&r, f.payload, f.len), PACKET_ERROR);   /* no start */
    assert_true(packet_fragment(msg, 300, 1, 0, &f));
    assert_int_equal(packet_reasm_add(&r, f.payload, f.len), PACKET_INCOMPLETE);
    assert_true(packet_fragment(msg, 300, 1, 2, &f));
    assert_int_equal(packet_reasm_add(&r, f.payload, f.len), PACKET_ERROR);   /* gap */
    assert_false(packet_fragment(msg, 300, 1, 3, &f));
    assert_int_equal(packet_reasm_add(&r, f.payload, 1), PACKET_ERROR);       /* runt */
}

/* The fragments after the first go out as a burst right after each ACK;
 * first fragments and retransmissions do not (mac_begin_burst). */
static void test_fragments_after_an_ack_are_a_burst(void **state)
{
    static uint8_t msg[300];
    struct frame data, ack;
    uint32_t now = 0;
    (void)state;
    assert_int_equal(link_send(&st[0].link, 1, 2, msg, sizeof msg, LINK_RELIABLE, now), LINK_OK);
    assert_int_equal(st[0].nq, 1);
    data = st[0].q[0];
    st[0].nq = 0;
    assert_false(link_is_burst(&st[0].link, &data));            /* first fragment */
    link_frame_done(&st[0].link, &data, now);
    link_receive(&st[1].link, &data, now);
    assert_int_equal(st[1].nq, 1);
    ack = st[1].q[0];
    st[1].nq = 0;
    assert_int_equal(LINK_KIND(ack.type), LINK_ACK);
    assert_false(link_is_burst(&st[1].link, &ack));
    link_receive(&st[0].link, &ack, now + 20u);
    assert_int_equal(st[0].nq, 1);
    data = st[0].q[0];
    st[0].nq = 0;
    assert_true(link_is_burst(&st[0].link, &data));             /* second, after the ACK */
    link_frame_done(&st[0].link, &data, now + 20u);
    (void)link_poll(&st[0].link, now + 20u + 2u * LINK_RTO_MS);  /* no ACK: retransmitted */
    assert_int_equal(st[0].nq, 1);
    assert_int_equal(st[0].q[0].seq, data.seq);
    assert_false(link_is_burst(&st[0].link, &st[0].q[0]));
}

/* Sequence numbers restart at 0 with a station; its new session tells the
 * receiver, which still holds the old boot's last number, to start afresh
 * instead of dropping the first message as a repeat. */
static void test_restarted_sender_is_not_taken_for_a_repeat(void **state)
{
    uint8_t msg[3] = { 1, 2, 3 };
    uint32_t now = 0;
    struct link_env env = { tx, deliver, done, NULL, &st[0] };
    (void)state;
    assert_int_equal(link_send(&st[0].link, 1, 0, msg, 3, LINK_RELIABLE, now), LINK_OK);
    run(&now, 100);
    assert_int_equal(st[0].result, LINK_OK);
    assert_int_equal(st[1].ngot, 1);
    link_init(&st[0].link, 0, &env, 77u, 11u);          /* station 0 reboots, session 11 */
    st[0].done = 0;
    msg[0] = 9;
    assert_int_equal(link_send(&st[0].link, 1, 0, msg, 3, LINK_RELIABLE, now), LINK_OK);
    run(&now, 100);
    assert_int_equal(st[0].result, LINK_OK);
    assert_int_equal(st[1].ngot, 2);                   /* delivered, not a duplicate */
    assert_int_equal(st[1].got[1][0], 9);
    assert_int_equal(st[1].link.stats.duplicates, 0);
    assert_int_equal(st[1].link.stats.new_sessions, 1);
    /* Its retransmissions in the new session are still repeats. */
    loss_every = 3;
    st[0].done = 0;
    assert_int_equal(link_send(&st[0].link, 1, 0, msg, 3, LINK_RELIABLE, now), LINK_OK);
    run(&now, 20000);
    assert_int_equal(st[0].result, LINK_OK);
    assert_int_equal(st[1].ngot, 3);
}

/* Only the ACK of the outstanding frame counts: same station, seq and session. */
static void test_only_the_outstanding_frames_ack_counts(void **state)
{
    uint8_t msg[2] = { 5, 6 };
    struct frame ack = { 0 };
    uint32_t now = 0;
    (void)state;
    assert_int_equal(link_send(&st[0].link, 1, 0, msg, 2, LINK_RELIABLE, now), LINK_OK);
    link_frame_done(&st[0].link, &st[0].q[0], now);
    st[0].nq = 0;
    ack.src = 1;
    ack.dst = 0;
    ack.seq = 0;
    ack.type = LINK_TYPE(LINK_ACK, 11u);               /* a previous boot's session */
    link_receive(&st[0].link, &ack, now + 1u);
    ack.src = 2;                                       /* the wrong station */
    ack.type = LINK_TYPE(LINK_ACK, 10u);
    link_receive(&st[0].link, &ack, now + 1u);
    ack.src = 1;
    ack.seq = 1;                                       /* the wrong seq */
    link_receive(&st[0].link, &ack, now + 1u);
    assert_false(st[0].done);
    assert_int_equal(st[0].link.stats.stale_acks, 3);
    ack.seq = 0;
    link_receive(&st[0].link, &ack, now + 2u);
    assert_true(st[0].done);
    assert_int_equal(st[0].result, LINK_OK);
}

/* A DATA frame the transmit queue refuses is not lost for ever: its timer
 * runs as for a frame lost on air, and the retransmission gets through. */
static void test_refused_data_frame_is_retransmitted(void **state)
{
    uint8_t msg[200];
    uint32_t now = 0;
    (void)state;
    memset(msg, 3, sizeof msg);
    refuse = 1;                                        /* the first fragment */
    assert_int_equal(link_send(&st[0].link, 1, 0, msg, sizeof msg, LINK_RELIABLE, now), LINK_OK);
    assert_int_equal(st[0].nq, 0);
    run(&now, 2u * LINK_RTO_MS);
    assert_true(st[0].link.stats.retransmissions >= 1u);
    run(&now, 20000);
    assert_true(st[0].done);
    assert_int_equal(st[0].result, LINK_OK);
    assert_int_equal(st[1].ngot, 1);
    /* Refused every time: unreachable after the retries, not a hang. */
    st[0].done = 0;
    refuse = 1000;
    assert_int_equal(link_send(&st[0].link, 1, 0, msg, 4, LINK_RELIABLE, now), LINK_OK);
    run(&now, 30000);
    assert_true(st[0].done);
    assert_int_equal(st[0].result, LINK_EUNREACH);
    /* A refused datagram is the caller's error, not a silent loss. */
    refuse = 1;
    assert_int_equal(link_send(&st[0].link, 2, 0, msg, 4, 0, now), LINK_ENOBUFS);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_reliable_multi_fragment, setup),
        cmocka_unit_test_setup(test_loss_retransmits_without_duplicates, setup),
        cmocka_unit_test_setup(test_unreachable_then_recovers, setup),
        cmocka_unit_test_setup(test_broadcast_and_datagram, setup),
        cmocka_unit_test_setup(test_bad_arguments, setup),
        cmocka_unit_test_setup(test_packet_reassembly_errors, setup),
        cmocka_unit_test_setup(test_fragments_after_an_ack_are_a_burst, setup),
        cmocka_unit_test_setup(test_restarted_sender_is_not_taken_for_a_repeat, setup),
        cmocka_unit_test_setup(test_only_the_outstanding_frames_ack_counts, setup),
        cmocka_unit_test_setup(test_refused_data_frame_is_retransmitted, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
