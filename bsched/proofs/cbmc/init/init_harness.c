/*
 * CBMC harness `init`: bsched_init on every priority set within the bounds
 * (n in 1..N processes, each pv in 0..P, in every input order).
 *
 * Checks, besides memory safety and the absence of undefined behaviour
 * (property flags in ../Makefile.common):
 *   - it succeeds and fills count, maxpv, pv[], cycle = 0, ran_count = 0;
 *   - waits start at the offsets, and every offset is below 2^pv;
 *   - order[] lists every process once, stably sorted by ascending pv;
 *   - perfect = ceil(sum 2^-pv);
 *   - the offsets are the bit-reversed interval positions of the hand proof
 *     (Lemmas 1 and 2): the process at position a of the order, with pv = k,
 *     owns the interval starting at A = sum of 2^-pv over the processes before
 *     it; A is a multiple of 2^-k and rev_k(offset) = 2^k A mod 2^k. This is the
 *     closed form the balance theorem rests on, stated without Fig. 6's
 *     start/slots bookkeeping.
 */
#include "proof_model.h"

void harness(void)
{
    static struct bsched s;
    struct proof_set set;
    uint32_t a;
    uint32_t i;
    uint32_t before; /* 2^P * A: area of the processes earlier in the order */
    int32_t rc;

    proof_nondet_set(&set);
    rc = bsched_init(&s, set.pv, (size_t)set.n);

    __CPROVER_assert(rc == BSCHED_OK, "init: a valid set is accepted");
    __CPROVER_assert(s.count == set.n, "init: count is the number of processes");
    __CPROVER_assert(s.maxpv == set.maxpv, "init: maxpv is the largest priority value");
    __CPROVER_assert(s.cycle == 0u, "init: the schedule starts at minor cycle 0");
    __CPROVER_assert(s.ran_count == 0u, "init: nothing has run yet");
    __CPROVER_assert(s.perfect == set.load_hi, "init: perfect = ceil(sum 2^-pv)");

    for (i = 0u; i < PROOF_N; i++) {
        if (i < set.n) {
            __CPROVER_assert(s.pv[i] == set.pv[i], "init: priority values kept in input order");
            __CPROVER_assert(s.wait[i] == s.offset[i], "init: waits start at the offsets");
            __CPROVER_assert((s.offset[i] >> set.pv[i]) == 0u, "init: offset below 2^pv");
        }
    }

    /* Strictly increasing (pv, index) keys over n positions, each naming a process
     * below n: a permutation, sorted by pv, ties in input order. */
    for (a = 0u; a < PROOF_N; a++) {
        if (a < set.n) {
            __CPROVER_assert(s.order[a] < set.n, "init: order names a process");
            if (a + 1u < set.n) {
                __CPROVER_assert(s.order[a + 1u] < set.n, "init: order names a process");
                __CPROVER_assert(proof_order_key(&set, s.order[a]) < proof_order_key(&set, s.order[a + 1u]),
                                 "init: order is stable and ascending in pv");
            }
        }
    }

    before = 0u;
    for (a = 0u; a < PROOF_N; a++) {
        if (a < set.n) {
            uint32_t p = s.order[a];
            uint32_t k = set.pv[p];
            /* A * 2^k is an integer: before is a multiple of 2^(P - k) */
            __CPROVER_assert((before & proof_mask(PROOF_P - k)) == 0u,
                             "init: each interval starts at a multiple of its length");
            __CPROVER_assert(s.offset[p] == proof_interval_offset(before, k),
                             "init: offset = rev_pv(interval position mod 2^pv)");
            before += PROOF_UNIT >> k;
        }
    }
    __CPROVER_assert(before == set.area, "init: the intervals tile [0, U)");
}
