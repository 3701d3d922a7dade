/* Host tests of the Reed-Solomon code (rs.c) and the FEC framing (fec.c).
 * The code itself is compared with reedsolo byte for byte in
 * net/tests/target/test_fec_python.py. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "net/fec.h"
#include "net/rs.h"

static uint32_t rng_state = 12345u;
static uint32_t rnd(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return rng_state;
}

/* Hits `count` distinct positions of buf[0..n) with nonzero error values. */
static void corrupt(uint8_t *buf, size_t n, unsigned count)
{
    uint8_t hit[RS_N_MAX] = { 0 };
    while (count > 0u) {
        size_t p = rnd() % n;
        if (hit[p])
            continue;
        hit[p] = 1;
        buf[p] = (uint8_t)(buf[p] ^ (1u + rnd() % 255u));
        count--;
    }
}

static void test_rs_rejects_bad_parameters(void **state)
{
    struct rs_code c;
    uint8_t buf[300] = { 0 }, par[32];
    (void)state;
    assert_int_equal(rs_init(&c, 0), -1);
    assert_int_equal(rs_init(&c, 3), -1);        /* odd */
    assert_int_equal(rs_init(&c, 34), -1);
    assert_int_equal(rs_init(&c, 12), 0);
    assert_int_equal(rs_encode(&c, buf, 244, par), -1);   /* 244 + 12 > 255 */
    assert_int_equal(rs_decode(&c, buf, 256), -1);
    assert_int_equal(rs_decode(&c, buf, 12), -1);         /* no message byte */
}

/* Every error pattern of up to nsym/2 bytes is corrected, for several codes
 * and lengths (shortened codes included). */
static void test_rs_corrects_up_to_half_the_parity(void **state)
{
    static const unsigned nsyms[] = { 2, 8, 12, 32 };
    unsigned ci, trial;
    (void)state;
    for (ci = 0; ci < 4u; ci++) {
        struct rs_code c;
        unsigned nsym = nsyms[ci];
        assert_int_equal(rs_init(&c, nsym), 0);
        for (trial = 0; trial < 300u; trial++) {
            uint8_t cw[RS_N_MAX], ref[RS_N_MAX];
            size_t k = 1u + rnd() % (RS_N_MAX - nsym), n = k + nsym, i;
            unsigned errors = rnd() % (nsym / 2u + 1u);
            for (i = 0; i < k; i++)
                cw[i] = (uint8_t)rnd();
            assert_int_equal(rs_encode(&c, cw, k, cw + k), 0);
            assert_int_equal(rs_decode(&c, cw, n), 0);           /* a codeword */
            memcpy(ref, cw, n);
            corrupt(cw, n, errors);
            assert_int_equal(rs_decode(&c, cw, n), (int)errors);
            assert_memory_equal(cw, ref, n);
        }
    }
}

/* Beyond the code: either refused with the bytes unchanged, or decoded to a
 * (different) codeword; never to garbage that is not a codeword. */
static void test_rs_beyond_the_code(void **state)
{
    struct rs_code c;
    unsigned trial, refused = 0;
    (void)state;
    assert_int_equal(rs_init(&c, 12), 0);
    for (trial = 0; trial < 2000u; trial++) {
        uint8_t cw[28], before[28];
        size_t i;
        int r;
        for (i = 0; i < 16u; i++)
            cw[i] = (uint8_t)rnd();
        assert_int_equal(rs_encode(&c, cw, 16, cw + 16), 0);
        corrupt(cw, 28, 7u + rnd() % 8u);
        memcpy(before, cw, 28);
        r = rs_decode(&c, cw, 28);
        if (r < 0) {
            refused++;
            assert_memory_equal(cw, before, 28);
        } else {
            assert_true(r <= 6);
            assert_int_equal(rs_decode(&c, cw, 28), 0);
        }
    }
    assert_true(refused > 1900u);      /* miscorrection is rare for t = 6 */
}

static void make_frame(struct frame *f, uint16_t len)
{
    uint16_t i;
    memset(f, 0, sizeof *f);
    f->src = 3;
    f->dst = 5;
    f->type = 1;
    f->seq = 0x7E;
    f->len = len;
    for (i = 0; i < len; i++)
        f->payload[i] = (uint8_t)(0x7D + i);
}

/* Returns 1 when bytes[0..n) give exactly one good frame, in *out. */
static int receive(const uint8_t *bytes, size_t n, struct frame *out, struct fec_stats *st)
{
    static struct fec_rx rx;
    static struct fec_raw raw;
    size_t i;
    int got = 0;
    fec_rx_init(&rx);
    for (i = 0; i < n; i++)
        if (fec_rx_byte(&rx, bytes[i], &raw))
            got += fec_frame_decode(&raw, out, st);
    return got;
}

static void test_fec_frame_round_trip_every_length(void **state)
{
    uint16_t len;
    (void)state;
    assert_int_equal(fec_init(), 0);
    for (len = 0; len <= FRAME_AIR_PAYLOAD_MAX; len++) {
        struct frame f, g;
        struct fec_stats st = { 0 };
        uint8_t enc[FEC_ENCODED_MAX];
        size_t n;
        make_frame(&f, len);
        n = fec_frame_encode(&f, enc, sizeof enc);
        assert_int_equal(n, FRAME_PREAMBLE_LEN + 1u + FEC_COPIES +
                            (1u + 6u + len + FEC_K - 1u) / FEC_K * FEC_N);
        assert_int_equal(receive(enc, n, &g, &st), 1);
        assert_int_equal(g.len, len);
        assert_int_equal(g.seq, 0x7E);
        assert_memory_equal(g.payload, f.payload, len);
        assert_int_equal(fec_frame_encode(&f, enc, n - 1u), 0);   /* too small */
    }
}

/* Six wrong bytes in every codeword and three of the five counts: corrected. */
static void test_fec_frame_survives_errors(void **state)
{
    struct frame f, g;
    struct fec_stats st = { 0 };
    uint8_t enc[FEC_ENCODED_MAX];
    size_t n, i, start = FRAME_PREAMBLE_LEN + 1u;
    (void)state;
    assert_int_equal(fec_init(), 0);
    make_frame(&f, FRAME_AIR_PAYLOAD_MAX);          /* a sealed full fragment */
    n = fec_frame_encode(&f, enc, sizeof enc);
    enc[start] = 0;
    enc[start + 2u] = 0xEE;
    enc[start + 4u] = 3;
    for (i = start + FEC_COPIES; i < n; i += FEC_N)
        corrupt(enc + i, FEC_N, 6);
    assert_int_equal(receive(enc, n, &g, &st), 1);
    assert_memory_equal(g.payload, f.payload, FRAME_AIR_PAYLOAD_MAX);
    assert_int_equal(st.corrected, 6u * ((n - start - FEC_COPIES) / FEC_N));
    /* seven in one codeword: the frame is refused, counted */
    n = fec_frame_encode(&f, enc, sizeof enc);
    corrupt(enc + start + FEC_COPIES, FEC_N, 7);
    memset(&st, 0, sizeof st);
    assert_int_equal(receive(enc, n, &g, &st), 0);
    assert_int_equal(st.uncorrectable + st.bad_frames, 1u);
}

/* Garbage never completes a frame with a good CRC by chance here, and the
 * receiver finds the next real frame after it. */
static void test_fec_resynchronises_after_garbage(void **state)
{
    struct frame f, g;
    struct fec_stats st = { 0 };
    uint8_t buf[2000];
    size_t n, i;
    (void)state;
    assert_int_equal(fec_init(), 0);
    for (i = 0; i < 1000u; i++)
        buf[i] = (uint8_t)(rnd() & 1u ? 0x7E : rnd());
    buf[999] = 0x55;
    make_frame(&f, 20);
    n = fec_frame_encode(&f, buf + 1000, sizeof buf - 1000u);
    /* the garbage may leave the receiver inside a bogus frame: a real
     * transmission starts after an idle gap, modelled by a resync byte run */
    memset(buf + 1000 - 300, 0x55, 300);
    assert_int_equal(receive(buf, 1000u + n, &g, &st), 1);
    assert_int_equal(g.len, 20);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rs_rejects_bad_parameters),
        cmocka_unit_test(test_rs_corrects_up_to_half_the_parity),
        cmocka_unit_test(test_rs_beyond_the_code),
        cmocka_unit_test(test_fec_frame_round_trip_every_length),
        cmocka_unit_test(test_fec_frame_survives_errors),
        cmocka_unit_test(test_fec_resynchronises_after_garbage),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
