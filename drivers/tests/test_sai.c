/*
 * Host unit tests of the uniform access layer (drivers/sai.c): channel
 * names, parsing, range checks, and the dispatch to the drivers, here fakes
 * that record each call and answer what the test sets up.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "drivers/drv_err.h"
#include "drivers/sai.h"
#include "drivers/analog.h"
#include "drivers/binin.h"
#include "drivers/bio.h"
#include "drivers/fastout.h"
#include "drivers/led.h"
#include "drivers/motor.h"
#include "drivers/tpu.h"

/* ---- fake drivers ---- */
static char last_call[32];      /* name of the last driver function called */
static unsigned last_ch;
static int last_value;
static int next_result;         /* what the next fake call returns (value or error) */
static uint16_t fast_shadow;
static bool led_state;

static int fake(const char *name, unsigned ch, int value)
{
    strncpy(last_call, name, sizeof last_call - 1u);
    last_ch = ch;
    last_value = value;
    return next_result;
}

int analog_read(unsigned ch) { return fake("analog_read", ch, 0); }
int analog_write(unsigned ch, int v) { return fake("analog_write", ch, v); }
int bio_read(unsigned line) { return fake("bio_read", line, 0); }
int bio_write(unsigned line, int v) { return fake("bio_write", line, v); }
int binin_read(unsigned n) { return fake("binin_read", n, 0); }
uint16_t fastout_get(void) { return fast_shadow; }
int fastout_write(unsigned bit, int v) { return fake("fastout_write", bit, v); }
int tpu_pwm(unsigned ch, uint32_t hz, int permille)
{
    return fake("tpu_pwm", ch, permille + (int)hz * 10000);
}
int tpu_pwm_get(unsigned ch, uint32_t *hz, int *permille)
{
    int rc = fake("tpu_pwm_get", ch, 0);
    if (hz != NULL)
        *hz = 1000u;
    if (permille != NULL)
        *permille = 250;
    return rc;
}
int motor_set(unsigned m, int permille) { return fake("motor_set", m, permille); }
int motor_power(unsigned m, int *permille)
{
    *permille = -300;
    return fake("motor_power", m, 0);
}
int motor_position(unsigned m, int32_t *counts)
{
    *counts = -123456;
    return fake("motor_position", m, 0);
}
void led_set(bool on) { led_state = on; (void)fake("led_set", 0, on); }
bool led_is_on(void) { return led_state; }
const char *drv_strerror(int code) { (void)code; return "?"; }

static int setup(void **state)
{
    (void)state;
    last_call[0] = '\0';
    last_ch = 999;
    last_value = -999;
    next_result = DRV_OK;
    fast_shadow = 0;
    led_state = false;
    return 0;
}

static struct sai_channel chan(const char *text)
{
    struct sai_channel ch = {0xFF, 0xFF};
    assert_int_equal(sai_parse(text, &ch), DRV_OK);
    return ch;
}

/* ---- parsing and naming ---- */

static void test_parse_every_kind_long_and_short(void **state)
{
    static const struct { const char *text; unsigned kind, index; } ok[] = {
        {"analog in 5", SAI_ANALOG_IN, 5}, {"ad 23", SAI_ANALOG_IN, 23},
        {"analog out 2", SAI_ANALOG_OUT, 2}, {"da 0", SAI_ANALOG_OUT, 0},
        {"binary io 12", SAI_BINARY_IO, 12}, {"bio 15", SAI_BINARY_IO, 15},
        {"binary in 3", SAI_BINARY_IN, 3}, {"bin 1", SAI_BINARY_IN, 1},
        {"fast out 7", SAI_FAST_OUT, 7}, {"fast 0", SAI_FAST_OUT, 0},
        {"pwm 4", SAI_PWM, 4}, {"pwm 14", SAI_PWM, 14},
        {"motor 1", SAI_MOTOR, 1}, {"encoder 0", SAI_ENCODER, 0}, {"enc 2", SAI_ENCODER, 2},
        {"led", SAI_LED, 0}, {"led 0", SAI_LED, 0},
        {"  Analog   IN\t5  ", SAI_ANALOG_IN, 5}, {"MOTOR 2", SAI_MOTOR, 2},
        {"ad 007", SAI_ANALOG_IN, 7},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof ok / sizeof ok[0]; i++) {
        struct sai_channel ch = chan(ok[i].text);
        assert_int_equal(ch.kind, ok[i].kind);
        assert_int_equal(ch.index, ok[i].index);
    }
}

static void test_parse_rejects_bad_channels(void **state)
{
    static const char *const bad[] = {
        "", "   ", "analog 5", "analog in", "analog in x", "analog in -1", "analog in 24",
        "ad 24", "da 6", "bio 16", "binary in 0", "bin 6", "fast out 16", "pwm 15",
        "motor 3", "encoder 3", "led 1", "analogin 5", "ad5", "ad 5x", "ad 5 6",
        "ad 1000", "ad 99999999999", "motorbike 1", "binary 3", "in 5", "ad +5",
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        struct sai_channel ch = {0xAB, 0xCD};
        int rc = sai_parse(bad[i], &ch);
        if (rc != DRV_ERR_CHANNEL)
            fail_msg("sai_parse(\"%s\") = %d, wanted DRV_ERR_CHANNEL", bad[i], rc);
        assert_int_equal(ch.kind, 0xAB); /* untouched on error */
        assert_int_equal(ch.index, 0xCD);
    }
    assert_int_equal(sai_parse(NULL, &(struct sai_channel){0, 0}), DRV_ERR_PARAM);
    assert_int_equal(sai_parse("ad 1", NULL), DRV_ERR_PARAM);
}

static void test_parse_prefix_leaves_the_rest(void **state)
{
    struct sai_channel ch;
    const char *rest = NULL;
    (void)state;
    assert_int_equal(sai_parse_prefix("da 2 100", &ch, &rest), DRV_OK);
    assert_int_equal(ch.kind, SAI_ANALOG_OUT);
    assert_int_equal(ch.index, 2);
    assert_string_equal(rest, " 100");
    assert_int_equal(sai_parse_prefix("led on", &ch, &rest), DRV_OK);
    assert_int_equal(ch.kind, SAI_LED);
    assert_string_equal(rest, "on");
    assert_int_equal(sai_parse_prefix("binary io 3 -1", &ch, &rest), DRV_OK);
    assert_int_equal(ch.kind, SAI_BINARY_IO);
    assert_int_equal(ch.index, 3);
    assert_string_equal(rest, " -1");
    rest = "unchanged";
    assert_int_equal(sai_parse_prefix("led 7", &ch, &rest), DRV_ERR_CHANNEL);
    assert_string_equal(rest, "unchanged");
}

static void test_names_round_trip(void **state)
{
    unsigned k;
    (void)state;
    for (k = 0; k < SAI_KIND_COUNT; k++) {
        const struct sai_kind_info *info = sai_kind_info(k);
        unsigned i;
        assert_non_null(info);
        for (i = info->first; i <= info->last; i++) {
            struct sai_channel ch = {(uint8_t)k, (uint8_t)i}, back;
            char name[24];
            int len = sai_name(ch, name, sizeof name);
            assert_int_equal(len, (int)strlen(name));
            assert_int_equal(sai_parse(name, &back), DRV_OK);
            assert_int_equal(back.kind, k);
            assert_int_equal(back.index, i);
        }
    }
    assert_null(sai_kind_info(SAI_KIND_COUNT));
}

static void test_name_truncates_and_rejects(void **state)
{
    char buf[8];
    struct sai_channel ch = {SAI_ANALOG_IN, 17};
    (void)state;
    assert_int_equal(sai_name(ch, buf, sizeof buf), 12); /* "analog in 17" */
    assert_string_equal(buf, "analog ");
    assert_int_equal(sai_name((struct sai_channel){SAI_ANALOG_IN, 24}, buf, sizeof buf),
                     DRV_ERR_CHANNEL);
    assert_int_equal(sai_name((struct sai_channel){SAI_KIND_COUNT, 0}, buf, sizeof buf),
                     DRV_ERR_CHANNEL);
    assert_int_equal(sai_name(ch, NULL, 4), DRV_ERR_PARAM);
}

static void test_value_ranges(void **state)
{
    (void)state;
    assert_int_equal(sai_check_value(chan("da 1"), 0), DRV_OK);
    assert_int_equal(sai_check_value(chan("da 1"), 255), DRV_OK);
    assert_int_equal(sai_check_value(chan("da 1"), 256), DRV_ERR_RANGE);
    assert_int_equal(sai_check_value(chan("da 1"), -1), DRV_ERR_RANGE);
    assert_int_equal(sai_check_value(chan("bio 3"), 2), DRV_ERR_RANGE);
    assert_int_equal(sai_check_value(chan("fast 3"), 1), DRV_OK);
    assert_int_equal(sai_check_value(chan("pwm 3"), 1000), DRV_OK);
    assert_int_equal(sai_check_value(chan("pwm 3"), 1001), DRV_ERR_RANGE);
    assert_int_equal(sai_check_value(chan("motor 0"), -1000), DRV_OK);
    assert_int_equal(sai_check_value(chan("motor 0"), -1001), DRV_ERR_RANGE);
    assert_int_equal(sai_check_value(chan("led"), 1), DRV_OK);
    assert_int_equal(sai_check_value(chan("led"), 2), DRV_ERR_RANGE);
    /* read-only kinds */
    assert_int_equal(sai_check_value(chan("ad 1"), 0), DRV_ERR_PARAM);
    assert_int_equal(sai_check_value(chan("bin 1"), 0), DRV_ERR_PARAM);
    assert_int_equal(sai_check_value(chan("enc 1"), 0), DRV_ERR_PARAM);
    assert_int_equal(sai_check_value((struct sai_channel){SAI_MOTOR, 3}, 0), DRV_ERR_CHANNEL);
}

/* ---- dispatch ---- */

/* One dispatch case: the channel, the fake driver's answer, the call expected
 * and what reaches the caller (reads) or the driver (writes). */
struct dispatch_case {
    const char *channel;
    int driver_result;
    const char *call;
    unsigned ch;
    int32_t value;
};

static void test_read_dispatches(void **state)
{
    static const struct dispatch_case reads[] = {
        {"analog in 5", 200, "analog_read", 5, 200},
        {"bio 12", 1, "bio_read", 12, 1},
        {"binary in 3", 0, "binin_read", 3, 0},
        {"pwm 9", DRV_OK, "tpu_pwm_get", 9, 250},
        {"motor 2", DRV_OK, "motor_power", 2, -300},
        {"encoder 1", DRV_OK, "motor_position", 1, -123456},
    };
    size_t i;
    int32_t v = -1;
    (void)state;
    for (i = 0; i < sizeof reads / sizeof reads[0]; i++) {
        next_result = reads[i].driver_result;
        assert_int_equal(sai_read(chan(reads[i].channel), &v), DRV_OK);
        assert_string_equal(last_call, reads[i].call);
        assert_int_equal(last_ch, reads[i].ch);
        assert_int_equal(v, reads[i].value);
    }
    /* no driver call: the fast outputs' shadow and the LED's state */
    fast_shadow = 0x0080;
    assert_int_equal(sai_read(chan("fast 7"), &v), DRV_OK);
    assert_int_equal(v, 1);
    assert_int_equal(sai_read(chan("fast 6"), &v), DRV_OK);
    assert_int_equal(v, 0);
    led_state = true;
    assert_int_equal(sai_read(chan("led"), &v), DRV_OK);
    assert_int_equal(v, 1);
}

static void test_write_dispatches(void **state)
{
    static const struct dispatch_case writes[] = {
        {"analog out 2", DRV_OK, "analog_write", 2, 100},
        {"binary io 12", DRV_OK, "bio_write", 12, 0},
        {"fast out 7", DRV_OK, "fastout_write", 7, 1},
        {"pwm 4", DRV_OK, "tpu_pwm", 4, 750},  /* hz 0: the channel keeps its frequency */
        {"motor 1", DRV_OK, "motor_set", 1, -500},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof writes / sizeof writes[0]; i++) {
        assert_int_equal(sai_write(chan(writes[i].channel), writes[i].value), DRV_OK);
        assert_string_equal(last_call, writes[i].call);
        assert_int_equal(last_ch, writes[i].ch);
        assert_int_equal(last_value, writes[i].value);
    }
    assert_int_equal(sai_write(chan("led"), 1), DRV_OK);
    assert_true(led_state);
    assert_int_equal(sai_write(chan("led"), 0), DRV_OK);
    assert_false(led_state);
}

static void test_refusals_reach_no_driver(void **state)
{
    int32_t v = 77;
    (void)state;
    assert_int_equal(sai_write(chan("da 1"), 256), DRV_ERR_RANGE);
    assert_int_equal(sai_write(chan("motor 0"), 1001), DRV_ERR_RANGE);
    assert_int_equal(sai_write(chan("ad 1"), 5), DRV_ERR_PARAM);
    assert_int_equal(sai_write(chan("encoder 0"), 5), DRV_ERR_PARAM);
    assert_int_equal(sai_write((struct sai_channel){SAI_ANALOG_OUT, 6}, 5), DRV_ERR_CHANNEL);
    assert_int_equal(sai_read(chan("da 1"), &v), DRV_ERR_PARAM);
    assert_int_equal(sai_read((struct sai_channel){SAI_ANALOG_IN, 24}, &v), DRV_ERR_CHANNEL);
    assert_int_equal(sai_read((struct sai_channel){200, 0}, &v), DRV_ERR_CHANNEL);
    assert_int_equal(sai_read(chan("ad 1"), NULL), DRV_ERR_PARAM);
    assert_string_equal(last_call, ""); /* no driver was called */
    assert_int_equal(v, 77);
}

static void test_driver_errors_pass_through(void **state)
{
    static const int errors[] = {DRV_ERR_ABSENT, DRV_ERR_TIMEOUT, DRV_ERR_ARB, DRV_ERR_STATE};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof errors / sizeof errors[0]; i++) {
        int32_t v = 55;
        next_result = errors[i];
        assert_int_equal(sai_read(chan("ad 3"), &v), errors[i]);
        assert_int_equal(v, 55); /* nothing written on error */
        assert_int_equal(sai_read(chan("enc 0"), &v), errors[i]);
        assert_int_equal(v, 55);
        assert_int_equal(sai_write(chan("da 3"), 9), errors[i]);
        assert_int_equal(sai_write(chan("motor 2"), 9), errors[i]);
    }
}

int main(void)
{
#define T(name) cmocka_unit_test_setup(name, setup)
    const struct CMUnitTest tests[] = {
        T(test_parse_every_kind_long_and_short),
        T(test_parse_rejects_bad_channels),
        T(test_parse_prefix_leaves_the_rest),
        T(test_names_round_trip),
        T(test_name_truncates_and_rejects),
        T(test_value_ranges),
        T(test_read_dispatches),
        T(test_write_dispatches),
        T(test_refusals_reach_no_driver),
        T(test_driver_errors_pass_through),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
