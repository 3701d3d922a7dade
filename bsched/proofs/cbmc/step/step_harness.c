/*
 * CBMC harness `step`: the inductive step of periodicity and the balance
 * theorem, for an arbitrary minor cycle t of an arbitrary priority set, without
 * simulating the cycles before t.
 *
 * The state is built from the specification, not by running bsched_init: for
 * ascending input (one input order per multiset, so order[] is the identity),
 * each process gets the offset of the hand proof's closed form
 * (proof_interval_offset), and at the start of cycle t the periodicity
 * invariant gives every wait:
 *     wait_i = (w_i - t) mod 2^pv_i,   cycle = t,   0 <= t < 2^maxpv.
 * The `init` harness checks that bsched_init produces exactly these offsets
 * (and waits = offsets, cycle = 0: the invariant at t = 0) for every input
 * order, so `init` + `step` together cover every cycle of every major cycle.
 *
 * Checks:
 *   - balance: the number of processes due at t, #{i : t = w_i mod 2^pv_i},
 *     is floor(U) or ceil(U) -- for every t at once, t being nondeterministic;
 *   - bsched_step runs exactly the due processes (the `perfect` cap never
 *     defers one), in execution order, and returns their number;
 *   - afterwards the state is the invariant's state for t + 1 (cycle wraps at
 *     2^maxpv), and nothing else in the state changed.
 *
 * With -DPROOF_STATE_FROM_INIT=1 the offsets come from bsched_init instead of
 * the closed form (slower: init is then part of the formula). The negative
 * check uses it with the unbalanced mutant of bsched.c, to show the balance
 * assertions can fail.
 */
#include "proof_model.h"

#ifndef PROOF_STATE_FROM_INIT
#define PROOF_STATE_FROM_INIT 0
#endif

void harness(void)
{
    static struct bsched s;
    struct proof_set set;
    uint32_t due[BSCHED_MAX_PROCS];
    uint32_t offset[BSCHED_MAX_PROCS];
    uint32_t before = 0u;
    uint32_t due_count = 0u;
    uint32_t listed = 0u;
    uint32_t t;
    uint32_t next;
    uint32_t i;
    int32_t rc;

    proof_nondet_set(&set);

    t = nondet_uint32();
    __CPROVER_assume((t >> set.maxpv) == 0u); /* t < 2^maxpv */
    next = (t + 1u) & proof_mask(set.maxpv);

#if PROOF_STATE_FROM_INIT
    rc = bsched_init(&s, set.pv, (size_t)set.n);
    __CPROVER_assert(rc == BSCHED_OK, "step: a valid set is accepted");
#endif
    /* The state at the start of cycle t. ran[] and ran_count keep whatever they
     * held: bsched_step must not depend on them. */
    s.count = (uint16_t)set.n;
    s.maxpv = (uint8_t)set.maxpv;
    s.perfect = (uint16_t)set.load_hi;
    s.cycle = t;
    for (i = 0u; i < PROOF_N; i++) {
        if (i < set.n) {
#if PROOF_STATE_FROM_INIT
            uint32_t w = s.offset[i];
#else
            uint32_t w = proof_interval_offset(before, set.pv[i]);
#endif
            before += PROOF_UNIT >> set.pv[i];
            s.pv[i] = set.pv[i];
            s.order[i] = (uint16_t)i;
            s.offset[i] = w;
            offset[i] = w;
            s.wait[i] = proof_wait_at(w, set.pv[i], t);
            due[i] = (uint32_t)proof_due_at(w, set.pv[i], t);
            due_count += due[i];
        }
    }

    __CPROVER_assert(due_count >= set.load_lo, "balance: at least floor(U) processes due in every cycle");
    __CPROVER_assert(due_count <= set.load_hi, "balance: at most ceil(U) processes due in every cycle");

    rc = bsched_step(&s);

    __CPROVER_assert(rc >= 0 && (uint32_t)rc == due_count, "step: runs every due process (the cap never defers one)");
    __CPROVER_assert(s.ran_count == due_count, "step: ran_count is the number run");
    for (i = 0u; i < PROOF_N; i++) {
        if (i < set.n) {
            if (due[i] != 0u) {
                /* order[] is the identity: due processes in index order */
                __CPROVER_assert(listed < due_count && s.ran[listed] == i, "step: ran[] lists the due processes in execution order");
                listed++;
            }
            __CPROVER_assert(s.wait[i] == proof_wait_at(offset[i], set.pv[i], next),
                             "periodicity: the waits after the step are the invariant's waits for t + 1");
            __CPROVER_assert(s.pv[i] == set.pv[i] && s.order[i] == i && s.offset[i] == offset[i],
                             "step: pv, order and offsets unchanged");
        }
    }
    __CPROVER_assert(s.cycle == next, "step: cycle advances to t + 1 mod 2^maxpv");
    __CPROVER_assert(s.count == set.n && s.maxpv == set.maxpv && s.perfect == set.load_hi,
                     "step: count, maxpv, perfect unchanged");
}
