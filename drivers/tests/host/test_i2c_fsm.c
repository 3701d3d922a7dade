/*
 * The PCF8584 transaction state machine (drivers/i2c_fsm.c) against a
 * scripted fake controller: every register access the machine makes must be
 * the next one in the script (reads return the scripted value), so each test
 * pins down the exact register sequence of one kind of transaction and its
 * result.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "drivers/i2c_fsm.h"

struct step {
    char op;          /* 'R' read, 'W' write, 'I' controller interrupt (test marker) */
    uint8_t reg;
    uint8_t val;
};

static const struct step *script;
static size_t script_len, script_pos;

uint8_t i2c_fake_rd(struct i2c_fsm *f, unsigned reg)
{
    (void)f;
    assert_true(script_pos < script_len);
    assert_int_equal(script[script_pos].op, 'R');
    assert_int_equal(script[script_pos].reg, reg);
    return script[script_pos++].val;
}

void i2c_fake_wr(struct i2c_fsm *f, unsigned reg, uint8_t v)
{
    (void)f;
    assert_true(script_pos < script_len);
    assert_int_equal(script[script_pos].op, 'W');
    assert_int_equal(script[script_pos].reg, reg);
    assert_int_equal(script[script_pos].val, v);
    script_pos++;
}

#define R(reg, v) { 'R', (reg), (v) }
#define W(reg, v) { 'W', (reg), (v) }
#define IRQ { 'I', 0, 0 }
#define S0 PCF_S0
#define S1 PCF_S1
/* Status values: PIN 0 + bus busy (held by us) + ACK received / not. */
#define ST_ACKED 0x00
#define ST_NACKED PCF_ST_LRB
#define ST_FREE (PCF_ST_PIN | PCF_ST_BB)

/* Runs the script: start, then one i2c_fsm_interrupt per IRQ marker. Returns
 * the last event; checks the whole script was consumed. */
static enum i2c_fsm_event run(struct i2c_fsm *f, struct i2c_xfer *x, const struct step *s, size_t n)
{
    enum i2c_fsm_event ev;
    script = s;
    script_len = n;
    script_pos = 0;
    ev = i2c_fsm_start(f, x);
    while (script_pos < script_len) {
        assert_int_equal(ev, I2C_FSM_RUNNING);
        assert_int_equal(script[script_pos].op, 'I');
        script_pos++;
        ev = i2c_fsm_interrupt(f);
    }
    return ev;
}

static struct i2c_fsm fsm;

static int setup(void **state)
{
    (void)state;
    memset(&fsm, 0, sizeof fsm);
    return 0;
}

static void test_write_two_bytes(void **state)
{
    const uint8_t data[2] = { 0x12, 0x34 };
    struct i2c_xfer x = { .addr7 = 0x38, .wr = data, .wr_len = 2 };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x70), W(S1, 0xCD),
        IRQ, R(S1, ST_ACKED), W(S0, 0x12),
        IRQ, R(S1, ST_ACKED), W(S0, 0x34),
        IRQ, R(S1, ST_ACKED), W(S1, 0xCB),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_OK);
    assert_null(fsm.x);
    assert_int_equal(fsm.need_reset, 0);
}

static void test_address_nack_is_absent(void **state)
{
    const uint8_t data[1] = { 0 };
    struct i2c_xfer x = { .addr7 = 0x20, .wr = data, .wr_len = 1 };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x40), W(S1, 0xCD),
        IRQ, R(S1, ST_NACKED), W(S1, 0xCB),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_ERR_ABSENT);
    assert_int_equal(fsm.need_reset, 0);
}

static void test_data_nack_stops_with_absent(void **state)
{
    const uint8_t data[3] = { 1, 2, 3 };
    struct i2c_xfer x = { .addr7 = 0x48, .wr = data, .wr_len = 3 };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x90), W(S1, 0xCD),
        IRQ, R(S1, ST_ACKED), W(S0, 1),
        IRQ, R(S1, ST_NACKED), W(S1, 0xCB),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_ERR_ABSENT);
}

static void test_probe_is_address_only(void **state)
{
    struct i2c_xfer x = { .addr7 = 0x4D };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x9A), W(S1, 0xCD),
        IRQ, R(S1, ST_ACKED), W(S1, 0xCB),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_OK);
}

/* The PCF8591 chip read: control byte, repeated START, 5 bytes. */
static void test_write_then_read_with_repeated_start(void **state)
{
    const uint8_t ctl = 0x04;
    uint8_t rd[5] = { 0 };
    struct i2c_xfer x = { .addr7 = 0x48, .wr = &ctl, .wr_len = 1, .rd = rd, .rd_len = 5 };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x90), W(S1, 0xCD),
        IRQ, R(S1, ST_ACKED), W(S0, 0x04),
        IRQ, R(S1, ST_ACKED), W(S1, 0x4D), W(S0, 0x91),      /* repeated START, read address */
        IRQ, R(S1, ST_ACKED), R(S0, 0x91),                    /* dummy read starts byte 0 */
        IRQ, R(S1, ST_ACKED), R(S0, 10),
        IRQ, R(S1, ST_ACKED), R(S0, 11),
        IRQ, R(S1, ST_ACKED), R(S0, 12),
        IRQ, R(S1, ST_ACKED), W(S1, 0x48), R(S0, 13),         /* NACK the last byte */
        IRQ, R(S1, ST_NACKED), W(S1, 0xCB), R(S0, 14),        /* STOP, then the last byte */
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_OK);
    assert_memory_equal(rd, ((uint8_t[]){ 10, 11, 12, 13, 14 }), 5);
}

static void test_read_one_byte(void **state)
{
    uint8_t rd = 0;
    struct i2c_xfer x = { .addr7 = 0x39, .rd = &rd, .rd_len = 1 };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x73), W(S1, 0xCD),
        IRQ, R(S1, ST_ACKED), W(S1, 0x48), R(S0, 0x73),      /* only byte = last: NACK it */
        IRQ, R(S1, ST_NACKED), W(S1, 0xCB), R(S0, 0x5A),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_OK);
    assert_int_equal(rd, 0x5A);
}

static void test_read_two_bytes(void **state)
{
    uint8_t rd[2] = { 0 };
    struct i2c_xfer x = { .addr7 = 0x39, .rd = rd, .rd_len = 2 };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x73), W(S1, 0xCD),
        IRQ, R(S1, ST_ACKED), R(S0, 0),
        IRQ, R(S1, ST_ACKED), W(S1, 0x48), R(S0, 1),
        IRQ, R(S1, ST_NACKED), W(S1, 0xCB), R(S0, 2),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(rd[0], 1);
    assert_int_equal(rd[1], 2);
}

static void test_read_address_nack(void **state)
{
    uint8_t rd[4];
    struct i2c_xfer x = { .addr7 = 0x4F, .rd = rd, .rd_len = 4 };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x9F), W(S1, 0xCD),
        IRQ, R(S1, ST_NACKED), W(S1, 0xCB),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_ERR_ABSENT);
}

static void test_busy_bus_sends_nothing(void **state)
{
    struct i2c_xfer x = { .addr7 = 0x48 };
    const struct step s[] = { R(S1, PCF_ST_PIN) };          /* BB = 0: busy */
    (void)state;
    script = s;
    script_len = 1;
    script_pos = 0;
    assert_int_equal(i2c_fsm_start(&fsm, &x), I2C_FSM_BUS_BUSY);
    assert_int_equal(script_pos, 1);
    assert_null(fsm.x);
}

static void test_arbitration_lost(void **state)
{
    const uint8_t d = 1;
    struct i2c_xfer x = { .addr7 = 0x48, .wr = &d, .wr_len = 1 };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x90), W(S1, 0xCD),
        IRQ, R(S1, PCF_ST_LAB),                              /* no STOP: we are not driving */
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_ERR_ARB);
    assert_int_equal(fsm.need_reset, 1);
}

static void test_bus_error_needs_reset(void **state)
{
    struct i2c_xfer x = { .addr7 = 0x48 };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x90), W(S1, 0xCD),
        IRQ, R(S1, PCF_ST_BER),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_ERR_TIMEOUT);
    assert_int_equal(fsm.need_reset, 1);
}

static void test_spurious_interrupts_are_ignored(void **state)
{
    struct i2c_xfer x = { .addr7 = 0x48 };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x90), W(S1, 0xCD),
        IRQ, R(S1, PCF_ST_PIN),                              /* byte not done yet */
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_SPURIOUS);
    assert_ptr_equal(fsm.x, &x);
    assert_ptr_equal(i2c_fsm_abort(&fsm), &x);
    assert_int_equal(x.status, DRV_ERR_TIMEOUT);
    assert_int_equal(fsm.need_reset, 1);
    assert_null(i2c_fsm_abort(&fsm));
    script_len = 0;
    script_pos = 0;
    assert_int_equal(i2c_fsm_interrupt(&fsm), I2C_FSM_SPURIOUS);  /* nothing on the wire: no access */
}

static void test_reset_sequence(void **state)
{
    const struct step s[] = {
        W(S1, 0x80), R(S1, 0x80), W(S0, 0x55), W(S1, 0xA0), W(S0, 0x1C),
        W(S1, 0x90), W(S0, 27), W(S1, 0xC9),
    };
    const struct step absent[] = { W(S1, 0x80), R(S1, 0xFF) };
    (void)state;
    fsm.need_reset = 1;
    script = s;
    script_len = sizeof s / sizeof s[0];
    script_pos = 0;
    assert_int_equal(i2c_fsm_reset(&fsm, 0x55, 27), 0);
    assert_int_equal(script_pos, script_len);
    assert_int_equal(fsm.need_reset, 0);
    script = absent;
    script_len = 2;
    script_pos = 0;
    assert_int_equal(i2c_fsm_reset(&fsm, 0x55, 27), -1);    /* floating bus: no controller */
}

/* The sampler's chain: a PCF8591 read (control byte, repeated START, 5
 * bytes) and a PCF8574A read, one transaction, repeated START in between. */
static void test_chain_of_two_messages(void **state)
{
    const uint8_t ctl = 0x04;
    uint8_t ad[5] = { 0 }, bio = 0;
    struct i2c_xfer second = { .addr7 = 0x38, .rd = &bio, .rd_len = 1 };
    struct i2c_xfer x = { .addr7 = 0x48, .wr = &ctl, .wr_len = 1, .rd = ad, .rd_len = 5,
                          .more = &second };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x90), W(S1, 0xCD),
        IRQ, R(S1, ST_ACKED), W(S0, 0x04),
        IRQ, R(S1, ST_ACKED), W(S1, 0x4D), W(S0, 0x91),
        IRQ, R(S1, ST_ACKED), R(S0, 0x91),
        IRQ, R(S1, ST_ACKED), R(S0, 10),
        IRQ, R(S1, ST_ACKED), R(S0, 11),
        IRQ, R(S1, ST_ACKED), R(S0, 12),
        IRQ, R(S1, ST_ACKED), W(S1, 0x48), R(S0, 13),
        IRQ, R(S1, ST_NACKED), W(S1, 0x4D), R(S0, 14), W(S0, 0x71),   /* next: repeated START */
        IRQ, R(S1, ST_ACKED), W(S1, 0x48), R(S0, 0x71),
        IRQ, R(S1, ST_NACKED), W(S1, 0xCB), R(S0, 0x5A),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_OK);
    assert_int_equal(x.msg_status, DRV_OK);
    assert_int_equal(second.msg_status, DRV_OK);
    assert_memory_equal(ad, ((uint8_t[]){ 10, 11, 12, 13, 14 }), 5);
    assert_int_equal(bio, 0x5A);
}

/* An absent chip in the middle does not end the chain. */
static void test_chain_goes_on_after_a_nack(void **state)
{
    uint8_t a = 0, c = 0;
    struct i2c_xfer third = { .addr7 = 0x39, .rd = &c, .rd_len = 1 };
    struct i2c_xfer second = { .addr7 = 0x4A, .more = &third };
    struct i2c_xfer x = { .addr7 = 0x38, .rd = &a, .rd_len = 1, .more = &second };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x71), W(S1, 0xCD),
        IRQ, R(S1, ST_ACKED), W(S1, 0x48), R(S0, 0x71),
        IRQ, R(S1, ST_NACKED), W(S1, 0x4D), R(S0, 1), W(S0, 0x94),
        IRQ, R(S1, ST_NACKED), W(S1, 0x4D), W(S0, 0x73),             /* 0x4A absent */
        IRQ, R(S1, ST_ACKED), W(S1, 0x48), R(S0, 0x73),
        IRQ, R(S1, ST_NACKED), W(S1, 0xCB), R(S0, 3),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_ERR_ABSENT);        /* the first error of the chain */
    assert_int_equal(x.msg_status, DRV_OK);
    assert_int_equal(second.msg_status, DRV_ERR_ABSENT);
    assert_int_equal(third.msg_status, DRV_OK);
    assert_int_equal(a, 1);
    assert_int_equal(c, 3);
}

/* A lost bus ends the message on the wire and every one after it. */
static void test_chain_arbitration_lost_fails_the_rest(void **state)
{
    uint8_t a = 0;
    struct i2c_xfer third = { .addr7 = 0x39 };
    struct i2c_xfer second = { .addr7 = 0x4A, .more = &third };
    struct i2c_xfer x = { .addr7 = 0x38, .rd = &a, .rd_len = 1, .more = &second };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x71), W(S1, 0xCD),
        IRQ, R(S1, ST_ACKED), W(S1, 0x48), R(S0, 0x71),
        IRQ, R(S1, ST_NACKED), W(S1, 0x4D), R(S0, 7), W(S0, 0x94),
        IRQ, R(S1, PCF_ST_LAB),
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_DONE);
    assert_int_equal(x.status, DRV_ERR_ARB);
    assert_int_equal(x.msg_status, DRV_OK);
    assert_int_equal(second.msg_status, DRV_ERR_ARB);
    assert_int_equal(third.msg_status, DRV_ERR_ARB);
    assert_int_equal(fsm.need_reset, 1);
}

static void test_chain_abort_times_out_the_rest(void **state)
{
    struct i2c_xfer third = { .addr7 = 0x39 };
    struct i2c_xfer second = { .addr7 = 0x4A, .more = &third };
    struct i2c_xfer x = { .addr7 = 0x38, .more = &second };
    const struct step s[] = {
        R(S1, ST_FREE), W(S0, 0x70), W(S1, 0xCD),
        IRQ, R(S1, ST_ACKED), W(S1, 0x4D), W(S0, 0x94),             /* probe 0x38 done */
    };
    (void)state;
    assert_int_equal(run(&fsm, &x, s, sizeof s / sizeof s[0]), I2C_FSM_RUNNING);
    assert_ptr_equal(i2c_fsm_abort(&fsm), &x);
    assert_int_equal(x.status, DRV_ERR_TIMEOUT);
    assert_int_equal(x.msg_status, DRV_OK);
    assert_int_equal(second.msg_status, DRV_ERR_TIMEOUT);
    assert_int_equal(third.msg_status, DRV_ERR_TIMEOUT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_write_two_bytes, setup),
        cmocka_unit_test_setup(test_address_nack_is_absent, setup),
        cmocka_unit_test_setup(test_data_nack_stops_with_absent, setup),
        cmocka_unit_test_setup(test_probe_is_address_only, setup),
        cmocka_unit_test_setup(test_write_then_read_with_repeated_start, setup),
        cmocka_unit_test_setup(test_read_one_byte, setup),
        cmocka_unit_test_setup(test_read_two_bytes, setup),
        cmocka_unit_test_setup(test_read_address_nack, setup),
        cmocka_unit_test_setup(test_busy_bus_sends_nothing, setup),
        cmocka_unit_test_setup(test_arbitration_lost, setup),
        cmocka_unit_test_setup(test_bus_error_needs_reset, setup),
        cmocka_unit_test_setup(test_spurious_interrupts_are_ignored, setup),
        cmocka_unit_test_setup(test_reset_sequence, setup),
        cmocka_unit_test_setup(test_chain_of_two_messages, setup),
        cmocka_unit_test_setup(test_chain_goes_on_after_a_nack, setup),
        cmocka_unit_test_setup(test_chain_arbitration_lost_fails_the_rest, setup),
        cmocka_unit_test_setup(test_chain_abort_times_out_the_rest, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
