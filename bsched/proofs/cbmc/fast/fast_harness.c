/*
 * CBMC harness `fast`: bsched_fast_step (O(classes + due), bsched/fast/) gives
 * exactly the results of Fig. 7's bsched_step, cycle by cycle, for an arbitrary
 * minor cycle t of an arbitrary priority set, by induction over the cycles.
 *
 * The state is the state of the periodicity invariant at the start of cycle t
 * (as in `step`), with the offsets bsched_init computes (the closed form, as in
 * `balance`; `init` checks that bsched_init yields them): for ascending input
 *     offset_i = rev_P(A_i mod 2^P) mod 2^pv_i,   A_i 2^P = sum_{j<i} 2^(P-pv_j),
 *     wait_i = (offset_i - t) mod 2^pv_i,   cycle = t,   perfect = ceil(U).
 * The class table is bsched_fast_init's, built at cycle t; or, for the inductive
 * step, any table that matches it except for its bit-reversed counter, which is
 * then any value when the table's cycle differs from t (the resynchronising path)
 * and rev_maxpv(t) when it equals t (the path every cycle after the first takes).
 *
 * Checks, on copies of the same state:
 *   - bsched_fast_step and bsched_step return the same value and leave the same
 *     ran_count, ran[0 .. ran_count-1] and cycle, and nothing else of the state
 *     differs except Fig. 7's wait[];
 *   - afterwards the table's counter is rev_maxpv(t + 1) for cycle t + 1, so the
 *     next cycle starts from the same kind of table (the induction);
 *   - with -DPROOF_FAST_DUE=1 (run `fast-due`, instead of the step):
 *     bsched_fast_due(ahead) == bsched_due(ahead) for any ahead, and
 *     bsched_wait(i) == wait[i] for every process.
 */
#include "proof_model.h"
#include "bsched_fast.h"

#ifndef PROOF_FAST_DUE
#define PROOF_FAST_DUE 0
#endif

#if !PROOF_SORTED_INPUT
#error "fast: the closed form is stated for ascending input (PROOF_SORTED_INPUT=1)"
#endif

static uint32_t reverse_maxpv(uint32_t x, uint32_t maxpv)
{
    return proof_reverse_p(x) >> (PROOF_P - maxpv);
}

void harness(void)
{
    static struct bsched fig7;
    static struct bsched fast;
    static struct bsched_fast table;
    static uint16_t due_fig7[BSCHED_MAX_PROCS];
    static uint16_t due_fast[BSCHED_MAX_PROCS];
    struct proof_set set;
    uint32_t before = 0u;
#if PROOF_FAST_DUE
    uint32_t ahead;
#endif
    uint32_t t;
    uint32_t i;
    int32_t rc;
    int32_t rc_fast;

    proof_nondet_set(&set);
    t = nondet_uint32();
    __CPROVER_assume((t >> set.maxpv) == 0u); /* t < 2^maxpv */

    fig7.count = (uint16_t)set.n;
    fig7.maxpv = (uint8_t)set.maxpv;
    fig7.perfect = (uint16_t)set.load_hi;
    fig7.cycle = t;
    fig7.ran_count = nondet_uint16();
    for (i = 0u; i < PROOF_N; i++) {
        uint32_t w = proof_interval_offset(before, set.pv[i]);
        fig7.pv[i] = set.pv[i];
        fig7.order[i] = (uint16_t)i;
        fig7.offset[i] = w;
        fig7.wait[i] = proof_wait_at(w, set.pv[i], t);
        fig7.ran[i] = nondet_uint16();
        if (i < set.n) {
            before += PROOF_UNIT >> set.pv[i];
        }
    }
    fast = fig7;

    rc = bsched_fast_init(&table, &fast);
    __CPROVER_assert(rc == BSCHED_OK, "fast: the table is built for a planned state");
    __CPROVER_assert(table.cycle == t && table.reversed == reverse_maxpv(t, set.maxpv),
                     "fast: the table's counter is rev_maxpv(t)");
    /* The inductive step: the counter carried over from the last cycle, or any
     * counter with a cycle that tells it is stale. */
    table.cycle = nondet_uint32();
    table.reversed = nondet_uint32();
    __CPROVER_assume(table.cycle != t || table.reversed == reverse_maxpv(t, set.maxpv));

#if PROOF_FAST_DUE
    for (i = 0u; i < PROOF_N; i++) {
        if (i < set.n) {
            __CPROVER_assert(bsched_wait(&fast, (uint16_t)i) == (int32_t)fig7.wait[i],
                             "fast: bsched_wait is Fig. 7's wait");
        }
    }
    ahead = nondet_uint32();
    rc = bsched_due(&fig7, ahead, due_fig7);
    rc_fast = bsched_fast_due(&fast, &table, ahead, due_fast);
    __CPROVER_assert(rc >= 0 && rc == rc_fast, "fast: bsched_fast_due returns what bsched_due returns");
    for (i = 0u; i < PROOF_N; i++) {
        if ((int32_t)i < rc) {
            __CPROVER_assert(due_fig7[i] == due_fast[i], "fast: bsched_fast_due lists what bsched_due lists");
        }
    }
    return;
#endif

    rc = bsched_step(&fig7);
    rc_fast = bsched_fast_step(&fast, &table);
    __CPROVER_assert(rc >= 0 && rc == rc_fast, "fast: same return value as Fig. 7");
    __CPROVER_assert(fast.ran_count == fig7.ran_count, "fast: same ran_count as Fig. 7");
    __CPROVER_assert(fast.cycle == fig7.cycle, "fast: same next cycle as Fig. 7");
    for (i = 0u; i < PROOF_N; i++) {
        if (i < fig7.ran_count) {
            __CPROVER_assert(fast.ran[i] == fig7.ran[i], "fast: same processes in the same order as Fig. 7");
        }
        __CPROVER_assert(fast.pv[i] == fig7.pv[i] && fast.order[i] == fig7.order[i] &&
                         fast.offset[i] == fig7.offset[i], "fast: pv, order, offsets unchanged");
    }
    __CPROVER_assert(fast.count == fig7.count && fast.maxpv == fig7.maxpv && fast.perfect == fig7.perfect,
                     "fast: count, maxpv, perfect unchanged");
    __CPROVER_assert(table.cycle == fast.cycle && table.reversed == reverse_maxpv(fast.cycle, set.maxpv),
                     "fast: the counter is rev_maxpv(t + 1) for the next cycle");
}
