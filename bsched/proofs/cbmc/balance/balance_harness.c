/*
 * CBMC harness `balance`: the balance theorem for the hand proof's closed-form
 * offsets, for every ascending priority set within the bounds and every minor
 * cycle t < 2^maxpv at once (t is nondeterministic). No library code runs here
 * (unless PROOF_STATE_FROM_INIT): `init` checks that bsched_init produces these
 * offsets, `step` that bsched_step runs exactly the due processes.
 *
 * Checks: #{i : t = w_i (mod 2^pv_i)} is floor(U) or ceil(U), U = sum 2^-pv_i,
 * where w_i = rev_P(A_i mod 2^P) mod 2^pv_i and A_i 2^P = sum of 2^(P-pv_j)
 * over j < i (the start of process i's interval, Lemmas 1 and 2).
 *
 * Counting is hard for a SAT solver, so the harness walks the hand proof's
 * argument as checked lemmas (PROOF_LEMMA: asserted, then assumed). With
 * x = rev_P(t), process i is due at t iff its interval [A_i, A_i + 2^-pv_i),
 * read on the circle of circumference 1, contains x 2^-P; unrolled, the
 * intervals tile [0, U) and the points x + m 2^P (m >= 0) are the laps, so
 * after i processes the number due is the number of laps below the end of
 * interval i. After all n: laps below U 2^P, which is floor(U) or ceil(U).
 * Each lemma is local (one process, its neighbour's facts assumed).
 *
 * With -DPROOF_STATE_FROM_INIT=1 the offsets come from bsched_init and no lemma
 * is used: the plain counting, affordable at small bounds. The negative check
 * runs it on the unbalanced mutant, where the balance assertions must fail.
 */
#include "proof_model.h"

#ifndef PROOF_STATE_FROM_INIT
#define PROOF_STATE_FROM_INIT 0
#endif

#if !PROOF_SORTED_INPUT
#error "balance: the closed form is stated for ascending input (PROOF_SORTED_INPUT=1)"
#endif

void harness(void)
{
    struct proof_set set;
    uint32_t before = 0u; /* A_i 2^P */
    uint32_t due_count = 0u;
    uint32_t t;
    uint32_t x;
    uint32_t i;
#if PROOF_STATE_FROM_INIT
    static struct bsched s;
    int32_t rc;
#endif

    proof_nondet_set(&set);
    t = nondet_uint32();
    __CPROVER_assume((t >> set.maxpv) == 0u); /* t < 2^maxpv <= 2^P */
    x = proof_reverse_p(t);

#if PROOF_STATE_FROM_INIT
    rc = bsched_init(&s, set.pv, (size_t)set.n);
    __CPROVER_assert(rc == BSCHED_OK, "balance: a valid set is accepted");
#endif

    for (i = 0u; i < PROOF_N; i++) {
        if (i < set.n) {
            uint32_t k = set.pv[i];
            uint32_t len = PROOF_UNIT >> k;
#if PROOF_STATE_FROM_INIT
            uint32_t w = s.offset[i];
#else
            uint32_t w = proof_interval_offset(before, k);
#endif
            uint32_t due = (uint32_t)proof_due_at(w, k, t);
#if !PROOF_STATE_FROM_INIT
            uint32_t start = before & (PROOF_UNIT - 1u); /* the interval's start on the circle */
            PROOF_LEMMA((start & (len - 1u)) == 0u,
                        "balance lemma: each interval starts at a multiple of its length");
            PROOF_LEMMA(due == ((start <= x && x - start < len) ? 1u : 0u),
                        "balance lemma: a process is due at t iff its interval holds the point rev_P(t)");
#endif
            due_count += due;
#if !PROOF_STATE_FROM_INIT
            PROOF_LEMMA(due_count == proof_laps_below(before + len, x),
                        "balance lemma: the processes due so far are the laps below the end of their intervals");
#endif
            before += len;
        }
    }
    __CPROVER_assert(before == set.area, "balance: the intervals tile [0, U)");
    __CPROVER_assert(due_count >= set.load_lo, "balance: at least floor(U) processes due in every cycle");
    __CPROVER_assert(due_count <= set.load_hi, "balance: at most ceil(U) processes due in every cycle");
}
