/*
 * Host unit tests for bsched_fast.c (cmocka): on the same planned state,
 * bsched_fast_step must give exactly what Fig. 7's bsched_step gives, cycle by
 * cycle (return value, ran[], ran_count, cycle), bsched_wait must equal Fig. 7's
 * count-down wait[], and bsched_fast_due must equal bsched_due.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "bsched.h"
#include "bsched_fast.h"

static struct bsched fig7, fast;
static struct bsched_fast table;

/* Runs `cycles` minor cycles of both, from a state planned for pv[0..n-1] and
 * moved `skip` cycles on by Fig. 7 before the table is built. */
static void check_same(const uint8_t *pv, size_t n, uint32_t skip, uint32_t cycles)
{
    uint16_t due_fig7[BSCHED_MAX_PROCS], due_fast[BSCHED_MAX_PROCS];
    uint32_t t, i;

    assert_int_equal(bsched_init(&fig7, pv, n), BSCHED_OK);
    for (t = 0; t < skip; t++) {
        assert_true(bsched_step(&fig7) >= 0);
    }
    fast = fig7;
    assert_int_equal(bsched_fast_init(&table, &fast), BSCHED_OK);
    for (t = 0; t < cycles; t++) {
        int32_t a, b;
        uint32_t ahead = t * 7u;
        for (i = 0; i < n; i++) {
            assert_int_equal(bsched_wait(&fast, (uint16_t)i), (int32_t)fig7.wait[i]);
        }
        a = bsched_due(&fig7, ahead, due_fig7);
        b = bsched_fast_due(&fast, &table, ahead, due_fast);
        assert_int_equal(a, b);
        assert_memory_equal(due_fig7, due_fast, (size_t)a * sizeof due_fig7[0]);
        a = bsched_step(&fig7);
        b = bsched_fast_step(&fast, &table);
        assert_true(a >= 0);
        assert_int_equal(a, b);
        assert_int_equal(fig7.ran_count, fast.ran_count);
        assert_int_equal(fig7.cycle, fast.cycle);
        assert_memory_equal(fig7.ran, fast.ran, (size_t)a * sizeof fig7.ran[0]);
    }
}

static const uint8_t table1_pv[] = {1, 1, 1, 2, 2, 3, 4, 4, 4};

static void test_table2(void **state)
{
    static const uint16_t cycle2[] = {0, 2, 8}; /* Table 2, cycle 2: p1.1 p1.3 p4.3 */
    (void)state;
    check_same(table1_pv, 9, 0, 40);
    assert_int_equal(bsched_init(&fast, table1_pv, 9), BSCHED_OK);
    assert_int_equal(bsched_fast_init(&table, &fast), BSCHED_OK);
    assert_int_equal(bsched_fast_step(&fast, &table), 3);
    assert_int_equal(bsched_fast_step(&fast, &table), 2);
    assert_int_equal(bsched_fast_step(&fast, &table), 3);
    assert_memory_equal(fast.ran, cycle2, sizeof cycle2);
}

static uint32_t rng_state = 4242u;
static uint32_t rng(void)
{
    rng_state = rng_state * 1103515245u + 12345u;
    return rng_state >> 8;
}

static void test_generated_sets(void **state)
{
    static uint8_t pv[300];
    int set;
    (void)state;
    for (set = 0; set < 2000; set++) {
        size_t n = 1 + rng() % 300, i;
        unsigned lo = rng() % 4, maxpv = lo + rng() % 10;
        for (i = 0; i < n; i++) {
            pv[i] = (uint8_t)(lo + rng() % (maxpv - lo + 1));
        }
        check_same(pv, n, rng() % 64, 2u << maxpv > 600 ? 600 : 2u << maxpv);
    }
}

static void test_large_pv_and_capacity(void **state)
{
    static uint8_t pv[BSCHED_MAX_PROCS];
    size_t i;
    (void)state;
    for (i = 0; i < BSCHED_MAX_PROCS; i++) {
        pv[i] = (uint8_t)(i % 4 == 0 ? 31 : i % 13);
    }
    check_same(pv, BSCHED_MAX_PROCS, 5, 300);
    pv[0] = 31;
    check_same(pv, 1, 0, 40);
    pv[0] = 0;
    check_same(pv, 1, 0, 4);
}

static void record_call(void *context, uint16_t index)
{
    uint16_t *log = context;
    log[++log[0]] = index;
}

static void test_run_cycle(void **state)
{
    uint16_t log[16];
    (void)state;
    assert_int_equal(bsched_init(&fast, table1_pv, 9), BSCHED_OK);
    assert_int_equal(bsched_fast_init(&table, &fast), BSCHED_OK);
    log[0] = 0;
    assert_int_equal(bsched_fast_run_cycle(&fast, &table, record_call, log), 3);
    assert_int_equal(log[0], 3);
    assert_int_equal(log[1], 0);
    assert_int_equal(log[2], 2);
    assert_int_equal(log[3], 5);
    assert_int_equal(bsched_fast_run_cycle(&fast, &table, NULL, NULL), BSCHED_ERR_NULL);
}

/* Resynchronises when the state's cycle moved under the table (e.g. Fig. 7 ran). */
static void test_cycle_moved_under_table(void **state)
{
    (void)state;
    assert_int_equal(bsched_init(&fig7, table1_pv, 9), BSCHED_OK);
    fast = fig7;
    assert_int_equal(bsched_fast_init(&table, &fast), BSCHED_OK);
    (void)bsched_step(&fig7);
    fast.cycle = fig7.cycle;
    assert_int_equal(bsched_step(&fig7), bsched_fast_step(&fast, &table));
    assert_memory_equal(fig7.ran, fast.ran, fig7.ran_count * sizeof fig7.ran[0]);
}

static void test_errors_leave_state_untouched(void **state)
{
    static struct bsched zero, before;
    static struct bsched_fast table_before;
    uint16_t due[BSCHED_MAX_PROCS];
    (void)state;
    memset(&zero, 0, sizeof zero);
    assert_int_equal(bsched_fast_init(NULL, &zero), BSCHED_ERR_NULL);
    assert_int_equal(bsched_fast_init(&table, NULL), BSCHED_ERR_NULL);
    assert_int_equal(bsched_fast_init(&table, &zero), BSCHED_ERR_STATE);
    assert_int_equal(bsched_wait(NULL, 0), BSCHED_ERR_NULL);
    assert_int_equal(bsched_wait(&zero, 0), BSCHED_ERR_STATE);

    assert_int_equal(bsched_init(&fast, table1_pv, 9), BSCHED_OK);
    assert_int_equal(bsched_fast_init(&table, &fast), BSCHED_OK);
    assert_int_equal(bsched_wait(&fast, 9), BSCHED_ERR_INDEX);
    before = fast;
    table_before = table;
    assert_int_equal(bsched_fast_step(NULL, &table), BSCHED_ERR_NULL);
    assert_int_equal(bsched_fast_step(&fast, NULL), BSCHED_ERR_NULL);
    assert_int_equal(bsched_fast_due(&fast, &table, 0, NULL), BSCHED_ERR_NULL);
    assert_int_equal(bsched_fast_step(&zero, &table), BSCHED_ERR_STATE);
    /* A table built for another set (the O(1) check of every call). */
    table.count++;
    assert_int_equal(bsched_fast_step(&fast, &table), BSCHED_ERR_STATE);
    assert_int_equal(bsched_fast_due(&fast, &table, 0, due), BSCHED_ERR_STATE);
    table = table_before;
    table.used = 0;
    assert_int_equal(bsched_fast_step(&fast, &table), BSCHED_ERR_STATE);
    table = table_before;
    table.maxpv = 3;
    assert_int_equal(bsched_fast_step(&fast, &table), BSCHED_ERR_STATE);
    table = table_before;
    fast.cycle = 16; /* beyond the major cycle */
    assert_int_equal(bsched_fast_step(&fast, &table), BSCHED_ERR_STATE);
    fast.cycle = before.cycle;
    assert_memory_equal(&fast, &before, sizeof before);
    assert_memory_equal(&table, &table_before, sizeof table_before);
    /* An unsorted order[] is refused. */
    fast.order[0] = 8;
    fast.order[8] = 0;
    assert_int_equal(bsched_fast_init(&table, &fast), BSCHED_ERR_STATE);
    assert_memory_equal(&table, &table_before, sizeof table_before);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table2),
        cmocka_unit_test(test_generated_sets),
        cmocka_unit_test(test_large_pv_and_capacity),
        cmocka_unit_test(test_run_cycle),
        cmocka_unit_test(test_cycle_moved_under_table),
        cmocka_unit_test(test_errors_leave_state_untouched),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
