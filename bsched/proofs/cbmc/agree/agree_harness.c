/*
 * CBMC harness `agree`: the library's bsched_step and Fig. 7's reference
 * engine (bsched/proofs/ref/bsched_fig7.c) agree cycle by cycle, for an arbitrary
 * minor cycle t of an arbitrary priority set, without simulating the cycles
 * before t.
 *
 * The plan is the state bsched_init leaves for the set (ascending input, one
 * input order per multiset, so order[] is the identity), advanced to cycle t:
 * proof_plan_at (include/proof_plan.h) builds it from the hand proof, with
 * the reversed counter set for t. Fig. 7's state is in phase at t:
 *     r.cycle = t,   r.wait_i = (offset_i - t) mod 2^pv_i,
 *     r.ran[], r.ran_count anything (the last cycle's record).
 * Checks, after one bsched_fig7_step(&r, &plan) and one bsched_step(&plan):
 *   - the same return value, the same ran_count, the same ran[] entries in
 *     the same order, the same next cycle (t + 1 mod 2^maxpv);
 *   - both states are again the states of this construction for t + 1:
 *     Fig. 7's waits are (offset_i - (t + 1)) mod 2^pv_i, the plan's reversed
 *     counter is rev_maxpv(t + 1), and nothing else of the plan changed.
 * So, by induction over the cycles from bsched_init (t = 0, where `init`
 * checks bsched_init yields this plan and bsched_fig7_start these waits), the
 * two run the same processes in the same order in every minor cycle.
 */
#include "proof_plan.h"
#include "bsched_fig7.h"

void harness(void)
{
    static struct bsched s;
    static struct bsched before;
    static struct bsched_fig7 r;
    struct proof_set set;
    uint32_t t;
    uint32_t next;
    uint32_t due[BSCHED_MAX_PROCS];
    uint32_t due_count = 0u;
    uint32_t listed;
    uint32_t i;
    int32_t rc7;
    int32_t rc;

    t = proof_plan_at_any_cycle(&s, &set);
    next = (t + 1u) & proof_mask(set.maxpv);

    r.cycle = (int32_t)t;
    r.ran_count = nondet_uint16();
    for (i = 0u; i < PROOF_N; i++) {
        r.wait[i] = proof_wait_at(s.offset[i], set.pv[i], t);
        r.ran[i] = nondet_uint16();
    }
    before = s;

    for (i = 0u; i < PROOF_N; i++) {
        due[i] = i < set.n ? (uint32_t)proof_due_at(s.offset[i], set.pv[i], t) : 0u;
        due_count += due[i];
    }

    /* Each engine against the closed form first, as checked lemmas (asserted,
     * then assumed; include/proof_model.h): order[] is the identity, so both
     * must list the due processes in index order. The agreement below then
     * follows from the two, which keeps each SAT question local. */
    rc7 = bsched_fig7_step(&r, &s);
    PROOF_LEMMA(rc7 >= 0 && (uint32_t)rc7 == due_count, "fig7: runs exactly the due processes");
    for (i = 0u, listed = 0u; i < PROOF_N; i++) {
        if (due[i] != 0u) {
            PROOF_LEMMA(listed < due_count && r.ran[listed] == i, "fig7: ran[] lists them in execution order");
            listed++;
        }
    }
    rc = bsched_step(&s);
    PROOF_LEMMA(rc >= 0 && (uint32_t)rc == due_count, "step: runs exactly the due processes");
    for (i = 0u, listed = 0u; i < PROOF_N; i++) {
        if (due[i] != 0u) {
            PROOF_LEMMA(listed < due_count && s.ran[listed] == i, "step: ran[] lists them in execution order");
            listed++;
        }
    }

    __CPROVER_assert(rc >= 0 && rc == rc7, "agree: the same return value");
    __CPROVER_assert(s.ran_count == r.ran_count, "agree: the same ran_count");
    for (i = 0u; i < PROOF_N; i++) {
        if (rc >= 0 && i < (uint32_t)rc) {
            __CPROVER_assert(s.ran[i] == r.ran[i], "agree: the same processes in the same order");
        }
        if (i < set.n) {
            __CPROVER_assert(r.wait[i] == proof_wait_at(before.offset[i], set.pv[i], next),
                             "next: Fig. 7's waits are in phase for t + 1");
        }
        __CPROVER_assert(s.pv[i] == before.pv[i] && s.order[i] == before.order[i] &&
                         s.offset[i] == before.offset[i], "next: pv, order and offsets unchanged");
    }
    __CPROVER_assert(s.cycle == next && r.cycle >= 0 && (uint32_t)r.cycle == next, "agree: the same next cycle, t + 1 mod 2^maxpv");
    __CPROVER_assert(proof_plan_next_ok(&s, &before, next),
                     "next: the plan is this construction's plan for t + 1");
}
