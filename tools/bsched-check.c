/*
 * bsched-check.c: the independent checker of bsched-plan --certify's run+check
 * method (bsched-check.h has the interface and the trace format).
 *
 * It shares no code with bsched.c or Fig. 7's reference engine, and takes
 * nothing from the library but the trace its run left. Fig. 7's schedule is
 * computed here from the paper's definitions (Fig. 6's initial waits from a
 * stable ascending sort and bit reversal; Fig. 7's waits counted down, kept as
 * the absolute cycle each wait reaches 0), not by running the reference engine:
 * that engine starts from the plan bsched_init made, so it would inherit the
 * library's initial waits instead of checking them.
 *
 * What is checked, for the set pv[0..N-1], M = maxpv, U = sum 2^-pv, and
 * A = U 2^M = sum 2^(M - pv) (an integer: U exactly):
 *   plan    the library planned this set (status 0, the same N and pv, maxpv M),
 *           its perfect is ceil(U) and its initial waits are Fig. 6's;
 *   period  in the trace each process first runs at a cycle below 2^pv (its
 *           phase), then exactly 2^pv cycles after each previous run, 2^(M - pv)
 *           times in the major cycle, and 2^pv cycles from its last run to its
 *           first of the next major cycle: once every 2^pv cycles, constant phase;
 *           and that phase is the library's own initial wait;
 *   balance every cycle t runs exactly ceil((A - rev_M(t)) / 2^M) processes (0 when
 *           A <= rev_M(t)), the count of the balance theorem (bsched/README.md,
 *           bsched/spec/bsched_balance.h): so between floor(U) and ceil(U), and
 *           when U is not whole exactly A mod 2^M cycles at ceil(U), when it is
 *           every cycle at U (checked as well, from the loads seen);
 *   fig7    every cycle calls exactly Fig. 7's processes in Fig. 7's order (the
 *           due processes in sorted order, at most perfect of them), and
 *           bsched_run_cycle returns the number it called;
 *   repeat  after the major cycle the library's cycle counter is back at 0 and
 *           every Fig. 7 wait is back at its initial value.
 * Memory: O(N) per process arrays and Fig. 7's calendar of 2^M heads; the
 * trace is read cycle by cycle and never kept.
 */
#include "bsched-check.h"

#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

const char *const check_property_name[CHECK_COUNT] = {"plan", "period", "balance", "fig7", "repeat"};

#define NO_PROCESS 0xffffffffu

struct checker {
    const uint8_t *pv;
    uint32_t n;
    uint32_t maxpv, cycles, mask;
    uint64_t area;        /* A = U 2^maxpv */
    uint32_t ceil_u, floor_u;
    uint32_t *position;   /* place of each process in the stable ascending sort by pv */
    uint32_t *by_position;/* the process at each place */
    uint32_t *fig6_wait;  /* Fig. 6's initial wait of each process */
    uint32_t *claimed;    /* the library's initial wait of each process (the trace's plan) */
    uint32_t *due;        /* Fig. 7: the cycle in which the process's wait is 0 */
    uint32_t *next;       /* Fig. 7's calendar: the next process due in the same cycle */
    uint32_t *calendar;   /* per cycle mod 2^maxpv, the first process due then */
    uint32_t *stamp;      /* t + 1 while the process is in cycle t's due set */
    uint32_t *deferred;   /* places of a due set that is larger than perfect */
    uint32_t *first, *last, *runs; /* the trace's runs of each process */
    uint16_t *called;     /* one cycle of the trace */
};

static void fail(struct check_result *r, enum check_property p, const char *fmt, ...)
{
    r->failed[p]++;
    if (strcmp(r->first_failure, "none") == 0) {
        va_list ap;
        size_t used;
        snprintf(r->first_failure, sizeof r->first_failure, "%s: ", check_property_name[p]);
        used = strlen(r->first_failure);
        va_start(ap, fmt);
        vsnprintf(r->first_failure + used, sizeof r->first_failure - used, fmt, ap);
        va_end(ap);
    }
}

/* A trace that cannot be read on: stop there (nothing after it can be trusted). */
static int malformed(struct check_result *r, const char *why)
{
    r->malformed = 1;
    snprintf(r->first_failure, sizeof r->first_failure, "trace: %s", why);
    return 1;
}

static int read_exact(FILE *f, void *buf, size_t size)
{
    return size == 0u || fread(buf, 1, size, f) == size ? 0 : -1;
}

/* The low `bits` bits of x, last bit first (the paper's reverse()). */
static uint32_t reverse_low_bits(uint32_t x, uint32_t bits)
{
    uint32_t out = 0u, b;
    for (b = 0u; b < bits; b++) {
        out = (out << 1) | ((x >> b) & 1u);
    }
    return out;
}

/* The stable ascending sort by pv and Fig. 6's initial waits: for class pc = 1 ..
 * maxpv, start doubles with the slot count n_slots = 2^pc, member j of the class
 * (in input order) gets reverse((start + j) mod n_slots), then start moves on by
 * the class's size; class 0 runs every cycle and waits 0. */
static void plan_fig6(struct checker *c)
{
    uint32_t size[CHECK_MAX_PV + 1] = {0}, place[CHECK_MAX_PV + 1], start_of[CHECK_MAX_PV + 1] = {0};
    uint32_t seen[CHECK_MAX_PV + 1] = {0};
    uint32_t i, k, start = 0u, n_slots = 1u, before = 0u;

    for (i = 0u; i < c->n; i++) {
        size[c->pv[i]]++;
    }
    for (k = 0u; k <= CHECK_MAX_PV; k++) {
        place[k] = before;
        before += size[k];
    }
    for (k = 1u; k <= c->maxpv; k++) {
        start *= 2u;
        n_slots *= 2u;
        start_of[k] = start;
        start = (start + size[k]) % n_slots;
    }
    for (i = 0u; i < c->n; i++) {
        uint32_t pv = c->pv[i];
        uint32_t member = seen[pv]++;
        c->position[i] = place[pv] + member;
        c->by_position[place[pv] + member] = i;
        c->fig6_wait[i] = pv == 0u ? 0u : reverse_low_bits((start_of[pv] + member) % (1u << pv), pv);
    }
}

static void calendar_add(struct checker *c, uint32_t i, uint32_t due)
{
    uint32_t slot = due & c->mask;
    c->due[i] = due;
    c->next[i] = c->calendar[slot];
    c->calendar[slot] = i;
}

static int by_place(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

/* One cycle of Fig. 7 against the trace's `got` calls. Fig. 7 runs the processes
 * whose wait is 0 (due <= t) in sorted order, at most perfect of them, and
 * restarts their waits at 2^pv; a due process left over keeps its wait at 0 and
 * is due again in the next cycle. */
static void fig7_cycle(struct checker *c, uint32_t t, uint32_t got, struct check_result *r)
{
    uint32_t slot = t & c->mask;
    uint32_t i = c->calendar[slot], due_count = 0u, k;
    int same = 1;

    c->calendar[slot] = NO_PROCESS;
    for (; i != NO_PROCESS; i = c->next[i]) {
        c->stamp[i] = t + 1u;
        c->deferred[due_count++] = c->position[i];
    }
    if (due_count <= c->ceil_u) {
        /* Fig. 7 runs them all: the trace must be exactly this set, in ascending places. */
        uint32_t prev = 0u;
        same = got == due_count;
        for (k = 0u; same && k < got; k++) {
            uint32_t p = c->called[k];
            same = p < c->n && c->stamp[p] == t + 1u && (k == 0u || c->position[p] > prev);
            prev = p < c->n ? c->position[p] : 0u;
        }
        for (k = 0u; k < due_count; k++) {
            uint32_t p = c->by_position[c->deferred[k]];
            calendar_add(c, p, t + (1u << c->pv[p]));
        }
    } else {
        /* More are due than perfect: Fig. 7 takes the first perfect in sorted order. */
        qsort(c->deferred, due_count, sizeof c->deferred[0], by_place);
        same = got == c->ceil_u;
        for (k = 0u; k < due_count; k++) {
            uint32_t p = c->by_position[c->deferred[k]];
            if (k < c->ceil_u) {
                same = same && c->called[k] == p;
                calendar_add(c, p, t + (1u << c->pv[p]));
            } else {
                calendar_add(c, p, t + 1u);
            }
        }
    }
    if (!same) {
        fail(r, CHECK_FIG7, "cycle %lu: the trace runs %lu processes, Fig. 7 %lu%s", (unsigned long)t,
             (unsigned long)got, (unsigned long)(due_count < c->ceil_u ? due_count : c->ceil_u),
             got == due_count ? " (other processes or another order)" : "");
    }
}

/* The trace's runs of one cycle against the period of each process. */
static void period_cycle(struct checker *c, uint32_t t, uint32_t got, struct check_result *r)
{
    uint32_t k;
    for (k = 0u; k < got; k++) {
        uint32_t p = c->called[k];
        uint32_t period;
        if (p >= c->n) {
            fail(r, CHECK_PERIOD, "cycle %lu: process %lu does not exist (%lu processes)", (unsigned long)t,
                 (unsigned long)p, (unsigned long)c->n);
            continue;
        }
        period = 1u << c->pv[p];
        if (c->runs[p] == 0u) {
            if (t >= period) {
                fail(r, CHECK_PERIOD, "process %lu (pv %u) first runs in cycle %lu, not within its period %lu",
                     (unsigned long)p, (unsigned)c->pv[p], (unsigned long)t, (unsigned long)period);
            } else if (t != c->claimed[p]) {
                fail(r, CHECK_PERIOD, "process %lu (pv %u) first runs in cycle %lu, its initial wait is %lu",
                     (unsigned long)p, (unsigned)c->pv[p], (unsigned long)t, (unsigned long)c->claimed[p]);
            }
            c->first[p] = t;
        } else if (t - c->last[p] != period) {
            fail(r, CHECK_PERIOD, "process %lu (pv %u) runs in cycles %lu and %lu, %lu apart, not 2^pv = %lu",
                 (unsigned long)p, (unsigned)c->pv[p], (unsigned long)c->last[p], (unsigned long)t,
                 (unsigned long)(t - c->last[p]), (unsigned long)period);
        }
        c->last[p] = t;
        c->runs[p]++;
    }
}

static void period_end(struct checker *c, struct check_result *r)
{
    uint32_t i;
    for (i = 0u; i < c->n; i++) {
        uint32_t period = 1u << c->pv[i];
        uint32_t expected = c->cycles >> c->pv[i];
        if (c->runs[i] != expected) {
            fail(r, CHECK_PERIOD, "process %lu (pv %u) runs %lu times in the major cycle, not 2^(maxpv - pv) = %lu",
                 (unsigned long)i, (unsigned)c->pv[i], (unsigned long)c->runs[i], (unsigned long)expected);
        } else if (c->first[i] + c->cycles - c->last[i] != period) {
            fail(r, CHECK_PERIOD, "process %lu (pv %u): %lu cycles from its last run to its first in the next "
                 "major cycle, not %lu", (unsigned long)i, (unsigned)c->pv[i],
                 (unsigned long)(c->first[i] + c->cycles - c->last[i]), (unsigned long)period);
        }
    }
}

/* The balance theorem's load of cycle t: the points rev_M(t), rev_M(t) + 2^M, ...
 * below A. */
static uint32_t theorem_load(const struct checker *c, uint32_t t)
{
    uint64_t point = reverse_low_bits(t, c->maxpv);
    return c->area > point ? (uint32_t)((c->area - point + c->cycles - 1u) / c->cycles) : 0u;
}

static void balance_end(const struct checker *c, struct check_result *r)
{
    /* cycles is 2^maxpv, set once; the static analyser cannot see it is never 0. */
    if (c->cycles == 0u) {
        fail(r, CHECK_BALANCE, "a major cycle of 0 cycles");
        return;
    }
    uint64_t rest = c->area % c->cycles;
    unsigned long at_ceil = rest != 0u ? (unsigned long)rest : (unsigned long)c->cycles;
    if (r->lowest_load < c->floor_u || r->highest_load > c->ceil_u) {
        fail(r, CHECK_BALANCE, "loads %lu..%lu, outside floor(U)..ceil(U) = %lu..%lu", r->lowest_load,
             r->highest_load, (unsigned long)c->floor_u, (unsigned long)c->ceil_u);
    } else if (r->highest_load == c->ceil_u && r->cycles_at_highest != at_ceil) {
        fail(r, CHECK_BALANCE, "%lu cycles at ceil(U) = %lu, not %lu", r->cycles_at_highest,
             (unsigned long)c->ceil_u, at_ceil);
    } else if (r->highest_load != c->ceil_u) {
        fail(r, CHECK_BALANCE, "no cycle at ceil(U) = %lu", (unsigned long)c->ceil_u);
    }
}

static int read_header(FILE *f, struct checker *c, struct check_result *r)
{
    char magic[8];
    int32_t status;
    uint32_t count, maxpv, perfect, i, wait;
    uint8_t pv;

    if (read_exact(f, magic, sizeof magic) != 0 || memcmp(magic, CHECK_TRACE_MAGIC, sizeof magic) != 0) {
        return malformed(r, "no trace header (the library run wrote no trace)");
    }
    if (read_exact(f, &status, sizeof status) != 0 || read_exact(f, &count, sizeof count) != 0 ||
        read_exact(f, &maxpv, sizeof maxpv) != 0 || read_exact(f, &perfect, sizeof perfect) != 0) {
        return malformed(r, "the header ends early");
    }
    if (status != 0) {
        fail(r, CHECK_PLAN, "bsched_init returned %ld, not BSCHED_OK", (long)status);
        return 1;
    }
    if (count != c->n || maxpv != c->maxpv) {
        fail(r, CHECK_PLAN, "the library planned %lu processes with maxpv %lu, not %lu with maxpv %lu",
             (unsigned long)count, (unsigned long)maxpv, (unsigned long)c->n, (unsigned long)c->maxpv);
        return 1;
    }
    if (perfect != c->ceil_u) {
        fail(r, CHECK_PLAN, "the library's perfect is %lu, not ceil(U) = %lu", (unsigned long)perfect,
             (unsigned long)c->ceil_u);
    }
    for (i = 0u; i < count; i++) {
        if (read_exact(f, &pv, 1u) != 0) {
            return malformed(r, "the header ends early");
        }
        if (pv != c->pv[i]) {
            fail(r, CHECK_PLAN, "the library holds pv %u for process %lu, the set %u", (unsigned)pv,
                 (unsigned long)i, (unsigned)c->pv[i]);
            return 1;
        }
    }
    for (i = 0u; i < count; i++) {
        if (read_exact(f, &wait, sizeof wait) != 0) {
            return malformed(r, "the header ends early");
        }
        c->claimed[i] = wait;
        if (wait != c->fig6_wait[i]) {
            fail(r, CHECK_PLAN, "process %lu (pv %u): the library's initial wait is %lu, Fig. 6's %lu",
                 (unsigned long)i, (unsigned)c->pv[i], (unsigned long)wait, (unsigned long)c->fig6_wait[i]);
        }
    }
    return 0;
}

static int run_checks(FILE *f, struct checker *c, struct check_result *r)
{
    uint32_t t, i, cycle_after, reversed_after;
    char magic[8];

    if (read_header(f, c, r) != 0) {
        return 1;
    }
    for (i = 0u; i < c->n; i++) {
        calendar_add(c, i, c->fig6_wait[i]);
    }
    r->lowest_load = ULONG_MAX;
    for (t = 0u; t < c->cycles; t++) {
        int32_t returned;
        uint32_t got, expected;
        if (read_exact(f, &returned, sizeof returned) != 0 || read_exact(f, &got, sizeof got) != 0) {
            return malformed(r, "it ends before the major cycle does");
        }
        if (got > c->n) {
            return malformed(r, "a cycle calls more processes than the set has");
        }
        if (read_exact(f, c->called, (size_t)got * sizeof c->called[0]) != 0) {
            return malformed(r, "it ends before the major cycle does");
        }
        if (returned < 0 || (uint32_t)returned != got) {
            fail(r, CHECK_FIG7, "cycle %lu: bsched_run_cycle returned %ld but called %lu processes",
                 (unsigned long)t, (long)returned, (unsigned long)got);
        }
        r->executions += got;
        expected = theorem_load(c, t);
        if (got != expected) {
            fail(r, CHECK_BALANCE, "cycle %lu runs %lu processes, the balance theorem's count is %lu",
                 (unsigned long)t, (unsigned long)got, (unsigned long)expected);
        }
        if (got < r->lowest_load) {
            r->lowest_load = got;
        }
        if (got > r->highest_load) {
            r->highest_load = got;
            r->cycles_at_highest = 0u;
        }
        if (got == r->highest_load) {
            r->cycles_at_highest++;
        }
        period_cycle(c, t, got, r);
        fig7_cycle(c, t, got, r);
    }
    if (read_exact(f, &cycle_after, sizeof cycle_after) != 0 ||
        read_exact(f, &reversed_after, sizeof reversed_after) != 0 || read_exact(f, magic, sizeof magic) != 0 ||
        memcmp(magic, CHECK_TRACE_END, sizeof magic) != 0) {
        return malformed(r, "no end after the major cycle");
    }
    if (fgetc(f) != EOF) {
        return malformed(r, "more after its end");
    }
    if (cycle_after != 0u || reversed_after != 0u) {
        fail(r, CHECK_REPEAT, "the library ends the major cycle at cycle %lu (reversed %lu), not 0",
             (unsigned long)cycle_after, (unsigned long)reversed_after);
    }
    for (i = 0u; i < c->n; i++) {
        if (c->due[i] != c->fig6_wait[i] + c->cycles) {
            fail(r, CHECK_REPEAT, "Fig. 7's wait of process %lu after the major cycle is not its initial wait",
                 (unsigned long)i);
        }
    }
    period_end(c, r);
    balance_end(c, r);
    return 0;
}

int check_trace(FILE *trace, const uint8_t *pv, size_t count, struct check_result *r)
{
    struct checker c;
    uint32_t i;
    int rc = -1;

    memset(r, 0, sizeof *r);
    snprintf(r->first_failure, sizeof r->first_failure, "none");
    if (count == 0u || count > CHECK_MAX_PROCS) {
        return -1;
    }
    memset(&c, 0, sizeof c);
    c.pv = pv;
    c.n = (uint32_t)count;
    for (i = 0u; i < c.n; i++) {
        if (pv[i] > CHECK_MAX_PV) {
            return -1;
        }
        c.maxpv = pv[i] > c.maxpv ? pv[i] : c.maxpv;
    }
    c.cycles = 1u << c.maxpv;
    c.mask = c.cycles - 1u;
    for (i = 0u; i < c.n; i++) {
        c.area += (uint64_t)(c.cycles >> pv[i]);
    }
    c.floor_u = (uint32_t)(c.area / c.cycles);
    c.ceil_u = (uint32_t)((c.area + c.cycles - 1u) / c.cycles);
    r->cycles = c.cycles;
    c.position = malloc(count * sizeof *c.position);
    c.by_position = malloc(count * sizeof *c.by_position);
    c.fig6_wait = malloc(count * sizeof *c.fig6_wait);
    c.claimed = malloc(count * sizeof *c.claimed);
    c.due = malloc(count * sizeof *c.due);
    c.next = malloc(count * sizeof *c.next);
    c.stamp = calloc(count, sizeof *c.stamp);
    c.deferred = malloc(count * sizeof *c.deferred);
    c.first = calloc(count, sizeof *c.first);
    c.last = calloc(count, sizeof *c.last);
    c.runs = calloc(count, sizeof *c.runs);
    c.called = malloc(count * sizeof *c.called);
    c.calendar = malloc((size_t)c.cycles * sizeof *c.calendar);
    if (c.position != NULL && c.by_position != NULL && c.fig6_wait != NULL && c.claimed != NULL && c.due != NULL && c.next != NULL &&
        c.stamp != NULL && c.deferred != NULL && c.first != NULL && c.last != NULL && c.runs != NULL &&
        c.called != NULL && c.calendar != NULL) {
        for (i = 0u; i < c.cycles; i++) {
            c.calendar[i] = NO_PROCESS;
        }
        plan_fig6(&c);
        (void)run_checks(trace, &c, r);
        rc = 0;
        for (i = 0u; i < CHECK_COUNT; i++) {
            rc |= r->failed[i] != 0u;
        }
        rc |= r->malformed;
    }
    free(c.position);
    free(c.by_position);
    free(c.fig6_wait);
    free(c.claimed);
    free(c.due);
    free(c.next);
    free(c.stamp);
    free(c.deferred);
    free(c.first);
    free(c.last);
    free(c.runs);
    free(c.called);
    free(c.calendar);
    return rc;
}
