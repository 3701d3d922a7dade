/* Host tests of the framing layer (frame.c, crc16.c). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "net/crc16.h"
#include "net/frame.h"

static void make_frame(struct frame *f, uint16_t len, uint8_t fill_base)
{
    uint16_t i;
    memset(f, 0, sizeof *f);
    f->src = 3;
    f->dst = 5;
    f->type = 1;
    f->seq = 0x7E;                      /* a flag value in the header: must be stuffed */
    f->len = len;
    for (i = 0; i < len; i++)
        f->payload[i] = (uint8_t)(fill_base + i);
}

/* Feeds bytes; returns the number of frames completed, the last in *out. */
static int feed(struct frame_rx *rx, const uint8_t *b, size_t n, struct frame *out)
{
    size_t i;
    int got = 0;
    for (i = 0; i < n; i++)
        got += frame_rx_byte(rx, b[i], out);
    return got;
}

static void test_crc16_check_value(void **state)
{
    (void)state;
    assert_int_equal(crc16_update(CRC16_INIT, (const uint8_t *)"123456789", 9), 0x29B1);
}

static void test_roundtrip_all_lengths(void **state)
{
    uint8_t enc[FRAME_ENCODED_MAX];
    struct frame f, g;
    struct frame_rx rx;
    uint16_t len;
    (void)state;
    frame_rx_init(&rx);
    /* Up to a sealed full fragment: the payload and the authentication trailer. */
    for (len = 0; len <= FRAME_AIR_PAYLOAD_MAX; len++) {
        size_t n;
        make_frame(&f, len, (uint8_t)(0x70 + len));   /* crosses 0x7D/0x7E */
        n = frame_encode(&f, enc, sizeof enc);
        assert_true(n > 0);
        assert_int_equal(feed(&rx, enc, n, &g), 1);
        assert_int_equal(g.src, 3);
        assert_int_equal(g.dst, 5);
        assert_int_equal(g.seq, 0x7E);
        assert_int_equal(g.len, len);
        assert_memory_equal(g.payload, f.payload, len);
    }
    assert_int_equal(rx.stats.frames, FRAME_AIR_PAYLOAD_MAX + 1);
    assert_int_equal(rx.stats.crc_errors, 0);
}

static void test_no_flag_inside(void **state)
{
    uint8_t enc[FRAME_ENCODED_MAX];
    struct frame f;
    size_t n, i;
    (void)state;
    make_frame(&f, FRAME_AIR_PAYLOAD_MAX, 0x7D);
    memset(f.payload, 0x7E, 64);
    n = frame_encode(&f, enc, sizeof enc);
    for (i = FRAME_PREAMBLE_LEN + 1; i + 1 < n; i++)
        assert_int_not_equal(enc[i], FRAME_FLAG);
    assert_int_equal(enc[n - 1], FRAME_FLAG);
}

static void test_encode_refuses(void **state)
{
    uint8_t enc[FRAME_ENCODED_MAX];
    struct frame f;
    (void)state;
    make_frame(&f, 10, 0);
    assert_int_equal(frame_encode(&f, enc, 12), 0);    /* too small a buffer */
    f.len = FRAME_AIR_PAYLOAD_MAX + 1;
    assert_int_equal(frame_encode(&f, enc, sizeof enc), 0);
}

static void test_crc_error_counted_and_resync(void **state)
{
    uint8_t enc[FRAME_ENCODED_MAX];
    struct frame f, g;
    struct frame_rx rx;
    size_t n;
    (void)state;
    frame_rx_init(&rx);
    make_frame(&f, 20, 1);
    n = frame_encode(&f, enc, sizeof enc);
    enc[10] ^= 0x01;                                  /* one bit flipped */
    assert_int_equal(feed(&rx, enc, n, &g), 0);
    assert_int_equal(rx.stats.crc_errors, 1);
    enc[10] ^= 0x01;
    assert_int_equal(feed(&rx, enc, n, &g), 1);       /* the next one is fine */
}

static void test_garbage_then_frame(void **state)
{
    uint8_t enc[FRAME_ENCODED_MAX], junk[2000];
    struct frame f, g;
    struct frame_rx rx;
    size_t n, i;
    unsigned seed = 12345;
    (void)state;
    for (i = 0; i < sizeof junk; i++) {
        seed = seed * 1103515245u + 12345u;
        junk[i] = (uint8_t)(seed >> 16);
    }
    make_frame(&f, 40, 9);
    n = frame_encode(&f, enc, sizeof enc);
    frame_rx_init(&rx);
    (void)feed(&rx, junk, sizeof junk, &g);
    assert_true(rx.n <= FRAME_BODY_MAX);
    assert_int_equal(feed(&rx, enc, n, &g), 1);
    assert_memory_equal(g.payload, f.payload, 40);
}

static void test_overlong_body_dropped(void **state)
{
    struct frame_rx rx;
    struct frame g;
    unsigned i;
    (void)state;
    frame_rx_init(&rx);
    (void)frame_rx_byte(&rx, FRAME_FLAG, &g);
    for (i = 0; i < 3u * FRAME_BODY_MAX; i++) {
        assert_int_equal(frame_rx_byte(&rx, 0x11, &g), 0);
        assert_true(rx.n <= FRAME_BODY_MAX);
    }
    assert_true(rx.stats.malformed >= 1);
    assert_int_equal(frame_rx_byte(&rx, FRAME_FLAG, &g), 0);
}

static void test_bad_escape(void **state)
{
    struct frame_rx rx;
    struct frame g;
    (void)state;
    frame_rx_init(&rx);
    (void)frame_rx_byte(&rx, FRAME_FLAG, &g);
    (void)frame_rx_byte(&rx, FRAME_ESC, &g);
    (void)frame_rx_byte(&rx, 0x00, &g);               /* 0x20 is never escaped */
    assert_int_equal(rx.stats.malformed, 1);
    assert_int_equal(rx.state, FRAME_RX_HUNT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crc16_check_value),
        cmocka_unit_test(test_roundtrip_all_lengths),
        cmocka_unit_test(test_no_flag_inside),
        cmocka_unit_test(test_encode_refuses),
        cmocka_unit_test(test_crc_error_counted_and_resync),
        cmocka_unit_test(test_garbage_then_frame),
        cmocka_unit_test(test_overlong_body_dropped),
        cmocka_unit_test(test_bad_escape),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
