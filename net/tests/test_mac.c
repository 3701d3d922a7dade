/* Host tests of the listen-before-talk arbitration (mac.c). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include "net/mac.h"

static void test_ack_goes_at_once_when_idle(void **state)
{
    struct mac m;
    uint32_t w = 0;
    (void)state;
    mac_init(&m, 1);
    mac_begin(&m);
    assert_int_equal(mac_decide(&m, 0, 1, &w), MAC_SEND);
}

static void test_data_waits_within_window_then_sends(void **state)
{
    struct mac m;
    unsigned i, waited = 0;
    (void)state;
    mac_init(&m, 7);
    for (i = 0; i < 100; i++) {
        uint32_t w = 0;
        int a;
        mac_begin(&m);
        a = mac_decide(&m, 0, 0, &w);
        if (a == MAC_WAIT) {
            waited++;
            assert_true(w >= MAC_SLOT_MS && w <= MAC_CW_MIN * MAC_SLOT_MS);
            a = mac_decide(&m, 0, 0, &w);
        }
        assert_int_equal(a, MAC_SEND);
    }
    assert_true(waited > 50 && waited < 100);          /* random, not always */
}

static void test_busy_channel_bounded(void **state)
{
    struct mac m;
    uint32_t w = 0, total = 0;
    unsigned n = 0;
    int a;
    (void)state;
    mac_init(&m, 3);
    mac_begin(&m);
    while ((a = mac_decide(&m, 1, 0, &w)) == MAC_WAIT) {
        if (n == 0 && w <= MAC_CW_MIN * MAC_SLOT_MS && m.attempt == 0)
            continue;                                  /* the initial wait */
        assert_true(w >= MAC_SLOT_MS && w <= MAC_CW_MAX * MAC_SLOT_MS);
        total += w;
        n++;
    }
    assert_int_equal(a, MAC_DROP);
    assert_int_equal(n, MAC_MAX_ATTEMPTS);
    assert_int_equal(m.drops, 1);
    assert_true(total < 20000u);                       /* gives up in bounded time */
}

static void test_ack_retries_quickly_and_bounded(void **state)
{
    struct mac m;
    uint32_t w = 0;
    unsigned n = 0;
    (void)state;
    mac_init(&m, 5);
    mac_begin(&m);
    while (mac_decide(&m, 1, 1, &w) == MAC_WAIT) {
        assert_int_equal(w, MAC_ACK_RETRY_MS);
        n++;
    }
    assert_int_equal(n, MAC_MAX_ATTEMPTS);
}

static void test_seeds_differ(void **state)
{
    struct mac a, b;
    (void)state;
    mac_init(&a, 1);
    mac_init(&b, 2);
    assert_int_not_equal(mac_random(&a), mac_random(&b));
    mac_init(&a, 0);                                   /* 0 is no valid xorshift state */
    assert_int_not_equal(mac_random(&a), 0);
}

static void test_burst_skips_the_initial_wait_and_waits_out_the_ack(void **state)
{
    struct mac m;
    uint32_t w = 0;
    unsigned i;
    (void)state;
    mac_init(&m, 7);
    mac_begin_burst(&m);
    assert_int_equal(mac_decide(&m, 0, 0, &w), MAC_SEND);       /* idle: at once */
    mac_begin_burst(&m);
    for (i = 0; i < MAC_BURST_RETRIES; i++) {                   /* busy: the ACK's tail */
        assert_int_equal(mac_decide(&m, 1, 0, &w), MAC_WAIT);
        assert_int_equal(w, MAC_ACK_RETRY_MS);
    }
    assert_int_equal(mac_decide(&m, 1, 0, &w), MAC_WAIT);       /* then a data backoff */
    assert_true(w >= MAC_SLOT_MS && w <= MAC_CW_MAX * MAC_SLOT_MS);
    mac_begin(&m);                                              /* the next frame: normal */
    (void)mac_decide(&m, 0, 0, &w);
    assert_int_equal(mac_decide(&m, 1, 0, &w), MAC_WAIT);
    assert_true(w >= MAC_SLOT_MS);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ack_goes_at_once_when_idle),
        cmocka_unit_test(test_data_waits_within_window_then_sends),
        cmocka_unit_test(test_busy_channel_bounded),
        cmocka_unit_test(test_ack_retries_quickly_and_bounded),
        cmocka_unit_test(test_seeds_differ),
        cmocka_unit_test(test_burst_skips_the_initial_wait_and_waits_out_the_ack),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
