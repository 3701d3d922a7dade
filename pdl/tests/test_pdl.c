/* Host unit tests of the PDL runtime semantics (cmocka). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "pdl/host/pdl_host.h"
#include "pdl/pdl_internal.h"   /* PDL_VALID_* */

static int setup(void **state)
{
    (void)state;
    return pdl_reset();
}

/* ---- value() is the previous cycle's value, in every process ---- */
static struct pdl_quantity q_a, q_b;
static int32_t seen_by_reader[8];
static unsigned reader_runs;

static void writer(void) { add_value(q_a, 5); }
static void reader(void)
{
    if (reader_runs < 8u)
        seen_by_reader[reader_runs] = value(q_a);
    reader_runs++;
}

static void test_value_is_previous_cycle(void **state)
{
    (void)state;
    reader_runs = 0;
    assert_int_equal(add_quantity(&q_a, -100, 100, 7), PDL_OK);
    assert_int_equal(add_process(writer), 0);   /* runs before the reader */
    assert_int_equal(add_process(reader), 1);
    assert_int_equal(run_pdl(), PDL_OK);
    assert_int_equal(value(q_a), 7);
    assert_int_equal(pdl_run_cycles(3), 3);
    /* the reader ran after the writer each cycle, yet saw the old value */
    assert_int_equal(seen_by_reader[0], 7);
    assert_int_equal(seen_by_reader[1], 12);
    assert_int_equal(seen_by_reader[2], 17);
    assert_int_equal(value(q_a), 22);
}

/* ---- sums of several processes, several adds in one process ---- */
static void add_one(void) { add_value(q_a, 1); }
static void add_two_twice(void) { add_value(q_a, 2); add_value(q_a, 2); }
static void add_minus_ten(void) { add_value(q_a, -10); add_value(q_b, 3); }

static void test_add_value_sums_contributions(void **state)
{
    struct pdl_stats st;
    (void)state;
    assert_int_equal(add_quantity(&q_a, -1000, 1000, 0), PDL_OK);
    assert_int_equal(add_quantity(&q_b, -1000, 1000, 0), PDL_OK);
    add_process(add_one);
    add_process(add_two_twice);
    add_process(add_minus_ten);
    assert_int_equal(run_pdl(), PDL_OK);
    assert_int_equal(pdl_run_cycles(1), 1);
    assert_int_equal(value(q_a), 1 + 4 - 10);
    assert_int_equal(value(q_b), 3);
    assert_int_equal(pdl_run_cycles(9), 9);
    assert_int_equal(value(q_a), 10 * -5);
    assert_int_equal(value(q_b), 30);
    pdl_get_stats(&st);
    assert_int_equal(st.cycles, 10);
    assert_int_equal(st.process_runs, 30);
    assert_int_equal(st.commits, 20);           /* two quantities per cycle */
    assert_int_equal(st.misuse, 0);
}

/* ---- clipping at both bounds, of the cycle's sum (not of partial sums) ---- */
static void push_up(void) { add_value(q_a, 70); }
static void push_down(void) { add_value(q_b, -70); }

static void test_clipping_both_bounds(void **state)
{
    (void)state;
    add_quantity(&q_a, -100, 100, 0);
    add_quantity(&q_b, -100, 100, 0);
    add_process(push_up);
    add_process(push_down);
    run_pdl();
    pdl_run_cycles(1);
    assert_int_equal(value(q_a), 70);
    assert_int_equal(value(q_b), -70);
    pdl_run_cycles(1);
    assert_int_equal(value(q_a), 100);
    assert_int_equal(value(q_b), -100);
    pdl_run_cycles(5);
    assert_int_equal(value(q_a), 100);
    assert_int_equal(value(q_b), -100);
}

static int32_t big;
static void add_big(void) { add_value(q_a, big); }
static void sub_big(void) { add_value(q_a, -big); }

static void test_clip_applies_to_the_sum(void **state)
{
    (void)state;
    /* +big and -big in one cycle cancel, whatever the order, even though
     * either partial sum alone would leave the bounds (or int32) */
    big = INT32_MAX;
    add_quantity(&q_a, -10, 10, 9);
    add_process(add_big);
    add_process(add_big);
    add_process(sub_big);
    add_process(sub_big);
    run_pdl();
    pdl_run_cycles(4);
    assert_int_equal(value(q_a), 9);
}

/* ---- clipping at the int32 extremes (32-bit fast path and 64-bit path) ---- */
static int32_t wide_step;
static void add_wide(void) { add_value(q_a, wide_step); }

static void test_clipping_at_int32_extremes(void **state)
{
    static const struct { int32_t start, step, want; } cases[] = {
        {INT32_MAX - 1, 5, INT32_MAX},          /* distance 1 to max */
        {INT32_MAX - 10, 10, INT32_MAX},        /* lands exactly on max */
        {INT32_MIN + 1, -5, INT32_MIN},
        {INT32_MIN, INT32_MAX, -1},             /* distance 2^32 - 1: no clip */
        {INT32_MAX, INT32_MIN, -1},
        {0, INT32_MIN, INT32_MIN},              /* -2^31 fits 32 bits */
        {-1, INT32_MAX, INT32_MAX - 1},
    };
    unsigned i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        pdl_reset();
        assert_int_equal(add_quantity(&q_a, INT32_MIN, INT32_MAX, cases[i].start), PDL_OK);
        wide_step = cases[i].step;
        add_process(add_wide);
        run_pdl();
        pdl_run_cycles(1);
        assert_int_equal(value(q_a), cases[i].want);
    }
    /* two contributions whose sum leaves 32 bits: the 64-bit path */
    pdl_reset();
    add_quantity(&q_a, -1000, 1000, 0);
    wide_step = INT32_MIN;
    add_process(add_wide);
    add_process(add_wide);
    run_pdl();
    pdl_run_cycles(1);
    assert_int_equal(value(q_a), -1000);
}

/* ---- integer contributions at the extremes: no undefined behaviour ----
 * This file is also built with -fsanitize=undefined,float-cast-overflow
 * -fno-sanitize-recover (pdl.mk), so an overflow or an out-of-range
 * conversion anywhere on these paths fails the test; the -O2 build checks
 * the values, which such undefined behaviour used to get wrong. */
enum contribution_kind { C_I64, C_U64, C_DOUBLE, C_FLOAT, C_LDOUBLE, C_INT };
struct contribution { enum contribution_kind kind; int64_t i; uint64_t u; double d; };
static struct contribution extreme[2];
static unsigned extreme_n;
static void add_extreme(const struct contribution *c)
{
    switch (c->kind) {
    case C_I64: add_value(q_a, c->i); break;
    case C_U64: add_value(q_a, c->u); break;
    case C_DOUBLE: add_value(q_a, c->d); break;
    case C_FLOAT: add_value(q_a, (float)c->d); break;
    case C_LDOUBLE: add_value(q_a, (long double)c->d * (long double)c->d); break;
    case C_INT: add_value(q_a, (int32_t)c->i); break;
    }
}
static void extreme_first(void) { add_extreme(&extreme[0]); }
static void extreme_second(void) { if (extreme_n > 1u) add_extreme(&extreme[1]); }

/* One cycle of q_a in [min, max] from start with the contributions; the
 * committed value, the misuse count and the last error through the out
 * parameters. */
static int32_t run_extreme(int32_t min, int32_t max, int32_t start, unsigned *misuse, int *last)
{
    struct pdl_stats st;
    pdl_reset();
    assert_int_equal(add_quantity(&q_a, min, max, start), PDL_OK);
    add_process(extreme_first);
    add_process(extreme_second);
    assert_int_equal(run_pdl(), PDL_OK);
    assert_int_equal(pdl_run_cycles(1), 1);
    pdl_get_stats(&st);
    *misuse = st.misuse;
    *last = st.last_error;
    return value(q_a);
}

static void test_integer_contribution_extremes(void **state)
{
    static const struct {
        struct contribution c[2];
        unsigned n;
        int32_t min, max, start, want;
    } cases[] = {
        /* huge integers saturate and clip, never wrap or reverse the clip */
        {{{C_I64, INT64_MAX, 0, 0}}, 1, -100, 100, 50, 100},
        {{{C_I64, INT64_MAX, 0, 0}, {C_I64, INT64_MAX, 0, 0}}, 2, -100, 100, 50, 100},
        {{{C_I64, INT64_MIN, 0, 0}}, 1, -100, 100, -50, -100},
        {{{C_I64, INT64_MIN, 0, 0}, {C_I64, INT64_MIN, 0, 0}}, 2, -100, 100, -50, -100},
        {{{C_I64, INT64_MAX, 0, 0}, {C_INT, 1, 0, 0}}, 2, -100, 100, 99, 100},
        {{{C_I64, INT64_MIN, 0, 0}, {C_INT, -1, 0, 0}}, 2, -100, 100, -99, -100},
        {{{C_I64, INT64_MAX, 0, 0}, {C_I64, INT64_MIN, 0, 0}}, 2, -100, 100, 7, 6},
        {{{C_I64, INT64_MAX, 0, 0}}, 1, INT32_MIN, INT32_MAX, INT32_MAX, INT32_MAX},
        {{{C_I64, INT64_MIN, 0, 0}}, 1, INT32_MIN, INT32_MAX, INT32_MIN, INT32_MIN},
        {{{C_I64, INT64_MAX - 5, 0, 0}}, 1, INT32_MIN, INT32_MAX, INT32_MIN, INT32_MAX},
        {{{C_U64, 0, UINT64_MAX, 0}}, 1, -100, 100, 0, 100},         /* not -1 */
        {{{C_U64, 0, (uint64_t)INT64_MAX + 1u, 0}}, 1, -100, 100, 0, 100},
        /* huge finite floating values saturate the same way */
        {{{C_DOUBLE, 0, 0, 1e300}}, 1, -100, 100, 0, 100},
        {{{C_DOUBLE, 0, 0, -1e300}}, 1, -100, 100, 0, -100},
        {{{C_DOUBLE, 0, 0, 1e300}}, 1, INT32_MIN, INT32_MAX, INT32_MAX, INT32_MAX},
        {{{C_DOUBLE, 0, 0, -1e300}}, 1, INT32_MIN, INT32_MAX, INT32_MIN, INT32_MIN},
        {{{C_DOUBLE, 0, 0, 9.3e18}}, 1, -100, 100, -100, 100},       /* just past 2^63 */
        {{{C_DOUBLE, 0, 0, -9.3e18}}, 1, -100, 100, 100, -100},
        {{{C_DOUBLE, 0, 0, 1e300}, {C_DOUBLE, 0, 0, 1e300}}, 2, -100, 100, 0, 100},
        {{{C_FLOAT, 0, 0, 1e30}}, 1, -100, 100, 0, 100},
        {{{C_FLOAT, 0, 0, -1e30}}, 1, -100, 100, 0, -100},
        {{{C_LDOUBLE, 0, 0, 1e300}}, 1, -100, 100, 0, 100},          /* 1e600L */
        /* in range: truncated toward zero, as C converts */
        {{{C_DOUBLE, 0, 0, 2.9}}, 1, -100, 100, 0, 2},
        {{{C_DOUBLE, 0, 0, -2.9}}, 1, -100, 100, 0, -2},
        {{{C_FLOAT, 0, 0, -7.5}}, 1, -100, 100, 0, -7},
        {{{C_LDOUBLE, 0, 0, 3.0}}, 1, -100, 100, 0, 9},
    };
    static const double not_finite[] = {NAN, -NAN, INFINITY, -INFINITY};
    static const enum contribution_kind floating[] = {C_DOUBLE, C_FLOAT, C_LDOUBLE};
    unsigned i, k, misuse;
    int last;
    int32_t got;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        extreme[0] = cases[i].c[0];
        extreme[1] = cases[i].c[1];
        extreme_n = cases[i].n;
        got = run_extreme(cases[i].min, cases[i].max, cases[i].start, &misuse, &last);
        if (got != cases[i].want || misuse != 0u)
            print_message("case %u: %d (want %d), misuse %u\n", i, got, cases[i].want, misuse);
        assert_int_equal(got, cases[i].want);
        assert_int_equal(misuse, 0);
    }
    /* NaN and the infinities: refused (misuse, reported), the quantity
     * unchanged, and a valid contribution of the same cycle still counts */
    for (i = 0; i < sizeof not_finite / sizeof not_finite[0]; i++) {
        for (k = 0; k < sizeof floating / sizeof floating[0]; k++) {
            extreme[0] = (struct contribution){floating[k], 0, 0, not_finite[i]};
            extreme_n = 1;
            if (run_extreme(-100, 100, 42, &misuse, &last) != 42 || misuse != 1u)
                print_message("not finite %u, kind %u: misuse %u\n", i, k, misuse);
            assert_int_equal(run_extreme(-100, 100, 42, &misuse, &last), 42);
            assert_int_equal(misuse, 1);
            assert_int_equal(last, PDL_ERR_NOT_FINITE);
            assert_non_null(strstr(pdl_last_message(), "add_value"));
            assert_non_null(strstr(pdl_last_message(), pdl_strerror(PDL_ERR_NOT_FINITE)));
            extreme[1] = (struct contribution){C_INT, -5, 0, 0};
            extreme_n = 2;
            assert_int_equal(run_extreme(-100, 100, 42, &misuse, &last), 37);
            assert_int_equal(misuse, 1);
            /* and at the bounds: refused, not clipped to the opposite one */
            extreme_n = 1;
            assert_int_equal(run_extreme(-100, 100, 100, &misuse, &last), 100);
            assert_int_equal(run_extreme(-100, 100, -100, &misuse, &last), -100);
        }
    }
}

/* ---- order independence: shuffle the process order, same result ---- */
static struct pdl_quantity n_x, n_y, n_z;
static struct pdl_fquantity n_f;
static struct pdl_sensor n_s;
static int first_runner = -1;   /* which process ran first in the cycle */
static void note(int who) { if (first_runner < 0) first_runner = who; }
static void p_spring(void) { note(0); add_value(n_x, -value(n_x) / 4 + value(n_y) / 8); }
static void p_drive(void) { note(1); add_value(n_y, 40 - value(n_x) / 2); add_value(n_z, 7); }
static void p_brake(void) { note(2); add_value(n_y, -value(n_y) / 3); add_value(n_x, value(n_s) / 4 - 32); }
static void p_limit(void) { note(3); add_value(n_z, -value(n_z) / 2 - 30); add_value(n_x, 3); }
static void p_float(void) { note(4); add_value(n_f, 0.125f * (float)(value(n_y) % 16) - value(n_f) / 2.0f); }
static void p_slow(void) { note(5); add_value(n_z, 100); add_value(n_f, 0.5f); }
static void p_slower(void) { note(6); add_value(n_y, -value(n_z) / 4); add_value(n_x, -value(n_y) / 16); }

static pdl_process_fn network[] = {p_spring, p_drive, p_brake, p_limit, p_float, p_slow, p_slower};
/* bsched runs every pv 0 process each cycle, in the caller's order, so
 * shuffling changes the order of execution; a pv > 0 process's phase
 * (Fig. 6 initial wait) depends on its position in its pv class, so these
 * classes have one member each and the shuffle moves only their rank. */
static const int network_pv[] = {0, 0, 1, 0, 2, 3, 0};
#define NETWORK_N (sizeof network / sizeof network[0])

struct net_trace {
    int32_t x[64], y[64], z[64];
    float f[64];
    int first;
};

static void run_network(const unsigned *order, struct net_trace *t)
{
    unsigned i;
    pdl_reset();
    assert_int_equal(add_quantity(&n_x, -5000, 5000, 100), PDL_OK);
    assert_int_equal(add_quantity(&n_y, -3000, 3000, -20), PDL_OK);
    assert_int_equal(add_quantity(&n_z, -1000, 50, 0), PDL_OK);   /* clips often */
    assert_int_equal(add_fquantity(&n_f, -64.0f, 64.0f, 1.0f), PDL_OK);
    assert_int_equal(add_sensor(&n_s, 0, 255), PDL_OK);
    assert_int_equal(pdl_bind_sensor(&n_s, PDL_ANALOG_IN, 3), PDL_OK);
    for (i = 0; i < NETWORK_N; i++)
        assert_true(add_process_pv(network[order[i]], network_pv[order[i]]) >= 0);
    assert_int_equal(run_pdl(), PDL_OK);
    for (i = 0; i < 64; i++) {
        pdl_host_set_input(PDL_ANALOG_IN, 3, (int32_t)((i * 37u) % 256u));
        first_runner = -1;
        pdl_run_cycles(1);
        if (i == 0)
            t->first = first_runner;
        t->x[i] = value(n_x);
        t->y[i] = value(n_y);
        t->z[i] = value(n_z);
        t->f[i] = value(n_f);
    }
}

static void test_shuffled_order_same_result(void **state)
{
    static struct net_trace reference, shuffled;
    unsigned order[NETWORK_N];
    unsigned i, trial, firsts = 0;
    uint32_t rng = 12345u;
    (void)state;
    for (i = 0; i < NETWORK_N; i++)
        order[i] = i;
    run_network(order, &reference);
    /* the network is not trivial: values change and some clip */
    {
        unsigned changes = 0;
        for (i = 1; i < 64; i++)
            changes += reference.x[i] != reference.x[i - 1] && reference.y[i] != reference.y[i - 1];
        assert_true(changes > 20);
    }
    {
        unsigned clipped = 0;
        for (i = 0; i < 64; i++)
            clipped += reference.z[i] == 50 || reference.z[i] == -1000;
        assert_true(clipped > 0);
    }
    for (trial = 0; trial < 40; trial++) {
        /* Fisher-Yates shuffle, within each pv class as well as across:
         * bsched orders processes by pv, the caller's order within a class */
        for (i = NETWORK_N - 1u; i > 0; i--) {
            unsigned j, tmp;
            rng = rng * 1103515245u + 12345u;
            j = (rng >> 16) % (i + 1u);
            tmp = order[i];
            order[i] = order[j];
            order[j] = tmp;
        }
        run_network(order, &shuffled);
        assert_memory_equal(reference.x, shuffled.x, sizeof reference.x);
        assert_memory_equal(reference.y, shuffled.y, sizeof reference.y);
        assert_memory_equal(reference.z, shuffled.z, sizeof reference.z);
        /* the float contributions here are exact in binary: no rounding */
        assert_memory_equal(reference.f, shuffled.f, sizeof reference.f);
        firsts |= 1u << shuffled.first;
    }
    /* the shuffles did change the order of execution: several first runners */
    assert_true(__builtin_popcount(firsts) >= 3);
}

/* ---- per-pv periods, as bsched.c plans them ---- */
#define PERIOD_CYCLES 200u
static uint32_t cycle_now;
static uint32_t runs_at[6][PERIOD_CYCLES];
static uint32_t runs_n[6];
#define RECORDER(k) static void rec##k(void) { runs_at[k][runs_n[k]++] = cycle_now; }
RECORDER(0) RECORDER(1) RECORDER(2) RECORDER(3) RECORDER(4) RECORDER(5)
static pdl_process_fn recorders[6] = {rec0, rec1, rec2, rec3, rec4, rec5};

static void test_pv_periods(void **state)
{
    unsigned k, j;
    (void)state;
    memset(runs_n, 0, sizeof runs_n);
    for (k = 0; k < 6; k++)
        assert_int_equal(add_process_pv(recorders[k], (int)k), (int)k);
    assert_int_equal(run_pdl(), PDL_OK);
    for (cycle_now = 0; cycle_now < PERIOD_CYCLES; cycle_now++)
        pdl_run_cycles(1);
    for (k = 0; k < 6; k++) {
        uint32_t period = 1u << k;
        /* starts within its first period, then exactly every 2^pv cycles */
        assert_true(runs_at[k][0] < period);
        assert_int_equal(runs_n[k], (PERIOD_CYCLES - runs_at[k][0] + period - 1u) / period);
        for (j = 1; j < runs_n[k]; j++)
            assert_int_equal(runs_at[k][j] - runs_at[k][j - 1], period);
    }
    /* the pv 3 process: exactly every 8 cycles */
    assert_int_equal(runs_at[3][1] - runs_at[3][0], 8);
    assert_true(runs_n[3] == 25);
}

/* ---- the recorded major cycle replays exactly what bsched_run_cycle runs ---- */
#define LOG_MAX 4096u
static uint16_t run_log[LOG_MAX];
static unsigned run_log_n;
#define LOGGER(k) static void logger##k(void) { if (run_log_n < LOG_MAX) run_log[run_log_n++] = k; }
LOGGER(0) LOGGER(1) LOGGER(2) LOGGER(3) LOGGER(4) LOGGER(5) LOGGER(6) LOGGER(7) LOGGER(8)
static pdl_process_fn loggers[9] = {logger0, logger1, logger2, logger3, logger4, logger5,
                                     logger6, logger7, logger8};
static uint16_t cycle_mark[LOG_MAX];

static int max_pv(const uint8_t *pv, unsigned n)
{
    int m = 0;
    unsigned i;
    for (i = 0; i < n; i++)
        m = pv[i] > m ? pv[i] : m;
    return m;
}

/* Runs `cycles` cycles of the set; records the process order and where each cycle starts. */
static unsigned log_run(const uint8_t *pv, unsigned n, unsigned cycles, int cached)
{
    unsigned i;
    pdl_reset();
    pdl_plan_cache_enabled = cached;
    run_log_n = 0;
    for (i = 0; i < n; i++)
        assert_true(add_process_pv(loggers[i], pv[i]) >= 0);
    assert_int_equal(run_pdl(), PDL_OK);
    assert_int_equal(pdl_core_plan_recorded(), cached && max_pv(pv, n) <= 8);
    for (i = 0; i < cycles; i++) {
        cycle_mark[i] = (uint16_t)run_log_n;
        pdl_run_cycles(1);
    }
    pdl_plan_cache_enabled = 1;
    return run_log_n;
}

static void test_recorded_plan_equals_live_bsched(void **state)
{
    static const uint8_t sets[][9] = {
        {1, 1, 1, 2, 2, 3, 4, 4, 4},        /* the paper's Table 1 */
        {0, 0, 1, 2, 3, 4, 5, 6, 7},
        {3, 3, 3, 3, 3, 3, 3, 3, 3},
        {0, 8, 8, 2, 5, 1, 0, 7, 3},        /* maxpv 8: 256 cycles, still recorded */
        {9, 0, 1, 2, 3, 4, 5, 6, 7},        /* maxpv 9: 512 cycles, stepped live */
    };
    static uint16_t live[LOG_MAX], live_mark[LOG_MAX];
    unsigned k;
    (void)state;
    for (k = 0; k < sizeof sets / sizeof sets[0]; k++) {
        unsigned cycles = 1200u, n_live, n_cached;
        n_live = log_run(sets[k], 9, cycles, 0);
        memcpy(live, run_log, sizeof live);
        memcpy(live_mark, cycle_mark, sizeof live_mark);
        n_cached = log_run(sets[k], 9, cycles, 1);
        assert_int_equal(n_live, n_cached);
        assert_true(n_live > cycles / 2u);
        assert_memory_equal(live, run_log, n_live * sizeof live[0]);
        assert_memory_equal(live_mark, cycle_mark, cycles * sizeof live_mark[0]);
    }
}

/* ---- dt ---- */
static uint32_t dt_seen[16], dtp_seen[16];
static float dtf_seen, dtpf_seen;
static unsigned dt_runs, dtp_runs;
static void dt_recorder(void) { dt_seen[dt_runs++ % 16] = dt_us(); dtf_seen = dt(); }
static void dtp_recorder(void) { dtp_seen[dtp_runs++ % 16] = dt_process_us(); dtpf_seen = dt_process(); }

static void test_dt(void **state)
{
    (void)state;
    dt_runs = dtp_runs = 0;
    assert_int_equal(pdl_set_frequency(1000), PDL_OK);
    assert_int_equal(pdl_period_us(), 1000);
    assert_int_equal(pdl_frequency_mhz(), 1000000);
    add_process(dt_recorder);
    add_process_pv(dtp_recorder, 2);
    assert_int_equal(run_pdl(), PDL_OK);
    pdl_run_cycles(4);
    assert_int_equal(dt_seen[0], 1000);         /* first cycle: nominal */
    assert_int_equal(dt_seen[3], 1000);
    assert_int_equal(dtp_runs, 1);
    assert_int_equal(dtp_seen[0], 4000);        /* first run: 2^pv nominal periods */
    pdl_host_set_cycle_us(2500);                /* the clock slows down */
    pdl_run_cycles(8);
    assert_int_equal(dt_seen[4], 2500);
    assert_int_equal(dt_seen[11], 2500);
    assert_float_equal(dtf_seen, 0.0025f, 1e-7f);
    assert_int_equal(dtp_runs, 3);
    /* second run: 3 cycles of 1 ms then one of 2.5 ms; third: four of 2.5 ms */
    assert_int_equal(dtp_seen[1], 3 * 1000 + 2500);
    assert_int_equal(dtp_seen[2], 4 * 2500);
    assert_float_equal(dtpf_seen, 0.01f, 1e-7f);
    assert_int_equal(pdl_host_now_us(), 3 * 1000 + 8 * 2500);
    assert_int_equal(dt_process_us(), 0);       /* outside a process */
}

/* ---- float quantities ---- */
static struct pdl_fquantity fq;
static void fq_add(void) { add_value(fq, 0.75); add_value(fq, 0.5f); }

/* ---- narrow integer quantities: the same semantics at each type's edges ---- */
static struct pdl_quantity_int8 n_i8;
static struct pdl_quantity_int16 n_i16;
static struct pdl_quantity_uint8 n_u8;
static struct pdl_quantity_uint16 n_u16;
static int64_t narrow_add;              /* what each of two processes adds this cycle */
static int narrow_seen[4][2];           /* value() seen by the first and second process */

static void narrow_first(void)
{
    narrow_seen[0][0] = value(n_i8);
    narrow_seen[1][0] = value(n_i16);
    narrow_seen[2][0] = value(n_u8);
    narrow_seen[3][0] = value(n_u16);
    add_value(n_i8, narrow_add);
    add_value(n_i16, narrow_add);
    add_value(n_u8, narrow_add);
    add_value(n_u16, narrow_add);
}

static void narrow_second(void)
{
    narrow_seen[0][1] = value(n_i8);
    narrow_seen[1][1] = value(n_i16);
    narrow_seen[2][1] = value(n_u8);
    narrow_seen[3][1] = value(n_u16);
    add_value(n_i8, narrow_add);
    add_value(n_i16, narrow_add);
    add_value(n_u8, narrow_add);
    add_value(n_u16, narrow_add);
}

/* One cycle with both processes adding `add`; the four values after it. */
static void narrow_cycle(int64_t add, int expect[4])
{
    int before[4] = {value(n_i8), value(n_i16), value(n_u8), value(n_u16)};
    int k;
    narrow_add = add;
    assert_int_equal(pdl_run_cycles(1), 1);
    for (k = 0; k < 4; k++) {
        /* both processes saw the previous cycle's value */
        assert_int_equal(narrow_seen[k][0], before[k]);
        assert_int_equal(narrow_seen[k][1], before[k]);
    }
    assert_int_equal(value(n_i8), expect[0]);
    assert_int_equal(value(n_i16), expect[1]);
    assert_int_equal(value(n_u8), expect[2]);
    assert_int_equal(value(n_u16), expect[3]);
}

static void test_narrow_quantities(void **state)
{
    (void)state;
    /* bounds: the full range of each type */
    assert_int_equal(add_quantity_int8(&n_i8, INT8_MIN, INT8_MAX, 0), PDL_OK);
    assert_int_equal(add_quantity_int16(&n_i16, INT16_MIN, INT16_MAX, 0), PDL_OK);
    assert_int_equal(add_quantity_uint8(&n_u8, 0, UINT8_MAX, 0), PDL_OK);
    assert_int_equal(add_quantity_uint16(&n_u16, 0, UINT16_MAX, 0), PDL_OK);
    /* value() has the quantity's own type */
    assert_true(__builtin_types_compatible_p(__typeof__(value(n_i8)), int8_t));
    assert_true(__builtin_types_compatible_p(__typeof__(value(n_u16)), uint16_t));
    assert_int_equal(add_process(narrow_first), 0);
    assert_int_equal(add_process(narrow_second), 1);
    assert_int_equal(run_pdl(), PDL_OK);
    /* summed: 2 x 50 */
    narrow_cycle(50, (int[4]){100, 100, 100, 100});
    /* the sum 2 x 20 passes int8's max by 13: clipped, not wrapped */
    narrow_cycle(20, (int[4]){127, 140, 140, 140});
    /* one below each type's top: 2 x 127 */
    narrow_cycle(127, (int[4]){127, 394, 255, 394});
    /* far past every top (and past 32 bits): clipped to each max */
    narrow_cycle(INT64_C(1) << 40, (int[4]){INT8_MAX, INT16_MAX, UINT8_MAX, UINT16_MAX});
    /* the int64 sum saturates (2 x INT64_MAX): still the max, no wrap */
    narrow_cycle(INT64_MAX, (int[4]){INT8_MAX, INT16_MAX, UINT8_MAX, UINT16_MAX});
    /* down past every bottom: clipped to each min (0 for the unsigned ones) */
    narrow_cycle(INT64_MIN, (int[4]){INT8_MIN, INT16_MIN, 0, 0});
    /* exactly to the bottom and one step up */
    narrow_cycle(0, (int[4]){INT8_MIN, INT16_MIN, 0, 0});
    narrow_cycle(1, (int[4]){INT8_MIN + 2, INT16_MIN + 2, 2, 2});
    /* a cycle without contributions keeps the values */
    narrow_add = 0;
    assert_int_equal(pdl_run_cycles(1), 1);
    assert_int_equal(value(n_u8), 2);
}

static void test_narrow_bounds_and_misuse(void **state)
{
    struct pdl_stats st;
    (void)state;
    /* narrower bounds than the type: clipped to them */
    assert_int_equal(add_quantity_int8(&n_i8, -10, 10, 0), PDL_OK);
    assert_int_equal(add_quantity_uint16(&n_u16, 100, 200, 150), PDL_OK);
    assert_int_equal(add_quantity_int16(&n_i16, 5, 4, 5), PDL_ERR_BOUNDS);
    assert_int_equal(add_quantity_uint8(&n_u8, 10, 20, 9), PDL_ERR_BOUNDS);
    assert_int_equal(add_quantity_int8(&n_i8, -10, 10, 0), PDL_ERR_TWICE);
    assert_int_equal(add_quantity_uint8(NULL, 0, 1, 0), PDL_ERR_NULL);
    /* two more, and a process adding to all four */
    assert_int_equal(add_quantity_int16(&n_i16, -100, 100, 0), PDL_OK);
    assert_int_equal(add_quantity_uint8(&n_u8, 0, 255, 0), PDL_OK);
    assert_int_equal(add_process(narrow_first), 0);
    assert_int_equal(run_pdl(), PDL_OK);
    narrow_add = 1000;
    assert_int_equal(pdl_run_cycles(1), 1);
    assert_int_equal(value(n_i8), 10);
    assert_int_equal(value(n_u16), 200);
    narrow_add = -1000;
    assert_int_equal(pdl_run_cycles(1), 1);
    assert_int_equal(value(n_i8), -10);
    assert_int_equal(value(n_u16), 100);
    pdl_get_stats(&st);
    assert_int_equal(st.misuse, 4);
}

static void test_float_quantity(void **state)
{
    (void)state;
    assert_int_equal(add_fquantity(&fq, -2.0f, 2.0f, 0.0f), PDL_OK);
    add_process(fq_add);
    run_pdl();
    pdl_run_cycles(1);
    assert_float_equal(value(fq), 1.25f, 0.0f);
    pdl_run_cycles(1);
    assert_float_equal(value(fq), 2.0f, 0.0f);  /* clipped */
}

/* ---- fixed-point help ---- */
static void test_mul_shift(void **state)
{
    (void)state;
    assert_int_equal(pdl_mul_shift(3 << 8, 5 << 8, 8), 15 << 8);     /* 3.0 * 5.0 in Q8 */
    assert_int_equal(pdl_mul_shift(-384, 512, 8), -768);            /* -1.5 * 2.0 */
    assert_int_equal(pdl_mul_shift(INT32_MAX, 2, 1), INT32_MAX);    /* no overflow inside */
    assert_int_equal(pdl_mul_shift(-3, 1, 1), -2);                  /* toward minus infinity */
    /* Shifts of 64 and more (undefined for a plain >>) and results past int32. */
    assert_int_equal(pdl_mul_shift(INT32_MAX, INT32_MAX, 64), 0);
    assert_int_equal(pdl_mul_shift(-1, 1, 200), -1);
    assert_int_equal(pdl_mul_shift(INT32_MAX, INT32_MAX, 0), INT32_MAX);
    assert_int_equal(pdl_mul_shift(INT32_MIN, INT32_MAX, 1), INT32_MIN);
    assert_int_equal(pdl_mul_shift(INT32_MIN, INT32_MIN, 62), 1);
}

/* ---- bindings: sensors from ports, actuators to ports ---- */
static struct pdl_sensor s_light, s_bump;
static struct pdl_quantity m_left, m_led;
static void follow(void) { add_value(m_left, 4 * value(s_light) - value(m_left)); }
static void blink(void) { add_value(m_led, value(s_bump) - value(m_led)); }

static void test_bindings(void **state)
{
    static const struct pdl_binding table[] = {
        {&s_bump.head, PDL_BINARY_IN, 2},
        {&m_led.head, PDL_LED, 0},
    };
    (void)state;
    add_sensor(&s_light, 0, 200);
    add_sensor(&s_bump, 0, 1);
    add_quantity(&m_left, -2000, 2000, 0);
    add_quantity(&m_led, 0, 1, 0);
    assert_int_equal(pdl_bind_sensor(&s_light, PDL_ANALOG_IN, 5), PDL_OK);
    assert_int_equal(pdl_bind_actuator(&m_left, PDL_MOTOR, 1), PDL_OK);
    assert_int_equal(pdl_bind_table(table, 2), PDL_OK);
    add_process(follow);
    add_process(blink);
    pdl_host_set_input(PDL_ANALOG_IN, 5, 100);
    pdl_host_set_input(PDL_BINARY_IN, 2, 0);
    assert_int_equal(run_pdl(), PDL_OK);
    assert_int_equal(pdl_host_writes(PDL_MOTOR, 1), 1);    /* the initial value */
    pdl_run_cycles(1);
    assert_int_equal(value(s_light), 100);
    assert_int_equal(value(m_left), 400);
    assert_int_equal(pdl_host_output(PDL_MOTOR, 1), 400);
    pdl_host_set_input(PDL_ANALOG_IN, 5, 250);              /* clipped to the sensor's 200 */
    pdl_run_cycles(1);
    assert_int_equal(value(s_light), 200);
    assert_int_equal(value(m_left), 800);
    pdl_run_cycles(1);
    assert_int_equal(pdl_host_writes(PDL_MOTOR, 1), 3);
    pdl_run_cycles(5);                                      /* unchanged: not rewritten */
    assert_int_equal(pdl_host_writes(PDL_MOTOR, 1), 3);
    pdl_host_set_input(PDL_ANALOG_IN, 5, 255);
    pdl_host_set_input(PDL_ANALOG_IN, 5, 200);
    assert_int_equal(pdl_host_output(PDL_LED, 0), 0);
    pdl_host_set_input(PDL_BINARY_IN, 2, 0);
    pdl_run_cycles(1);
    pdl_host_set_input(PDL_BINARY_IN, 2, 1);    /* pulled up: 1 */
    pdl_run_cycles(1);
    assert_int_equal(value(m_led), 1);
    assert_int_equal(pdl_host_output(PDL_LED, 0), 1);
    /* an input the drivers failed to read keeps its sensor's last value */
    pdl_host_set_input_valid(PDL_VALID_ALL & ~(1ul << 5));
    pdl_host_set_input(PDL_ANALOG_IN, 5, 10);
    pdl_run_cycles(1);
    assert_int_equal(value(s_light), 200);
    pdl_host_set_input_valid(PDL_VALID_ALL);
    pdl_run_cycles(1);
    assert_int_equal(value(s_light), 10);
}

static struct pdl_quantity m_big;
static int32_t drive_step;
static void drive_big(void) { add_value(m_big, drive_step); }

static void test_actuator_clipped_to_port_and_driver_errors(void **state)
{
    struct pdl_stats st;
    (void)state;
    add_quantity(&m_big, -5000, 5000, 0);
    pdl_bind_actuator(&m_big, PDL_MOTOR, 0);
    add_process(drive_big);
    drive_step = 700;
    run_pdl();
    pdl_run_cycles(2);
    assert_int_equal(value(m_big), 1400);
    assert_int_equal(pdl_host_output(PDL_MOTOR, 0), 1000);  /* the motor's range */
    pdl_host_fail_output(PDL_MOTOR, 0, -5);
    drive_step = -900;                  /* 500, -400, -1300: three new outputs */
    pdl_run_cycles(3);
    pdl_get_stats(&st);
    assert_int_equal(st.driver_errors, 3);                  /* retried every cycle */
    assert_int_equal(st.last_error, PDL_ERR_DRIVER);
    assert_int_equal(st.last_driver_code, -5);
    assert_non_null(strstr(pdl_last_message(), "actuator write"));
    pdl_host_fail_output(PDL_MOTOR, 0, 0);
    pdl_run_cycles(1);
    pdl_get_stats(&st);
    assert_int_equal(st.driver_errors, 3);
    assert_int_equal(pdl_host_output(PDL_MOTOR, 0), -1000);  /* the failed value, retried */
}

/* ---- misuse is refused with an error, and changes nothing ---- */
static unsigned noop_runs;
static void noop(void) { noop_runs++; }
static struct pdl_quantity never_declared;
static void bad_add(void) { add_value(never_declared, 1); }

static void expect_refused(int got, int code, unsigned *misuse)
{
    struct pdl_stats st;
    assert_int_equal(got, code);
    pdl_get_stats(&st);
    assert_int_equal(st.misuse, ++*misuse);
    assert_int_equal(st.last_error, code);
    assert_non_null(strstr(pdl_last_message(), pdl_strerror(code)));
}

static void test_misuse_before_run(void **state)
{
    static struct pdl_quantity qs[PDL_MAX_QUANTITIES + 1];
    static struct pdl_sensor sens;
    struct pdl_fquantity ff;
    unsigned misuse = 0, i;
    (void)state;
    memset(&ff, 0, sizeof ff);
    expect_refused(run_pdl(), PDL_ERR_NO_PROCESSES, &misuse);
    expect_refused(pdl_run_cycles(1), PDL_ERR_NOT_RUNNING, &misuse);
    expect_refused(add_process(NULL), PDL_ERR_NULL, &misuse);
    expect_refused(add_process_pv(noop, -1), PDL_ERR_PV_RANGE, &misuse);
    expect_refused(add_process_pv(noop, PDL_MAX_PV + 1), PDL_ERR_PV_RANGE, &misuse);
    assert_int_equal(add_process_pv(noop, PDL_MAX_PV), 0);
    for (i = 1; i < PDL_MAX_PROCESSES; i++)
        assert_int_equal(add_process(noop), (int)i);
    expect_refused(add_process(noop), PDL_ERR_TOO_MANY_PROCESSES, &misuse);
    expect_refused(add_quantity(&qs[0], 5, 4, 5), PDL_ERR_BOUNDS, &misuse);
    expect_refused(add_quantity(&qs[0], 0, 10, 11), PDL_ERR_BOUNDS, &misuse);
    expect_refused(add_quantity(&qs[0], 0, 10, -1), PDL_ERR_BOUNDS, &misuse);
    expect_refused(add_sensor(&sens, 1, 0), PDL_ERR_BOUNDS, &misuse);
    expect_refused(add_fquantity(&ff, 1.0f, -1.0f, 0.0f), PDL_ERR_BOUNDS, &misuse);
    expect_refused(add_fquantity(&ff, -1.0f, 1.0f, 0.0f / 0.0f), PDL_ERR_BOUNDS, &misuse);
    expect_refused(add_quantity(NULL, 0, 1, 0), PDL_ERR_NULL, &misuse);
    assert_int_equal(qs[0].head.id, 0);     /* refused declarations left nothing */
    for (i = 0; i < PDL_MAX_QUANTITIES; i++)
        assert_int_equal(add_quantity(&qs[i], 0, 10, 0), PDL_OK);
    expect_refused(add_quantity(&qs[PDL_MAX_QUANTITIES], 0, 10, 0),
                   PDL_ERR_TOO_MANY_QUANTITIES, &misuse);
    expect_refused(add_quantity(&qs[3], 0, 10, 0), PDL_ERR_TWICE, &misuse);
    expect_refused(pdl_set_frequency(0), PDL_ERR_FREQUENCY, &misuse);
}

static void test_misuse_of_bindings(void **state)
{
    static struct pdl_sensor s1;
    static struct pdl_quantity a1, a2, undeclared;
    unsigned misuse = 0;
    (void)state;
    add_sensor(&s1, 0, 255);
    add_quantity(&a1, -1000, 1000, 0);
    add_quantity(&a2, -1000, 1000, 0);
    expect_refused(pdl_bind_sensor(&s1, PDL_MOTOR, 0), PDL_ERR_PORT, &misuse);        /* output */
    expect_refused(pdl_bind_sensor(&s1, PDL_ANALOG_IN, 24), PDL_ERR_PORT, &misuse);
    expect_refused(pdl_bind_sensor(&s1, PDL_BINARY_IN, 0), PDL_ERR_PORT, &misuse);    /* IP1..5 */
    expect_refused(pdl_bind_actuator(&a1, PDL_ANALOG_IN, 0), PDL_ERR_PORT, &misuse);  /* input */
    expect_refused(pdl_bind_actuator(&a1, PDL_MOTOR, 3), PDL_ERR_PORT, &misuse);
    expect_refused(pdl_bind_actuator(&a1, (enum pdl_port)0, 0), PDL_ERR_PORT, &misuse);
    expect_refused(pdl_bind_actuator(&undeclared, PDL_MOTOR, 0), PDL_ERR_UNDECLARED, &misuse);
    /* a sensor quantity cannot be bound as an actuator, nor the other way round */
    expect_refused(pdl_bind_actuator((struct pdl_quantity *)(void *)&s1, PDL_MOTOR, 0),
                   PDL_ERR_UNDECLARED, &misuse);
    assert_int_equal(pdl_bind_sensor(&s1, PDL_ANALOG_IN, 0), PDL_OK);
    expect_refused(pdl_bind_sensor(&s1, PDL_ANALOG_IN, 1), PDL_ERR_TWICE, &misuse);
    assert_int_equal(pdl_bind_actuator(&a1, PDL_MOTOR, 0), PDL_OK);
    expect_refused(pdl_bind_actuator(&a2, PDL_MOTOR, 0), PDL_ERR_PORT_TAKEN, &misuse);
    expect_refused(pdl_bind_table(NULL, 1), PDL_ERR_NULL, &misuse);
}

/* ---- a refused binding table binds nothing, whichever line is bad ---- */
static struct pdl_sensor t_light, t_bump;
static struct pdl_quantity t_left, t_right, t_undeclared;
static void t_drive(void)
{
    add_value(t_left, 300 + value(t_light));
    add_value(t_right, -300);
}

static void test_bind_table_all_or_nothing(void **state)
{
    /* good lines, each a different port; a bad line goes in at every position */
    static const struct pdl_binding good[] = {
        {&t_light.head, PDL_ANALOG_IN, 4},
        {&t_left.head, PDL_MOTOR, 0},
        {&t_right.head, PDL_MOTOR, 1},
        {&t_bump.head, PDL_BINARY_IN, 1},
    };
    static const struct { struct pdl_binding line; int code; } bad[] = {
        {{&t_left.head, PDL_MOTOR, 7}, PDL_ERR_PORT},               /* no such motor */
        {{&t_light.head, PDL_MOTOR, 2}, PDL_ERR_PORT},              /* a sensor on an output */
        {{&t_undeclared.head, PDL_MOTOR, 2}, PDL_ERR_UNDECLARED},
        {{NULL, PDL_MOTOR, 2}, PDL_ERR_NULL},
        {{&t_right.head, PDL_MOTOR, 0}, PDL_ERR_PORT_TAKEN},        /* motor 0 twice in the table */
        {{&t_light.head, PDL_ANALOG_IN, 5}, PDL_ERR_TWICE},         /* a sensor twice in the table */
    };
    struct pdl_binding table[5];
    struct pdl_stats st;
    unsigned b, pos, i, n;
    (void)state;
    for (b = 0; b < sizeof bad / sizeof bad[0]; b++) {
        for (pos = 0; pos <= 4; pos++) {
            pdl_reset();
            assert_int_equal(add_sensor(&t_light, 0, 255), PDL_OK);
            assert_int_equal(add_sensor(&t_bump, 0, 1), PDL_OK);
            assert_int_equal(add_quantity(&t_left, -1000, 1000, 0), PDL_OK);
            assert_int_equal(add_quantity(&t_right, -1000, 1000, 0), PDL_OK);
            for (i = 0, n = 0; i < 5; i++)
                table[i] = i == pos ? bad[b].line : good[n++];
            if (pdl_bind_table(table, 5) != bad[b].code)
                print_message("bad line %u at %u\n", b, pos);
            pdl_get_stats(&st);
            assert_int_equal(st.misuse, 1);
            assert_int_equal(st.last_error, bad[b].code);
            assert_non_null(strstr(pdl_last_message(), "pdl_bind_table: line "));
            assert_non_null(strstr(pdl_last_message(), ", none bound"));
            assert_non_null(strstr(pdl_last_message(), pdl_strerror(bad[b].code)));
            if (b < 4u) {       /* wrong on its own: the message names its line */
                char line[24];
                snprintf(line, sizeof line, "line %u,", pos + 1u);
                assert_non_null(strstr(pdl_last_message(), line));
            }
            /* nothing of the table was bound: no port in use ... */
            for (i = PDL_ANALOG_IN; i < PDL_PORT_END; i++)
                assert_false(pdl_bind_uses((enum pdl_port)i));
            /* ... and nothing drives a motor or reads an input afterwards */
            assert_int_equal(add_process(t_drive), 0);
            pdl_host_set_input(PDL_ANALOG_IN, 4, 200);
            assert_int_equal(run_pdl(), PDL_OK);
            assert_int_equal(pdl_run_cycles(3), 3);
            assert_int_equal(value(t_light), 0);
            assert_int_equal(value(t_left), 900);
            assert_int_equal(value(t_right), -900);
            assert_int_equal(pdl_host_writes(PDL_MOTOR, 0), 0);
            assert_int_equal(pdl_host_writes(PDL_MOTOR, 1), 0);
            assert_int_equal(pdl_host_output(PDL_MOTOR, 0), 0);
            assert_int_equal(pdl_host_output(PDL_MOTOR, 1), 0);
        }
    }
    /* too many lines for the room left: refused whole as well */
    pdl_reset();
    assert_int_equal(add_sensor(&t_light, 0, 255), PDL_OK);
    {
        static struct pdl_quantity outs[PDL_MAX_BINDINGS];
        static struct pdl_binding lines[PDL_MAX_BINDINGS + 1];
        static const struct { enum pdl_port port; unsigned n; } room[] = {
            {PDL_BIO_OUT, 16}, {PDL_FAST_OUT, 16}, {PDL_PWM, 16},
        };
        unsigned r;
        lines[0] = (struct pdl_binding){&t_light.head, PDL_ANALOG_IN, 0};
        for (r = 0, n = 1; r < 3 && n <= PDL_MAX_BINDINGS; r++)
            for (i = 0; i < room[r].n && n <= PDL_MAX_BINDINGS; i++, n++) {
                assert_int_equal(add_quantity(&outs[n - 1u], 0, 1, 0), PDL_OK);
                lines[n] = (struct pdl_binding){&outs[n - 1u].head, room[r].port, i};
            }
        assert_int_equal(n, PDL_MAX_BINDINGS + 1);
        assert_int_equal(pdl_bind_table(lines, n), PDL_ERR_TOO_MANY_BINDINGS);
        for (i = PDL_ANALOG_IN; i < PDL_PORT_END; i++)
            assert_false(pdl_bind_uses((enum pdl_port)i));
        /* one line fewer fits, and is bound whole */
        assert_int_equal(pdl_bind_table(lines, n - 1u), PDL_OK);
        assert_true(pdl_bind_uses(PDL_ANALOG_IN));
        assert_true(pdl_bind_uses(PDL_FAST_OUT));
    }
    /* after a refusal the corrected table binds every line */
    pdl_reset();
    add_sensor(&t_light, 0, 255);
    add_sensor(&t_bump, 0, 1);
    add_quantity(&t_left, -1000, 1000, 0);
    add_quantity(&t_right, -1000, 1000, 0);
    table[0] = good[0];
    table[1] = good[1];
    table[2] = bad[0].line;
    assert_int_equal(pdl_bind_table(table, 3), PDL_ERR_PORT);
    assert_int_equal(pdl_bind_table(good, 4), PDL_OK);
    add_process(t_drive);
    pdl_host_set_input(PDL_ANALOG_IN, 4, 200);
    run_pdl();
    pdl_run_cycles(1);
    assert_int_equal(value(t_light), 200);
    assert_int_equal(pdl_host_output(PDL_MOTOR, 0), 500);
    assert_int_equal(pdl_host_output(PDL_MOTOR, 1), -300);
}

static void test_misuse_after_run(void **state)
{
    static struct pdl_quantity late;
    static struct pdl_sensor late_s;
    unsigned misuse = 0;
    struct pdl_stats st;
    (void)state;
    noop_runs = 0;
    add_quantity(&q_a, 0, 100, 50);
    add_process(noop);
    assert_int_equal(run_pdl(), PDL_OK);
    expect_refused(run_pdl(), PDL_ERR_RUNNING, &misuse);
    expect_refused(add_process(noop), PDL_ERR_RUNNING, &misuse);
    expect_refused(add_process_pv(noop, 1), PDL_ERR_RUNNING, &misuse);
    expect_refused(add_quantity(&late, 0, 1, 0), PDL_ERR_RUNNING, &misuse);
    expect_refused(add_sensor(&late_s, 0, 1), PDL_ERR_RUNNING, &misuse);
    expect_refused(pdl_bind_actuator(&q_a, PDL_MOTOR, 2), PDL_ERR_RUNNING, &misuse);
    expect_refused(pdl_set_frequency(50), PDL_ERR_RUNNING, &misuse);
    /* add_value outside a process: refused, and the value stays */
    add_value(q_a, 10);
    pdl_get_stats(&st);
    assert_int_equal(st.last_error, PDL_ERR_OUTSIDE_PROCESS);
    misuse++;
    pdl_run_cycles(2);
    assert_int_equal(value(q_a), 50);
    assert_int_equal(noop_runs, 2);             /* the refused processes never ran */
}

static void test_add_value_on_undeclared_quantity(void **state)
{
    struct pdl_stats st;
    (void)state;
    add_process(bad_add);
    run_pdl();
    pdl_run_cycles(3);
    pdl_get_stats(&st);
    assert_int_equal(st.misuse, 3);             /* once per cycle */
    assert_int_equal(st.last_error, PDL_ERR_UNDECLARED);
    assert_int_equal(st.commits, 0);
    assert_non_null(strstr(pdl_last_message(), "add_value"));
}

static void test_reset_and_rerun(void **state)
{
    (void)state;
    add_quantity(&q_a, -100, 100, 0);
    add_process(add_one);
    run_pdl();
    pdl_run_cycles(5);
    assert_int_equal(value(q_a), 5);
    assert_int_equal(pdl_stop(0), PDL_OK);
    assert_int_equal(pdl_run_cycles(1), PDL_ERR_NOT_RUNNING);
    pdl_reset();
    /* the same quantity can be declared again after a reset */
    assert_int_equal(add_quantity(&q_a, -100, 100, 3), PDL_OK);
    add_process(add_one);
    run_pdl();
    pdl_run_cycles(2);
    assert_int_equal(value(q_a), 5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_value_is_previous_cycle, setup),
        cmocka_unit_test_setup(test_add_value_sums_contributions, setup),
        cmocka_unit_test_setup(test_clipping_both_bounds, setup),
        cmocka_unit_test_setup(test_clip_applies_to_the_sum, setup),
        cmocka_unit_test_setup(test_clipping_at_int32_extremes, setup),
        cmocka_unit_test_setup(test_integer_contribution_extremes, setup),
        cmocka_unit_test_setup(test_shuffled_order_same_result, setup),
        cmocka_unit_test_setup(test_pv_periods, setup),
        cmocka_unit_test_setup(test_recorded_plan_equals_live_bsched, setup),
        cmocka_unit_test_setup(test_dt, setup),
        cmocka_unit_test_setup(test_narrow_quantities, setup),
        cmocka_unit_test_setup(test_narrow_bounds_and_misuse, setup),
        cmocka_unit_test_setup(test_float_quantity, setup),
        cmocka_unit_test(test_mul_shift),
        cmocka_unit_test_setup(test_bindings, setup),
        cmocka_unit_test_setup(test_actuator_clipped_to_port_and_driver_errors, setup),
        cmocka_unit_test_setup(test_misuse_before_run, setup),
        cmocka_unit_test_setup(test_misuse_of_bindings, setup),
        cmocka_unit_test_setup(test_bind_table_all_or_nothing, setup),
        cmocka_unit_test_setup(test_misuse_after_run, setup),
        cmocka_unit_test_setup(test_add_value_on_undeclared_quantity, setup),
        cmocka_unit_test_setup(test_reset_and_rerun, setup),
    };
    return cmocka_run_group_tests_name("pdl", tests, NULL, NULL);
}
