/* Host tests of the frame authentication (auth.c on Mbed TLS's CMAC). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "net/auth.h"
#include "net/auth_mbedtls_config.h"   /* the pool's allocator */
#include "net/tests/rfc4493.h"

/* RFC 4493, section 4: the examples' lengths and CMACs (key and message: rfc4493.h). */
static const struct { size_t len; uint8_t mac[16]; } rfc_examples[] = {
    { 0, { 0xbb, 0x1d, 0x69, 0x29, 0xe9, 0x59, 0x37, 0x28,
           0x7f, 0xa3, 0x7d, 0x12, 0x9b, 0x75, 0x67, 0x46 } },
    { 16, { 0x07, 0x0a, 0x16, 0xb4, 0x6b, 0x4d, 0x41, 0x44,
            0xf7, 0x9b, 0xdd, 0x9d, 0xd0, 0x4a, 0x28, 0x7c } },
    { 40, { 0xdf, 0xa6, 0x67, 0x47, 0xde, 0x9a, 0xe6, 0x30,
            0x30, 0xca, 0x32, 0x61, 0x14, 0x97, 0xc8, 0x27 } },
    { 64, { 0x51, 0xf0, 0xbe, 0xbf, 0x7e, 0x3b, 0x9d, 0x92,
            0xfc, 0x49, 0x74, 0x17, 0x79, 0x36, 0x3c, 0xfe } },
};

static const uint8_t net_key[16] = {
    0x42, 0x53, 0x43, 0x48, 0x45, 0x44, 0x2d, 0x52, 0x41, 0x44, 0x49, 0x4f, 0x2d, 0x4b, 0x45, 0x59,
};

struct sealed {
    uint8_t header[AUTH_HEADER_LEN];
    uint8_t buf[AUTH_PAYLOAD_MAX + AUTH_TRAILER_LEN];
    size_t len;                         /* payload + trailer */
};

/* Seals a frame from src to dst with `len` payload bytes made from fill. */
static void seal(struct auth *a, struct sealed *s, uint8_t src, uint8_t dst, uint8_t type,
                 uint8_t seq, size_t len, uint8_t fill)
{
    size_t i;
    int n;
    s->header[0] = src;
    s->header[1] = dst;
    s->header[2] = type;
    s->header[3] = seq;
    for (i = 0; i < len; i++)
        s->buf[i] = (uint8_t)(fill + 7u * i);
    n = auth_seal(a, s->header, s->buf, len, sizeof s->buf);
    assert_int_equal(n, (int)(len + AUTH_TRAILER_LEN));
    s->len = (size_t)n;
}

static uint32_t fcnt_of(const struct sealed *s)
{
    const uint8_t *t = s->buf + s->len - AUTH_TRAILER_LEN;
    return (uint32_t)t[0] << 24 | (uint32_t)t[1] << 16 | (uint32_t)t[2] << 8 | t[3];
}

static int setup_key(void **state)
{
    (void)state;
    return net_auth_init(net_key) == AUTH_OK ? 0 : -1;
}

static void test_cmac_rfc4493_examples(void **state)
{
    size_t i;
    uint8_t mac[AUTH_CMAC_LEN];
    (void)state;
    assert_int_equal(net_auth_init(rfc_key), AUTH_OK);
    for (i = 0; i < sizeof rfc_examples / sizeof rfc_examples[0]; i++) {
        memset(mac, 0, sizeof mac);
        assert_int_equal(auth_cmac(rfc_msg, rfc_examples[i].len, mac), AUTH_OK);
        assert_memory_equal(mac, rfc_examples[i].mac, 16);
    }
    /* The MIC is the CMAC of header | FCNT | payload, cut to 4 bytes: with
     * the RFC's first 8 message bytes as header and FCNT and the next 32 as
     * payload it is the first 4 bytes of the 40-byte example. */
    {
        uint8_t mic[AUTH_MIC_LEN];
        uint32_t fcnt = (uint32_t)rfc_msg[4] << 24 | (uint32_t)rfc_msg[5] << 16 |
                        (uint32_t)rfc_msg[6] << 8 | rfc_msg[7];
        assert_int_equal(auth_mic(rfc_msg, fcnt, rfc_msg + 8, 32, mic), AUTH_OK);
        assert_memory_equal(mic, rfc_examples[2].mac, AUTH_MIC_LEN);
    }
}

static void test_seal_open_every_length(void **state)
{
    struct auth tx, rx;
    struct sealed s;
    size_t len;
    (void)state;
    assert_int_equal(auth_init(&tx, 7), AUTH_OK);
    assert_int_equal(auth_init(&rx, 1), AUTH_OK);
    for (len = 0; len <= AUTH_PAYLOAD_MAX; len++) {
        uint8_t copy[AUTH_PAYLOAD_MAX];
        seal(&tx, &s, 2, 1, 1, (uint8_t)len, len, (uint8_t)len);
        memcpy(copy, s.buf, len);
        /* FCNT = epoch 7, count = frames sealed before. */
        assert_int_equal(fcnt_of(&s), (7u << AUTH_COUNT_BITS) | (uint32_t)len);
        assert_int_equal(auth_open(&rx, s.header, s.buf, s.len), (int)len);
        assert_memory_equal(s.buf, copy, len);
    }
    assert_int_equal(tx.stats.sealed, AUTH_PAYLOAD_MAX + 1u);
    assert_int_equal(rx.stats.opened, AUTH_PAYLOAD_MAX + 1u);
    assert_int_equal(rx.stats.forged + rx.stats.replayed + rx.stats.malformed, 0);
}

/* Every single-bit change of header, payload, FCNT or MIC is refused, and
 * refusing it leaves the receiver's counters as they were. */
static void check_every_bit(size_t len)
{
    struct auth tx, rx;
    struct sealed s;
    size_t byte, refused = 0, total = 0;
    unsigned bit;
    assert_int_equal(auth_init(&tx, 3), AUTH_OK);
    assert_int_equal(auth_init(&rx, 0), AUTH_OK);
    seal(&tx, &s, 4, 9, 0x45, 0x7E, len, 0x11);
    for (byte = 0; byte < AUTH_HEADER_LEN + s.len; byte++) {
        for (bit = 0; bit < 8; bit++) {
            struct sealed t = s;
            uint8_t *p = byte < AUTH_HEADER_LEN ? &t.header[byte]
                                                : &t.buf[byte - AUTH_HEADER_LEN];
            uint32_t forged = rx.stats.forged, malformed = rx.stats.malformed;
            int rc;
            *p ^= (uint8_t)(1u << bit);
            rc = auth_open(&rx, t.header, t.buf, t.len);
            total++;
            if (byte == 0 && t.header[0] >= AUTH_STATIONS) {
                /* src beyond the stations: refused before the MIC. */
                assert_int_equal(rc, AUTH_EMALFORMED);
                assert_int_equal(rx.stats.malformed, malformed + 1u);
            } else {
                assert_int_equal(rc, AUTH_EFORGED);
                assert_int_equal(rx.stats.forged, forged + 1u);
            }
            refused++;
        }
    }
    assert_int_equal(refused, total);
    assert_int_equal(total, 8u * (AUTH_HEADER_LEN + len + AUTH_TRAILER_LEN));
    assert_int_equal(rx.stats.opened, 0);
    assert_int_equal(rx.rx_valid, 0);
    /* The untouched frame still opens: no refused one moved the counter. */
    assert_int_equal(auth_open(&rx, s.header, s.buf, s.len), (int)len);
}

static void test_flipped_bit_refused_ack_sized(void **state)
{
    (void)state;
    check_every_bit(0);
}

static void test_flipped_bit_refused_full(void **state)
{
    (void)state;
    check_every_bit(AUTH_PAYLOAD_MAX);
}

static void test_wrong_key_refused(void **state)
{
    static const uint8_t other[16] = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16 };
    struct auth tx, rx;
    struct sealed s;
    (void)state;
    assert_int_equal(auth_init(&tx, 0), AUTH_OK);
    assert_int_equal(auth_init(&rx, 0), AUTH_OK);
    assert_int_equal(net_auth_init(other), AUTH_OK);
    seal(&tx, &s, 5, 1, 1, 0, 20, 3);
    assert_int_equal(net_auth_init(net_key), AUTH_OK);
    assert_int_equal(auth_open(&rx, s.header, s.buf, s.len), AUTH_EFORGED);
    assert_int_equal(rx.stats.forged, 1);
}

static void test_replay_refused(void **state)
{
    struct auth tx, rx;
    struct sealed a, b;
    (void)state;
    assert_int_equal(auth_init(&tx, 0), AUTH_OK);
    assert_int_equal(auth_init(&rx, 0), AUTH_OK);
    seal(&tx, &a, 2, 1, 1, 0, 16, 1);
    assert_int_equal(auth_open(&rx, a.header, a.buf, a.len), 16);
    assert_int_equal(auth_open(&rx, a.header, a.buf, a.len), AUTH_EREPLAY);
    assert_int_equal(auth_open(&rx, a.header, a.buf, a.len), AUTH_EREPLAY);
    assert_int_equal(rx.stats.replayed, 2);
    assert_int_equal(rx.stats.forged, 0);
    /* A retransmission is sealed anew (auth.h) and is taken. */
    seal(&tx, &b, 2, 1, 1, 0, 16, 1);
    assert_memory_equal(a.buf, b.buf, 16);
    assert_int_equal(auth_open(&rx, b.header, b.buf, b.len), 16);
    assert_int_equal(rx.stats.opened, 2);
}

/* The policy: strictly increasing per source. Gaps are fine (lost frames,
 * frames to other stations); a lower counter never seen before is refused,
 * because a station's frames reach the air in the order it sealed them. */
static void test_counter_policy_gaps_and_reorder(void **state)
{
    struct auth tx, rx;
    struct sealed f[4];
    unsigned i;
    (void)state;
    assert_int_equal(auth_init(&tx, 1), AUTH_OK);
    assert_int_equal(auth_init(&rx, 0), AUTH_OK);
    for (i = 0; i < 4; i++)
        seal(&tx, &f[i], 6, 1, 1, (uint8_t)i, 8, (uint8_t)i);
    assert_int_equal(auth_open(&rx, f[0].header, f[0].buf, f[0].len), 8);
    assert_int_equal(auth_open(&rx, f[2].header, f[2].buf, f[2].len), 8);   /* f[1] lost */
    assert_int_equal(auth_open(&rx, f[1].header, f[1].buf, f[1].len), AUTH_EREPLAY);
    assert_int_equal(auth_open(&rx, f[3].header, f[3].buf, f[3].len), 8);
    assert_int_equal(rx.rx_last[6], (1u << AUTH_COUNT_BITS) | 3u);
    assert_int_equal(rx.stats.replayed, 1);
}

static void test_counters_per_source(void **state)
{
    struct auth s2, s3, rx;
    struct sealed a, b;
    unsigned i;
    (void)state;
    assert_int_equal(auth_init(&s2, 0), AUTH_OK);
    assert_int_equal(auth_init(&s3, 0), AUTH_OK);
    assert_int_equal(auth_init(&rx, 0), AUTH_OK);
    for (i = 0; i < 10; i++)
        seal(&s2, &a, 2, 1, 1, 0, 4, 0);
    assert_int_equal(auth_open(&rx, a.header, a.buf, a.len), 4);   /* station 2 at count 9 */
    seal(&s3, &b, 3, 1, 1, 0, 4, 0);                               /* station 3 at count 0 */
    assert_int_equal(auth_open(&rx, b.header, b.buf, b.len), 4);
    assert_int_equal(rx.rx_valid, (1u << 2) | (1u << 3));
    /* The same sealed bytes under another src do not pass for station 2's. */
    b.header[0] = 2;
    assert_int_equal(auth_open(&rx, b.header, b.buf, b.len), AUTH_EFORGED);
}

/* A station restarts: its counters begin again at its new epoch. */
static void test_restart_with_next_epoch(void **state)
{
    struct auth boot1, boot2, boot2_again, rx;
    struct sealed old, first, again;
    unsigned i;
    (void)state;
    assert_int_equal(auth_init(&rx, 0), AUTH_OK);
    assert_int_equal(auth_init(&boot1, 41), AUTH_OK);
    for (i = 0; i < 1000; i++) {
        seal(&boot1, &old, 5, 1, 1, (uint8_t)i, 12, (uint8_t)i);
        assert_int_equal(auth_open(&rx, old.header, old.buf, old.len), 12);
    }
    /* The new boot's first frame (count 0) is above the old boot's last. */
    assert_int_equal(auth_init(&boot2, 42), AUTH_OK);
    seal(&boot2, &first, 5, 1, 1, 0, 12, 0);
    assert_int_equal(fcnt_of(&first), 42u << AUTH_COUNT_BITS);
    assert_int_equal(auth_open(&rx, first.header, first.buf, first.len), 12);
    /* The old boot's frames are replays now. */
    assert_int_equal(auth_open(&rx, old.header, old.buf, old.len), AUTH_EREPLAY);
    /* A boot that did not advance its epoch is refused, as it must be: its
     * frames cannot be told from a replay of the earlier boot's. */
    assert_int_equal(auth_init(&boot2_again, 42), AUTH_OK);
    seal(&boot2_again, &again, 5, 1, 1, 0, 12, 0);
    assert_int_equal(auth_open(&rx, again.header, again.buf, again.len), AUTH_EREPLAY);
    /* The receiver itself restarting forgets every counter: it takes the
     * next frame of any boot (see net/README.md, "Authentication"). */
    assert_int_equal(auth_init(&rx, 0), AUTH_OK);
    seal(&boot2, &first, 5, 1, 1, 1, 12, 0);
    assert_int_equal(auth_open(&rx, first.header, first.buf, first.len), 12);
}

static void test_exhausted_and_bad_arguments(void **state)
{
    struct auth a, rx;
    struct sealed s;
    uint8_t buf[AUTH_PAYLOAD_MAX + AUTH_TRAILER_LEN + 1];
    const uint8_t header[AUTH_HEADER_LEN] = { 1, 2, 1, 0 };
    (void)state;
    assert_int_equal(auth_init(&a, AUTH_EPOCH_MAX + 1u), AUTH_EINVAL);
    assert_int_equal(auth_init(&a, AUTH_EPOCH_MAX), AUTH_OK);
    assert_int_equal(auth_init(&rx, 0), AUTH_OK);
    a.tx_count = (1u << AUTH_COUNT_BITS) - 1u;      /* the epoch's last count */
    seal(&a, &s, 1, 2, 1, 0, 3, 0);
    assert_int_equal(fcnt_of(&s), 0xFFFFFFFFu);
    assert_int_equal(auth_open(&rx, s.header, s.buf, s.len), 3);
    memset(buf, 0xA5, sizeof buf);
    assert_int_equal(auth_seal(&a, header, buf, 3, sizeof buf), AUTH_EEXHAUSTED);
    assert_int_equal(buf[3], 0xA5);                 /* nothing appended */
    assert_int_equal(auth_init(&a, 0), AUTH_OK);
    assert_int_equal(auth_seal(&a, header, buf, AUTH_PAYLOAD_MAX + 1u, sizeof buf), AUTH_EINVAL);
    assert_int_equal(auth_seal(&a, header, buf, 10, 10 + AUTH_TRAILER_LEN - 1u), AUTH_EINVAL);
    assert_int_equal(auth_seal(&a, header, NULL, 0, 8), AUTH_EINVAL);
    assert_int_equal(a.tx_count, 0);                /* no counter used */
    assert_int_equal(a.stats.sealed, 0);
    /* Malformed: shorter than a trailer, longer than a sealed payload, no station. */
    assert_int_equal(auth_open(&rx, header, buf, AUTH_TRAILER_LEN - 1u), AUTH_EMALFORMED);
    assert_int_equal(auth_open(&rx, header, buf, AUTH_PAYLOAD_MAX + AUTH_TRAILER_LEN + 1u),
                     AUTH_EMALFORMED);
    {
        const uint8_t far[AUTH_HEADER_LEN] = { AUTH_STATIONS, 2, 1, 0 };
        assert_int_equal(auth_open(&rx, far, buf, 20), AUTH_EMALFORMED);
    }
    assert_int_equal(rx.stats.malformed, 3);
    assert_int_equal(rx.stats.forged + rx.stats.replayed, 0);
}

/* The key can change any number of times: the pool's two slots come back. */
static void test_rekey_and_no_key(void **state)
{
    uint8_t key[16], mac[AUTH_CMAC_LEN], header[AUTH_HEADER_LEN] = { 1, 2, 3, 4 };
    uint8_t buf[AUTH_TRAILER_LEN];
    struct auth a;
    unsigned i;
    (void)state;
    memcpy(key, net_key, sizeof key);
    for (i = 0; i < 300; i++) {
        key[0] = (uint8_t)i;
        assert_int_equal(net_auth_init(key), AUTH_OK);
    }
    assert_int_equal(net_auth_init(rfc_key), AUTH_OK);
    assert_int_equal(auth_cmac(rfc_msg, 16, mac), AUTH_OK);
    assert_memory_equal(mac, rfc_examples[1].mac, 16);
    /* The key holds both slots: a third allocation is refused, not served
     * from nowhere; so is one whose size overflows. */
    assert_null(auth_mbedtls_calloc(1, 8));
    assert_int_equal(net_auth_init(NULL), AUTH_ECRYPTO);           /* frees both */
    assert_null(auth_mbedtls_calloc(2, SIZE_MAX / 2u + 1u));
    assert_null(auth_mbedtls_calloc(1, 4096));
    /* No key: everything is refused. */
    assert_int_equal(net_auth_init(NULL), AUTH_ECRYPTO);
    assert_int_equal(auth_cmac(rfc_msg, 16, mac), AUTH_ECRYPTO);
    assert_int_equal(auth_init(&a, 0), AUTH_OK);
    assert_int_equal(auth_seal(&a, header, buf, 0, sizeof buf), AUTH_ECRYPTO);
    assert_int_equal(a.tx_count, 0);
    assert_int_equal(net_auth_init(net_key), AUTH_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cmac_rfc4493_examples),
        cmocka_unit_test_setup(test_seal_open_every_length, setup_key),
        cmocka_unit_test_setup(test_flipped_bit_refused_ack_sized, setup_key),
        cmocka_unit_test_setup(test_flipped_bit_refused_full, setup_key),
        cmocka_unit_test_setup(test_wrong_key_refused, setup_key),
        cmocka_unit_test_setup(test_replay_refused, setup_key),
        cmocka_unit_test_setup(test_counter_policy_gaps_and_reorder, setup_key),
        cmocka_unit_test_setup(test_counters_per_source, setup_key),
        cmocka_unit_test_setup(test_restart_with_next_epoch, setup_key),
        cmocka_unit_test_setup(test_exhausted_and_bad_arguments, setup_key),
        cmocka_unit_test(test_rekey_and_no_key),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
