/*
 * CBMC harness `step`: one minor cycle of bsched_step, for an arbitrary minor
 * cycle t of an arbitrary priority set, without simulating the cycles before t.
 *
 * The state is the one bsched_init leaves for the set (ascending input, one
 * input order per multiset, so order[] is the identity), advanced to cycle t,
 * built from the hand proof rather than by bsched.c (proof_plan_at,
 * include/proof_plan.h):
 *     offset_i = rev_P(A_i mod 2^P) mod 2^pv_i, A_i 2^P = sum of 2^(P - pv_j), j < i
 *         (the closed form that `init` checks bsched_init computes),
 *     class k: first = #{i : pv_i < k}, size = #{i : pv_i == k},
 *         lead = 2^k - (B_k mod 2^k), B_k = A 2^k at the class's first member;
 *         the entries of empty classes hold anything (lead at most 2^k),
 *     cycle = t < 2^maxpv (any), reversed = rev_maxpv(t), perfect = ceil(U),
 *     ran[] and ran_count anything (the last cycle's record).
 *
 * Checks:
 *   - with -DPROOF_STEP_WAIT=1 (run `step-wait`): bsched_wait(i) is Fig. 7's
 *     wait (offset_i - t) mod 2^pv_i;
 *   - bsched_step runs exactly the processes due at t (t = offset mod 2^pv), in
 *     execution order, and returns their number, at most perfect;
 *   - afterwards cycle = t + 1 mod 2^maxpv, reversed = rev_maxpv(cycle), and
 *     nothing else in the state changed.
 * With `init` (bsched_init yields this state at t = 0) this covers every cycle
 * of every major cycle at the same bounds.
 */
#include "proof_plan.h"

/* PROOF_STEP_WAIT=1: also check bsched_wait for every process (a divider per
 * process for the SAT back end: a run of its own at smaller bounds). */
#ifndef PROOF_STEP_WAIT
#define PROOF_STEP_WAIT 0
#endif

void harness(void)
{
    static struct bsched s;
    static struct bsched before;
    struct proof_set set;
    uint32_t due[BSCHED_MAX_PROCS];
    uint32_t due_count = 0u;
    uint32_t listed = 0u;
    uint32_t t;
    uint32_t next;
    uint32_t i;
    int32_t rc;

    t = proof_plan_at_any_cycle(&s, &set);
    next = (t + 1u) & proof_mask(set.maxpv);

    for (i = 0u; i < PROOF_N; i++) {
        due[i] = i < set.n ? (uint32_t)proof_due_at(s.offset[i], set.pv[i], t) : 0u;
        due_count += due[i];
#if PROOF_STEP_WAIT
        if (i < set.n) {
            __CPROVER_assert(bsched_wait(&s, (uint16_t)i) == (int32_t)proof_wait_at(s.offset[i], set.pv[i], t),
                             "wait: bsched_wait is Fig. 7's wait (offset - t) mod 2^pv");
        }
#endif
    }
    before = s;

    rc = bsched_step(&s);

    __CPROVER_assert(rc >= 0 && (uint32_t)rc == due_count, "step: runs every due process and only those");
    __CPROVER_assert(rc >= 0 && (uint32_t)rc <= set.load_hi, "step: at most perfect = ceil(U) processes");
    __CPROVER_assert(s.ran_count == due_count, "step: ran_count is the number run");
    for (i = 0u; i < PROOF_N; i++) {
        if (due[i] != 0u) {
            /* order[] is the identity: due processes in index order */
            __CPROVER_assert(listed < due_count && s.ran[listed] == i,
                             "step: ran[] lists the due processes in execution order");
            listed++;
        }
        __CPROVER_assert(s.pv[i] == before.pv[i] && s.order[i] == before.order[i] &&
                         s.offset[i] == before.offset[i], "step: pv, order and offsets unchanged");
    }
    __CPROVER_assert(s.cycle == next, "step: cycle advances to t + 1 mod 2^maxpv");
    __CPROVER_assert(proof_plan_next_ok(&s, &before, next),
                     "step: the reversed counter is rev_maxpv of the next cycle; class table, count, maxpv, minpv, perfect unchanged");
}
