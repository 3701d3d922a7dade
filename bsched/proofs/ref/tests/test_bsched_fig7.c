/*
 * Host unit tests of the reference engine bsched_fig7 (cmocka).
 *
 * The expected schedule comes from the closed form, not from counting waits:
 * process i runs in cycle t iff t mod 2^pv_i == offset_i, the due processes in
 * execution order (ascending pv, ties in input order, computed here by a plain
 * selection, not from plan->order). The engine is also run beside bsched_step
 * on the same plans: the two must run the same processes in the same order
 * every cycle (what CBMC's `agree` harness proves within its bounds).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "bsched.h"
#include "bsched_fig7.h"
#include "../../tests/table2.h"

static struct bsched plan, plan_copy, library;
static struct bsched_fig7 ref;

/* The due processes of cycle t in execution order, from the closed form. */
static size_t expected_due(const uint8_t *pv, size_t n, uint64_t t, uint16_t *due)
{
    size_t done = 0, i;
    unsigned k;
    for (k = 0; k <= BSCHED_MAX_PV; k++) {
        for (i = 0; i < n; i++) {
            if (pv[i] == k && t % ((uint64_t)1 << k) == plan.offset[i]) {
                due[done++] = (uint16_t)i;
            }
        }
    }
    return done;
}

/* Plans pv, starts the engine and bsched_step's state, and runs `cycles`
 * minor cycles: every cycle the engine runs exactly the closed form's due set
 * in execution order, keeps its waits in phase, agrees with bsched_step, and
 * never touches the plan. */
static void check_engine(const uint8_t *pv, size_t n, uint64_t cycles)
{
    static uint16_t due[BSCHED_MAX_PROCS];
    uint64_t t;
    size_t i;

    assert_int_equal(bsched_init(&plan, pv, n), BSCHED_OK);
    library = plan;
    plan_copy = plan;
    assert_int_equal(bsched_fig7_start(&ref, &plan), BSCHED_OK);
    assert_int_equal(ref.cycle, 0);
    assert_int_equal(ref.ran_count, 0);
    for (t = 0; t < cycles; t++) {
        uint32_t period = (uint32_t)1u << plan.maxpv;
        size_t want = expected_due(pv, n, t, due);
        int32_t ran;
        int32_t lib;
        for (i = 0; i < n; i++) {
            uint32_t mask = ((uint32_t)1u << pv[i]) - 1u;
            /* in phase: wait = (offset - t) mod 2^pv */
            assert_int_equal(ref.wait[i], (plan.offset[i] - (uint32_t)t) & mask);
        }
        assert_int_equal(ref.cycle, (uint32_t)(t % period));
        ran = bsched_fig7_step(&ref, &plan);
        lib = bsched_step(&library);
        assert_int_equal(ran, (int32_t)want);
        assert_int_equal(ref.ran_count, want);
        assert_true(ran <= plan.perfect);
        assert_memory_equal(ref.ran, due, want * sizeof due[0]);
        assert_int_equal(lib, ran);
        assert_memory_equal(library.ran, ref.ran, want * sizeof ref.ran[0]);
    }
    assert_memory_equal(&plan, &plan_copy, sizeof plan);
}

static void test_table2(void **state)
{
    /* The paper's Table 2 (bsched/tests/table2.h). */
    int t, k;
    (void)state;
    assert_int_equal(bsched_init(&plan, table1_pv, 9), BSCHED_OK);
    assert_int_equal(bsched_fig7_start(&ref, &plan), BSCHED_OK);
    for (t = 0; t < 32; t++) {
        int32_t ran = bsched_fig7_step(&ref, &plan);
        for (k = 0; table2[t % 16][k] >= 0; k++) {
            assert_true(k < ran);
            assert_int_equal(ref.ran[k], table2[t % 16][k]);
        }
        assert_int_equal(ran, k);
    }
    check_engine(table1_pv, 9, 48);
}

static void test_shapes(void **state)
{
    static const uint8_t class0[] = {0, 2, 0, 1};
    static const uint8_t single[] = {5};
    static const uint8_t wrap[] = {2, 2, 2, 2, 2};
    static const uint8_t ties[] = {3, 1, 2, 1, 0, 3, 2, 1};
    static const uint8_t full[] = {1, 1};
    (void)state;
    check_engine(class0, 4, 20);
    check_engine(single, 1, 70);
    check_engine(wrap, 5, 12);
    check_engine(ties, 8, 20);
    check_engine(full, 2, 6);
}

/* Generated sets: n processes, pv drawn from lo..hi by a fixed LCG; a full
 * major cycle and a few cycles of the next. */
static void test_generated_sets(void **state)
{
    static uint8_t pv[BSCHED_MAX_PROCS];
    static const struct { size_t n; unsigned lo, hi; } sets[] = {
        {3, 0, 3}, {17, 1, 6}, {64, 3, 9}, {200, 2, 10}, {BSCHED_MAX_PROCS, 4, 11},
    };
    uint32_t x = 14u;
    size_t s, i;
    (void)state;
    for (s = 0; s < sizeof sets / sizeof sets[0]; s++) {
        unsigned maxpv = 0;
        for (i = 0; i < sets[s].n; i++) {
            x = x * 1103515245u + 12345u;
            pv[i] = (uint8_t)(sets[s].lo + (x >> 16) % (sets[s].hi - sets[s].lo + 1u));
            maxpv = pv[i] > maxpv ? pv[i] : maxpv;
        }
        check_engine(pv, sets[s].n, ((uint64_t)1 << maxpv) + 5);
    }
}

static void test_large_pv_from_the_middle(void **state)
{
    /* pv 31 processes: the waits stay in phase over a stretch of cycles. */
    static const uint8_t pv[] = {BSCHED_MAX_PV, 0, BSCHED_MAX_PV, 1, BSCHED_MAX_PV};
    (void)state;
    check_engine(pv, 5, 4096);
}

static void test_errors_leave_state_untouched(void **state)
{
    static struct bsched zero;
    static struct bsched_fig7 before;
    static const uint8_t pv[] = {1, 2};
    (void)state;
    memset(&zero, 0, sizeof zero);
    memset(&ref, 0xA5, sizeof ref);
    before = ref;
    assert_int_equal(bsched_fig7_start(NULL, &zero), BSCHED_ERR_NULL);
    assert_int_equal(bsched_fig7_start(&ref, NULL), BSCHED_ERR_NULL);
    assert_int_equal(bsched_fig7_start(&ref, &zero), BSCHED_ERR_STATE);
    assert_int_equal(bsched_fig7_step(NULL, &zero), BSCHED_ERR_NULL);
    assert_int_equal(bsched_fig7_step(&ref, NULL), BSCHED_ERR_NULL);
    assert_int_equal(bsched_fig7_step(&ref, &zero), BSCHED_ERR_STATE);
    assert_memory_equal(&ref, &before, sizeof before);
    /* A plan with an out-of-range maxpv fails the check too. */
    assert_int_equal(bsched_init(&plan, pv, 2), BSCHED_OK);
    plan.maxpv = BSCHED_MAX_PV + 1;
    assert_int_equal(bsched_fig7_step(&ref, &plan), BSCHED_ERR_STATE);
    assert_memory_equal(&ref, &before, sizeof before);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table2),
        cmocka_unit_test(test_shapes),
        cmocka_unit_test(test_generated_sets),
        cmocka_unit_test(test_large_pv_from_the_middle),
        cmocka_unit_test(test_errors_leave_state_untouched),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
