/*
 * CBMC harness `step`: the inductive step of periodicity, for an arbitrary
 * minor cycle t of an arbitrary priority set, without simulating the cycles
 * before t.
 *
 * The state is any state the periodicity invariant allows at the start of
 * cycle t, for ascending input (one input order per multiset, so order[] is
 * the identity):
 *     offset_i = any w_i < 2^pv_i,   wait_i = (w_i - t) mod 2^pv_i,
 *     cycle = t < 2^maxpv,   perfect = any value in 1..n that is at least the
 *     number of processes due at t, #{i : t = w_i mod 2^pv_i}.
 * The last condition is what the balance theorem provides: `balance` checks
 * that with the offsets bsched_init computes (the closed form, checked by
 * `init`) at most ceil(U) processes are due in every cycle, and `init` that
 * perfect = ceil(U). So `init` (the invariant at t = 0), `balance` and `step`
 * together cover every cycle of every major cycle, at the same bounds.
 * Everything here holds for any offsets, so the closed form is not needed.
 *
 * Checks:
 *   - bsched_step runs exactly the due processes (the `perfect` cap never
 *     defers one), in execution order, and returns their number;
 *   - afterwards the state is the invariant's state for t + 1 (cycle wraps at
 *     2^maxpv), and nothing else in the state changed.
 */
#include "proof_model.h"

void harness(void)
{
    static struct bsched s;
    struct proof_set set;
    uint32_t due[BSCHED_MAX_PROCS];
    uint32_t offset[BSCHED_MAX_PROCS];
    uint32_t due_count = 0u;
    uint32_t listed = 0u;
    uint32_t perfect;
    uint32_t t;
    uint32_t next;
    uint32_t i;
    int32_t rc;

    proof_nondet_set(&set);

    t = nondet_uint32();
    __CPROVER_assume((t >> set.maxpv) == 0u); /* t < 2^maxpv */
    next = (t + 1u) & proof_mask(set.maxpv);
    perfect = nondet_uint32();
    __CPROVER_assume(perfect >= 1u && perfect <= set.n);

    /* The state at the start of cycle t. ran[] and ran_count hold anything (the
     * last cycle's record): bsched_step must not depend on them. */
    s.ran_count = nondet_uint16();
    s.count = (uint16_t)set.n;
    s.maxpv = (uint8_t)set.maxpv;
    s.perfect = (uint16_t)perfect;
    s.cycle = t;
    /* Entries at and after n are filled too (the library never reads them):
     * then order[id] = id is a constant for CBMC, and so are the indices
     * bsched_step derives from it. */
    for (i = 0u; i < PROOF_N; i++) {
        uint32_t w = nondet_uint32();
        __CPROVER_assume((w >> set.pv[i]) == 0u); /* w < 2^pv */
        s.pv[i] = set.pv[i];
        s.order[i] = (uint16_t)i;
        s.offset[i] = w;
        offset[i] = w;
        s.wait[i] = proof_wait_at(w, set.pv[i], t);
        s.ran[i] = nondet_uint16();
        due[i] = i < set.n ? (uint32_t)proof_due_at(w, set.pv[i], t) : 0u;
        due_count += due[i];
    }
    /* What `balance` shows for the offsets of bsched_init, with perfect = ceil(U). */
    __CPROVER_assume(due_count <= perfect);

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
    __CPROVER_assert(s.count == set.n && s.maxpv == set.maxpv && s.perfect == perfect,
                     "step: count, maxpv, perfect unchanged");
}
