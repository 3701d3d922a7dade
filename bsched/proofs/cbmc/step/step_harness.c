/*
 * CBMC harness `step`: one minor cycle of bsched_step, for an arbitrary minor
 * cycle t of an arbitrary priority set, without simulating the cycles before t.
 *
 * The state is the one bsched_init leaves for the set (ascending input, one
 * input order per multiset, so order[] is the identity), advanced to cycle t,
 * built here from the hand proof rather than by bsched.c:
 *     offset_i = rev_P(A_i mod 2^P) mod 2^pv_i, A_i 2^P = sum of 2^(P - pv_j), j < i
 *         (the closed form that `init` checks bsched_init computes),
 *     class k: first = #{i : pv_i < k}, size = #{i : pv_i == k},
 *         lead = 2^k - (B_k mod 2^k), B_k = A 2^k at the class's first member;
 *         the entries of empty classes hold anything (lead at most 2^k),
 *     cycle = t < 2^maxpv (any), reversed = rev_maxpv(t), perfect = ceil(U),
 *     ran[] and ran_count anything (the last cycle's record).
 *
 * Checks:
 *   - bsched_wait(i) is Fig. 7's wait (offset_i - t) mod 2^pv_i;
 *   - bsched_step runs exactly the processes due at t (t = offset mod 2^pv), in
 *     execution order, and returns their number, at most perfect;
 *   - afterwards cycle = t + 1 mod 2^maxpv, reversed = rev_maxpv(cycle), and
 *     nothing else in the state changed.
 * With `init` (bsched_init yields this state at t = 0) this covers every cycle
 * of every major cycle at the same bounds.
 */
#include "proof_model.h"

/* rev_bits(x): the low `bits` bits of x in reverse order. */
static uint32_t proof_reverse_bits(uint32_t x, uint32_t bits)
{
    uint32_t r = 0u;
    uint32_t b;
    for (b = 0u; b < PROOF_P; b++) {
        if (b < bits) {
            r |= ((x >> b) & 1u) << (bits - 1u - b);
        }
    }
    return r;
}

void harness(void)
{
    static struct bsched s;
    static struct bsched before;
    struct proof_set set;
    uint32_t due[BSCHED_MAX_PROCS];
    uint32_t area = 0u; /* A_i 2^P */
    uint32_t due_count = 0u;
    uint32_t listed = 0u;
    uint32_t minpv = PROOF_P;
    uint32_t t;
    uint32_t next;
    uint32_t i;
    uint32_t k;
    int32_t rc;

    proof_nondet_set(&set);

    t = nondet_uint32();
    __CPROVER_assume((t >> set.maxpv) == 0u); /* t < 2^maxpv */
    next = (t + 1u) & proof_mask(set.maxpv);

    s.ran_count = nondet_uint16();
    s.count = (uint16_t)set.n;
    s.maxpv = (uint8_t)set.maxpv;
    s.perfect = (uint16_t)set.load_hi;
    s.cycle = t;
    s.reversed = proof_reverse_bits(t, set.maxpv);
    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        s.class_first[k] = nondet_uint16();
        s.class_size[k] = 0u;
        s.class_lead[k] = nondet_uint32();
        __CPROVER_assume(s.class_lead[k] <= ((uint32_t)1u << k)); /* 2^k - s_k, s_k >= 0 */
    }
    /* Entries at and after n are filled too (the library never reads them):
     * then order[id] = id is a constant for CBMC. */
    for (i = 0u; i < PROOF_N; i++) {
        uint32_t pv = set.pv[i];
        uint32_t w = proof_interval_offset(area, pv);
        s.pv[i] = set.pv[i];
        s.order[i] = (uint16_t)i;
        s.offset[i] = w;
        s.ran[i] = nondet_uint16();
        due[i] = 0u;
        if (i < set.n) {
            if (i == 0u || set.pv[i - 1u] != pv) {
                /* The first member of class pv: B_k mod 2^k, B_k = A 2^k. */
                uint32_t start = (area >> (PROOF_P - pv)) & proof_mask(pv);
                s.class_first[pv] = (uint16_t)i;
                s.class_lead[pv] = proof_mask(pv) + 1u - start;
            }
            s.class_size[pv]++;
            if (pv < minpv) {
                minpv = pv;
            }
            due[i] = (uint32_t)proof_due_at(w, pv, t);
            due_count += due[i];
            __CPROVER_assert(bsched_wait(&s, (uint16_t)i) == (int32_t)proof_wait_at(w, pv, t),
                             "wait: bsched_wait is Fig. 7's wait (offset - t) mod 2^pv");
            area += PROOF_UNIT >> pv;
        }
    }
    s.minpv = (uint8_t)minpv;
    before = s;

    rc = bsched_step(&s);

    __CPROVER_assert(rc >= 0 && (uint32_t)rc == due_count, "step: runs every due process and only those");
    __CPROVER_assert(rc >= 0 && (uint32_t)rc <= set.load_hi, "step: at most perfect = ceil(U) processes");
    __CPROVER_assert(s.ran_count == due_count, "step: ran_count is the number run");
    for (i = 0u; i < PROOF_N; i++) {
        if (i < set.n && due[i] != 0u) {
            /* order[] is the identity: due processes in index order */
            __CPROVER_assert(listed < due_count && s.ran[listed] == i,
                             "step: ran[] lists the due processes in execution order");
            listed++;
        }
        __CPROVER_assert(s.pv[i] == before.pv[i] && s.order[i] == before.order[i] &&
                         s.offset[i] == before.offset[i], "step: pv, order and offsets unchanged");
    }
    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        __CPROVER_assert(s.class_first[k] == before.class_first[k] && s.class_size[k] == before.class_size[k] &&
                         s.class_lead[k] == before.class_lead[k], "step: class table unchanged");
    }
    __CPROVER_assert(s.cycle == next, "step: cycle advances to t + 1 mod 2^maxpv");
    __CPROVER_assert(s.reversed == proof_reverse_bits(next, set.maxpv),
                     "step: the reversed counter is rev_maxpv of the next cycle");
    __CPROVER_assert(s.count == before.count && s.maxpv == before.maxpv && s.minpv == before.minpv &&
                     s.perfect == before.perfect, "step: count, maxpv, minpv, perfect unchanged");
}
