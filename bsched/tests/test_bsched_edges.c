/*
 * Host unit tests for bsched.c (cmocka): the edges that mutation testing
 * (assure/mutants.py, make mutants) found the main suite did not pin down.
 * Each test names the mutants it kills; see ASSURANCE.md "Mutation testing".
 *
 * - the cheap state check rejects each kind of forged state on its own
 *   (count 0, count above capacity, maxpv above 31, perfect 0), not only a
 *   zeroed struct;
 * - an out-of-range pv is found in every position, the first included;
 * - bsched_init clears ran_count; bsched_step advances cycle modulo 2^maxpv;
 * - bsched_run_cycle calls the body when exactly one process is due;
 * - Fig. 7's cap (at most `perfect` processes per cycle) is gone from
 *   bsched_step: the balance theorem (proven by WP) says it never binds on a
 *   state from bsched_init. A state whose perfect was lowered is outside the
 *   contract; there the step still runs exactly the due processes (into ran[],
 *   which has room for every process), and the schedule goes on unchanged.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "bsched.h"

static const uint8_t table1_pv[] = {1, 1, 1, 2, 2, 3, 4, 4, 4};

static void plan_table1(struct bsched *s)
{
    memset(s, 0xA5, sizeof *s); /* every field starts out wrong */
    assert_int_equal(bsched_init(s, table1_pv, 9), BSCHED_OK);
}

/* Each forged state must fail the check by itself, in step and due,
 * and leave the state as it was. */
static void expect_rejected(const struct bsched *forged)
{
    static struct bsched s, before;
    uint16_t due[BSCHED_MAX_PROCS];
    s = *forged;
    before = s;
    assert_int_equal(bsched_step(&s), BSCHED_ERR_STATE);
    assert_int_equal(bsched_due(&s, 0, due), BSCHED_ERR_STATE);
    assert_int_equal(bsched_due(&s, 5, due), BSCHED_ERR_STATE);
    assert_memory_equal(&s, &before, sizeof s);
}

static void test_forged_states_rejected(void **state)
{
    static struct bsched good, bad;
    (void)state;
    plan_table1(&good);

    bad = good;
    bad.count = 0; /* no processes */
    expect_rejected(&bad);

    bad = good;
    bad.count = (uint16_t)(BSCHED_MAX_PROCS + 1); /* above capacity */
    expect_rejected(&bad);

#if BSCHED_MAX_PROCS < 65534
    bad = good;
    bad.count = (uint16_t)(BSCHED_MAX_PROCS + 2); /* further above: not just the first value */
    expect_rejected(&bad);
    bad = good;
    bad.count = 65535;
    expect_rejected(&bad);
#endif

    bad = good;
    bad.maxpv = BSCHED_MAX_PV + 1; /* a period the library cannot hold */
    expect_rejected(&bad);

    bad = good;
    bad.maxpv = 255;
    expect_rejected(&bad);

    bad = good;
    bad.perfect = 0; /* bsched_init never leaves 0 */
    expect_rejected(&bad);

    /* The bounds themselves are accepted. */
    bad = good;
    bad.maxpv = BSCHED_MAX_PV;
    assert_true(bsched_step(&bad) >= 0);
}

static void record_call(void *context, uint16_t index)
{
    uint16_t *log = context;
    log[++log[0]] = index;
}

static void test_forged_states_run_nothing(void **state)
{
    static struct bsched good, bad;
    uint16_t log[BSCHED_MAX_PROCS + 1];
    (void)state;
    plan_table1(&good);
    bad = good;
    bad.perfect = 0;
    log[0] = 0;
    assert_int_equal(bsched_run_cycle(&bad, record_call, log), BSCHED_ERR_STATE);
    assert_int_equal(log[0], 0);
    bad = good;
    bad.count = (uint16_t)(BSCHED_MAX_PROCS + 1);
    assert_int_equal(bsched_run_cycle(&bad, record_call, log), BSCHED_ERR_STATE);
    assert_int_equal(log[0], 0);
}

static void test_pv_range_checked_at_every_position(void **state)
{
    static struct bsched s, before;
    uint8_t pv[5];
    size_t bad, i;
    (void)state;
    for (bad = 0; bad < 5; bad++) {
        for (i = 0; i < 5; i++) {
            pv[i] = (uint8_t)(i == bad ? BSCHED_MAX_PV + 1 : 2);
        }
        memset(&s, 0x5A, sizeof s);
        before = s;
        assert_int_equal(bsched_init(&s, pv, 5), BSCHED_ERR_PV_RANGE);
        assert_memory_equal(&s, &before, sizeof s);
        pv[bad] = 255;
        assert_int_equal(bsched_init(&s, pv, 5), BSCHED_ERR_PV_RANGE);
        assert_memory_equal(&s, &before, sizeof s);
    }
}

static void test_init_clears_ran_count_and_cycle(void **state)
{
    static struct bsched s;
    (void)state;
    plan_table1(&s); /* from a struct full of 0xA5 */
    assert_int_equal(s.ran_count, 0);
    assert_int_equal(s.cycle, 0);
    /* and again after some steps, from a state that had run processes */
    assert_true(bsched_step(&s) > 0);
    assert_true(s.ran_count > 0);
    assert_int_equal(bsched_init(&s, table1_pv, 9), BSCHED_OK);
    assert_int_equal(s.ran_count, 0);
    assert_int_equal(s.cycle, 0);
}

static void test_cycle_counts_modulo_major_cycle(void **state)
{
    static struct bsched s;
    static const uint8_t pv0[] = {0, 0};
    uint32_t t;
    (void)state;
    plan_table1(&s); /* maxpv 4: a major cycle of 16 */
    for (t = 1; t <= 40; t++) {
        int32_t ran = bsched_step(&s);
        assert_true(ran >= 0);
        assert_int_equal(s.ran_count, (uint16_t)ran);
        assert_int_equal(s.cycle, t % 16u);
    }
    /* maxpv 0: the major cycle is one minor cycle, cycle stays 0 */
    assert_int_equal(bsched_init(&s, pv0, 2), BSCHED_OK);
    assert_int_equal(bsched_step(&s), 2);
    assert_int_equal(s.cycle, 0);
}

static void test_run_cycle_one_due_process(void **state)
{
    static struct bsched s;
    static const uint8_t pv[] = {1}; /* runs in cycle 0 alone, then idles */
    uint16_t log[4];
    (void)state;
    assert_int_equal(bsched_init(&s, pv, 1), BSCHED_OK);
    log[0] = 0;
    assert_int_equal(bsched_run_cycle(&s, record_call, log), 1);
    assert_int_equal(log[0], 1);
    assert_int_equal(log[1], 0);
    log[0] = 0;
    assert_int_equal(bsched_run_cycle(&s, record_call, log), 0);
    assert_int_equal(log[0], 0);
}

static void test_no_cap_when_perfect_is_too_small(void **state)
{
    static struct bsched s;
    uint16_t due[BSCHED_MAX_PROCS];
    uint16_t log[BSCHED_MAX_PROCS + 1];
    (void)state;
    plan_table1(&s);  /* cycle 0 runs p1.1 p1.3 p3.1 (inputs 0, 2, 5) */
    s.perfect = 1;    /* forged: outside the contract */
    assert_int_equal(bsched_due(&s, 0, due), 3);
    log[0] = 0;
    assert_int_equal(bsched_run_cycle(&s, record_call, log), 3);
    assert_int_equal(log[0], 3);
    assert_int_equal(log[1], 0);
    assert_int_equal(log[2], 2);
    assert_int_equal(log[3], 5);
    assert_int_equal(s.ran_count, 3);
    /* Nothing was deferred: the next cycle is Table 2's cycle 1 (p1.2 p2.1). */
    assert_int_equal(bsched_wait(&s, 0), 1);
    assert_int_equal(bsched_wait(&s, 1), 0);
    assert_int_equal(bsched_wait(&s, 5), 7);
    assert_int_equal(bsched_step(&s), 2);
    assert_int_equal(s.ran[0], 1);
    assert_int_equal(s.ran[1], 3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_forged_states_rejected),
        cmocka_unit_test(test_forged_states_run_nothing),
        cmocka_unit_test(test_pv_range_checked_at_every_position),
        cmocka_unit_test(test_init_clears_ran_count_and_cycle),
        cmocka_unit_test(test_cycle_counts_modulo_major_cycle),
        cmocka_unit_test(test_run_cycle_one_due_process),
        cmocka_unit_test(test_no_cap_when_perfect_is_too_small),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
