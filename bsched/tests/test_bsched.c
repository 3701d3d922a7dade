/*
 * Host unit tests for bsched.c (cmocka).
 *
 * The reference model below is written independently of the library, from the
 * paper's pseudo-code: classes are walked by scanning the input for each pv
 * (no sort), bit reversal goes through an array of bits, and due sets come
 * from the closed form t = w (mod 2^pv), not from counting waits down.
 * Fig. 7's waits (bsched_wait) are checked against the model's (w - t) mod 2^pv.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "bsched.h"
#include "table2.h"

static struct bsched sched;

/* ---------- reference model ---------- */

struct model {
    size_t n;
    unsigned maxpv;
    uint8_t pv[BSCHED_MAX_PROCS];
    uint32_t wait[BSCHED_MAX_PROCS];
    uint16_t order[BSCHED_MAX_PROCS];
    uint64_t area; /* U * 2^maxpv = sum 2^(maxpv - pv) */
    unsigned minpv;
    uint64_t start[BSCHED_MAX_PV + 1]; /* s_k of Fig. 6, for the classes up to maxpv */
    size_t first[BSCHED_MAX_PV + 1], size[BSCHED_MAX_PV + 1];
};

static uint32_t model_reverse(uint32_t x, unsigned bits)
{
    unsigned char b[32];
    uint32_t r = 0;
    unsigned i;
    for (i = 0; i < bits; i++) {
        b[i] = (unsigned char)((x >> i) & 1u); /* b[0] is the lowest bit */
    }
    for (i = 0; i < bits; i++) {
        r |= (uint32_t)b[bits - 1 - i] << i; /* r_i = b_(n-1-i) */
    }
    return r;
}

static void model_plan(struct model *m, const uint8_t *pv, size_t n)
{
    uint64_t start = 0, slots = 1;
    unsigned k;
    size_t i, pos = 0;

    memset(m, 0, sizeof *m);
    m->n = n;
    m->minpv = BSCHED_MAX_PV;
    for (i = 0; i < n; i++) {
        m->pv[i] = pv[i];
        if (pv[i] > m->maxpv) {
            m->maxpv = pv[i];
        }
        if (pv[i] < m->minpv) {
            m->minpv = pv[i];
        }
    }
    for (k = 0; k <= m->maxpv; k++) {
        uint64_t members = 0;
        if (k > 0) {
            start *= 2;
            slots *= 2;
        }
        m->start[k] = start;
        m->first[k] = pos;
        for (i = 0; i < n; i++) {
            if (pv[i] != k) {
                continue;
            }
            m->size[k]++;
            m->order[pos++] = (uint16_t)i;
            m->wait[i] = k == 0 ? 0 : model_reverse((uint32_t)((start + members) % slots), k);
            members++;
        }
        if (k > 0) {
            start = (start + members) % slots;
        }
    }
    for (i = 0; i < n; i++) {
        m->area += (uint64_t)1 << (m->maxpv - pv[i]);
    }
}

static int model_due(const struct model *m, size_t i, uint64_t t)
{
    return (t % ((uint64_t)1 << m->pv[i])) == m->wait[i];
}

/* Fig. 7's count-down at the start of cycle t: the cycles until i next runs. */
static uint32_t model_wait_at(const struct model *m, size_t i, uint64_t t)
{
    uint64_t period = (uint64_t)1 << m->pv[i];
    return (uint32_t)((m->wait[i] + period - t % period) % period);
}

static unsigned model_ceil_u(const struct model *m)
{
    uint64_t cycles = (uint64_t)1 << m->maxpv;
    return (unsigned)((m->area + cycles - 1) / cycles);
}

static unsigned model_floor_u(const struct model *m)
{
    return (unsigned)(m->area >> m->maxpv);
}

/* ---------- helpers ---------- */

static void plan(const uint8_t *pv, size_t n)
{
    assert_int_equal(bsched_init(&sched, pv, n), BSCHED_OK);
}

/* Checks a whole major cycle (and the start of the next) against the model:
 * each cycle runs exactly the model's due set, in execution order; loads are
 * floor(U) or ceil(U), with exactly area mod 2^M cycles at ceil(U); bsched_due
 * predicts every step; after the major cycle the state is back at its start. */
static void check_against_model(const uint8_t *pv, size_t n)
{
    struct model m;
    uint64_t cycles, t, heavy = 0;
    size_t i;
    unsigned c;
    static struct bsched initial;
    uint16_t predicted[BSCHED_MAX_PROCS];

    model_plan(&m, pv, n);
    plan(pv, n);
    assert_int_equal(sched.count, n);
    assert_int_equal(sched.maxpv, m.maxpv);
    assert_int_equal(sched.perfect, model_ceil_u(&m));
    assert_int_equal(sched.cycle, 0);
    for (i = 0; i < n; i++) {
        assert_int_equal(sched.offset[i], m.wait[i]);
        assert_int_equal(bsched_wait(&sched, (uint16_t)i), m.wait[i]);
        assert_int_equal(sched.order[i], m.order[i]);
        assert_int_equal(sched.pv[i], pv[i]);
        assert_true(sched.offset[i] < ((uint64_t)1 << pv[i]));
    }
    assert_int_equal(bsched_wait(&sched, (uint16_t)n), BSCHED_ERR_INDEX);
    /* The class table: where each class sits in order[], and its residue test on
     * 31-bit words: key ((2^k - s_k) mod 2^k) 2^(31-k), limit min(c_k, 2^k) 2^(31-k). */
    assert_int_equal(sched.minpv, m.minpv);
    assert_int_equal(sched.reversed, 0);
    for (c = 0; c <= m.maxpv; c++) {
        uint64_t period = (uint64_t)1 << c;
        uint64_t in_use = m.size[c] < period ? m.size[c] : period;
        assert_int_equal(sched.class_size[c], m.size[c]);
        assert_int_equal(sched.class_limit[c], in_use << (31 - c));
        if (m.size[c] != 0) {
            assert_int_equal(sched.class_first[c], m.first[c]);
            assert_int_equal(sched.class_key[c], ((period - m.start[c]) % period) << (31 - c));
        }
    }
    for (; c <= BSCHED_MAX_PV; c++) {
        assert_int_equal(sched.class_size[c], 0);
        assert_int_equal(sched.class_limit[c], 0);
    }
    initial = sched;

    cycles = (uint64_t)1 << m.maxpv;
    for (t = 0; t < cycles + 3; t++) {
        int32_t npred, ran;
        size_t expected = 0, k;
        /* The bit-reversed counter is rev_maxpv of the cycle, and every wait is
         * Fig. 7's count-down. */
        assert_int_equal(sched.cycle, t % cycles);
        assert_int_equal(sched.reversed, model_reverse((uint32_t)(t % cycles), m.maxpv));
        for (k = 0; k < n; k++) {
            assert_int_equal(bsched_wait(&sched, (uint16_t)k), model_wait_at(&m, k, t));
        }
        npred = bsched_due(&sched, 0, predicted);
        ran = bsched_step(&sched);
        assert_true(ran >= 0);
        assert_int_equal(npred, ran);
        assert_int_equal(sched.ran_count, ran);
        /* The model's due set, in execution order. */
        for (k = 0; k < n; k++) {
            uint16_t p = m.order[k];
            if (model_due(&m, p, t)) {
                assert_true(expected < (size_t)ran);
                assert_int_equal(sched.ran[expected], p);
                assert_int_equal(predicted[expected], p);
                expected++;
            }
        }
        assert_int_equal(expected, ran);
        assert_true((unsigned)ran >= model_floor_u(&m));
        assert_true((unsigned)ran <= model_ceil_u(&m));
        if (t < cycles && (unsigned)ran > model_floor_u(&m)) {
            heavy++;
        }
        if (t + 1 == cycles) {
            /* A major cycle later the schedule is where it began. */
            assert_int_equal(sched.cycle, 0);
            assert_int_equal(sched.reversed, 0);
            initial.ran_count = sched.ran_count;
            memcpy(initial.ran, sched.ran, sizeof initial.ran);
            assert_memory_equal(&sched, &initial, sizeof initial);
        }
    }
    assert_int_equal(heavy, m.area % cycles);
}

/* ---------- the paper's example ---------- */


static void test_table1_waits(void **state)
{
    static const uint32_t waits[] = {0, 1, 0, 1, 3, 0, 4, 12, 2};
    size_t i;
    (void)state;
    plan(table1_pv, 9);
    for (i = 0; i < 9; i++) {
        assert_int_equal(sched.offset[i], waits[i]);
    }
    assert_int_equal(sched.perfect, 3);
    assert_int_equal(sched.maxpv, 4);
}

static void test_table2_major_cycle(void **state)
{
    /* Table 2 (table2.h). */
    int t, k;
    (void)state;
    plan(table1_pv, 9);
    for (t = 0; t < 16; t++) {
        int32_t ran = bsched_step(&sched);
        for (k = 0; table2[t][k] >= 0; k++) {
            assert_true(k < ran);
            assert_int_equal(sched.ran[k], table2[t][k]);
        }
        assert_int_equal(ran, k);
    }
    check_against_model(table1_pv, 9);
}

/* ---------- shapes of priority sets ---------- */

static void test_class_zero_runs_every_cycle(void **state)
{
    static const uint8_t pv[] = {0, 2, 0, 1};
    int t;
    (void)state;
    plan(pv, 4);
    assert_int_equal(sched.offset[0], 0);
    assert_int_equal(sched.offset[2], 0);
    assert_int_equal(sched.perfect, 3); /* 1 + 1 + 1/2 + 1/4 = 2.75 */
    for (t = 0; t < 8; t++) {
        int32_t ran = bsched_step(&sched);
        assert_true(ran >= 2);
        assert_int_equal(sched.ran[0], 0); /* class 0 first, in input order */
        assert_int_equal(sched.ran[1], 2);
    }
    check_against_model(pv, 4);
}

static void test_single_process(void **state)
{
    static const uint8_t pv0[] = {0};
    static const uint8_t pv5[] = {5};
    int t;
    (void)state;
    plan(pv5, 1);
    assert_int_equal(sched.offset[0], 0);
    assert_int_equal(sched.perfect, 1);
    for (t = 0; t < 64; t++) {
        assert_int_equal(bsched_step(&sched), t % 32 == 0 ? 1 : 0);
    }
    check_against_model(pv0, 1);
    check_against_model(pv5, 1);
}

static void test_one_class_more_members_than_slots(void **state)
{
    /* Five processes of period 4: the fifth wraps onto slot 0 again. */
    static const uint8_t pv[] = {2, 2, 2, 2, 2};
    static const uint32_t waits[] = {0, 2, 1, 3, 0};
    size_t i;
    (void)state;
    plan(pv, 5);
    for (i = 0; i < 5; i++) {
        assert_int_equal(sched.offset[i], waits[i]);
    }
    assert_int_equal(sched.perfect, 2);
    assert_int_equal(bsched_step(&sched), 2);
    assert_int_equal(bsched_step(&sched), 1);
    assert_int_equal(bsched_step(&sched), 1);
    assert_int_equal(bsched_step(&sched), 1);
    check_against_model(pv, 5);
}

static void test_unsorted_input_with_ties(void **state)
{
    static const uint8_t pv[] = {3, 1, 2, 1, 0, 3, 2, 1};
    static const uint16_t order[] = {4, 1, 3, 7, 2, 6, 0, 5};
    size_t i;
    (void)state;
    plan(pv, 8);
    for (i = 0; i < 8; i++) {
        assert_int_equal(sched.order[i], order[i]);
        assert_int_equal(sched.pv[i], pv[i]); /* the caller's order is kept */
    }
    check_against_model(pv, 8);
}

static void test_largest_pv(void **state)
{
    static const uint8_t pv[] = {BSCHED_MAX_PV, 0, BSCHED_MAX_PV, 1, BSCHED_MAX_PV};
    struct model m;
    uint16_t due[BSCHED_MAX_PROCS];
    size_t i;
    (void)state;
    model_plan(&m, pv, 5);
    plan(pv, 5);
    assert_int_equal(sched.maxpv, BSCHED_MAX_PV);
    assert_int_equal(sched.perfect, 2);
    for (i = 0; i < 5; i++) {
        int32_t n, k, found = 0;
        assert_int_equal(sched.offset[i], m.wait[i]);
        /* Each pv-31 process is due exactly at its offset within 2^31 cycles. */
        n = bsched_due(&sched, sched.offset[i], due);
        for (k = 0; k < n; k++) {
            found |= due[k] == i;
        }
        assert_true(found);
    }
    /* Class 31 starts at start = 2^30 (classes 0 and 1 fill 1.5 slots):
     * its members get rev_31(2^30 + j). */
    assert_int_equal(sched.offset[0], 1u);
    assert_int_equal(sched.offset[2], (1u << 30) | 1u);
    assert_int_equal(sched.offset[4], (1u << 29) | 1u);
    /* A few thousand cycles from the start, against the closed form. */
    for (i = 0; i < 4096; i++) {
        int32_t ran = bsched_step(&sched);
        int32_t expect = 0;
        size_t p;
        for (p = 0; p < 5; p++) {
            expect += model_due(&m, p, i);
        }
        assert_int_equal(ran, expect);
    }
}

static void test_maximum_capacity(void **state)
{
    static uint8_t pv[BSCHED_MAX_PROCS];
    size_t i;
    (void)state;
    for (i = 0; i < BSCHED_MAX_PROCS; i++) {
        pv[i] = (uint8_t)(4 + (i * 7) % 5); /* pv 4..8, mixed order */
    }
    check_against_model(pv, BSCHED_MAX_PROCS);
}

/* ---------- errors ---------- */

static void fill_pattern(struct bsched *s)
{
    memset(s, 0xA5, sizeof *s);
}

static void test_init_errors_leave_state_untouched(void **state)
{
    static struct bsched before;
    static uint8_t many[BSCHED_MAX_PROCS + 1];
    static const uint8_t bad_pv[] = {1, 2, BSCHED_MAX_PV + 1, 0};
    static const uint8_t max_pv[] = {BSCHED_MAX_PV};
    (void)state;

    fill_pattern(&sched);
    before = sched;
    assert_int_equal(bsched_init(NULL, table1_pv, 9), BSCHED_ERR_NULL);
    assert_int_equal(bsched_init(&sched, NULL, 9), BSCHED_ERR_NULL);
    assert_memory_equal(&sched, &before, sizeof before);
    assert_int_equal(bsched_init(&sched, table1_pv, 0), BSCHED_ERR_NO_PROCS);
    assert_memory_equal(&sched, &before, sizeof before);
    assert_int_equal(bsched_init(&sched, many, BSCHED_MAX_PROCS + 1), BSCHED_ERR_TOO_MANY);
    assert_memory_equal(&sched, &before, sizeof before);
    assert_int_equal(bsched_init(&sched, bad_pv, 4), BSCHED_ERR_PV_RANGE);
    assert_memory_equal(&sched, &before, sizeof before);
    assert_int_equal(bsched_init(&sched, max_pv, 1), BSCHED_OK); /* the bound itself is fine */

    /* A valid state is not disturbed by a later bad init either. */
    plan(table1_pv, 9);
    before = sched;
    assert_int_equal(bsched_init(&sched, bad_pv, 4), BSCHED_ERR_PV_RANGE);
    assert_memory_equal(&sched, &before, sizeof before);
}

static void record_call(void *context, uint16_t index)
{
    uint16_t *log = context;
    log[++log[0]] = index;
}

static void test_step_and_due_errors(void **state)
{
    static struct bsched zero, before;
    uint16_t due[BSCHED_MAX_PROCS];
    (void)state;
    memset(&zero, 0, sizeof zero);
    before = zero;
    assert_int_equal(bsched_step(NULL), BSCHED_ERR_NULL);
    assert_int_equal(bsched_step(&zero), BSCHED_ERR_STATE);
    assert_memory_equal(&zero, &before, sizeof before);
    assert_int_equal(bsched_due(NULL, 0, due), BSCHED_ERR_NULL);
    assert_int_equal(bsched_due(&zero, 0, due), BSCHED_ERR_STATE);
    assert_int_equal(bsched_run_cycle(&zero, record_call, due), BSCHED_ERR_STATE);
    assert_int_equal(bsched_wait(NULL, 0), BSCHED_ERR_NULL);
    assert_int_equal(bsched_wait(&zero, 0), BSCHED_ERR_STATE);
    assert_memory_equal(&zero, &before, sizeof before);
    plan(table1_pv, 9);
    before = sched;
    assert_int_equal(bsched_due(&sched, 0, NULL), BSCHED_ERR_NULL);
    assert_int_equal(bsched_run_cycle(&sched, NULL, NULL), BSCHED_ERR_NULL);
    assert_int_equal(bsched_run_cycle(NULL, record_call, due), BSCHED_ERR_NULL);
    assert_int_equal(bsched_wait(&sched, 9), BSCHED_ERR_INDEX);
    assert_int_equal(bsched_wait(&sched, 65535), BSCHED_ERR_INDEX);
    assert_int_equal(bsched_wait(&sched, 8), 2); /* p4.3 runs in cycle 2 */
    assert_memory_equal(&sched, &before, sizeof before);
}

static void test_run_cycle_calls_in_order(void **state)
{
    uint16_t log[16];
    (void)state;
    plan(table1_pv, 9);
    log[0] = 0;
    assert_int_equal(bsched_run_cycle(&sched, record_call, log), 3);
    assert_int_equal(log[0], 3);
    assert_int_equal(log[1], 0);
    assert_int_equal(log[2], 2);
    assert_int_equal(log[3], 5);
    log[0] = 0;
    assert_int_equal(bsched_run_cycle(&sched, record_call, log), 2);
    assert_int_equal(log[0], 2);
    assert_int_equal(log[1], 1);
    assert_int_equal(log[2], 3);
}

static void test_due_ahead_matches_future_steps(void **state)
{
    uint16_t predicted[20][BSCHED_MAX_PROCS];
    int32_t counts[20];
    uint32_t a;
    (void)state;
    plan(table1_pv, 9);
    (void)bsched_step(&sched); /* from the middle of the major cycle */
    (void)bsched_step(&sched);
    for (a = 0; a < 20; a++) {
        counts[a] = bsched_due(&sched, a, predicted[a]);
    }
    for (a = 0; a < 20; a++) {
        int32_t ran = bsched_step(&sched), k;
        assert_int_equal(ran, counts[a]);
        for (k = 0; k < ran; k++) {
            assert_int_equal(sched.ran[k], predicted[a][k]);
        }
    }
}

/* ---------- generated sets ---------- */

static uint32_t rng_state = 12345u;
static uint32_t rng(void)
{
    rng_state = rng_state * 1103515245u + 12345u;
    return rng_state >> 8;
}

static void test_generated_sets(void **state)
{
    static uint8_t pv[64];
    int set;
    (void)state;
    for (set = 0; set < 3000; set++) {
        size_t n = 1 + rng() % 40, i;
        unsigned maxpv = rng() % 11;
        for (i = 0; i < n; i++) {
            pv[i] = (uint8_t)(rng() % (maxpv + 1));
        }
        check_against_model(pv, n);
    }
}

static void test_exhaustive_small_sets(void **state)
{
    /* Every multiset of priority values 0..4 with up to 6 processes, in ascending
     * and in descending input order. */
    uint8_t pv[6], rev[6];
    size_t n, i;
    (void)state;
    for (n = 1; n <= 6; n++) {
        memset(pv, 0, sizeof pv);
        for (;;) {
            for (i = 0; i < n; i++) {
                rev[i] = pv[n - 1 - i];
            }
            check_against_model(pv, n);
            check_against_model(rev, n);
            /* next non-decreasing sequence over 0..4 */
            i = n;
            while (i > 0 && pv[i - 1] == 4) {
                i--;
            }
            if (i == 0) {
                break;
            }
            pv[i - 1]++;
            for (; i < n; i++) {
                pv[i] = pv[i - 1];
            }
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table1_waits),
        cmocka_unit_test(test_table2_major_cycle),
        cmocka_unit_test(test_class_zero_runs_every_cycle),
        cmocka_unit_test(test_single_process),
        cmocka_unit_test(test_one_class_more_members_than_slots),
        cmocka_unit_test(test_unsorted_input_with_ties),
        cmocka_unit_test(test_largest_pv),
        cmocka_unit_test(test_maximum_capacity),
        cmocka_unit_test(test_init_errors_leave_state_untouched),
        cmocka_unit_test(test_step_and_due_errors),
        cmocka_unit_test(test_run_cycle_calls_in_order),
        cmocka_unit_test(test_due_ahead_matches_future_steps),
        cmocka_unit_test(test_generated_sets),
        cmocka_unit_test(test_exhaustive_small_sets),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
