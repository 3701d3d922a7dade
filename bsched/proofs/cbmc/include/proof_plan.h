/*
 * The plan bsched_init leaves for an ascending priority set, advanced to an
 * arbitrary minor cycle t, built from the hand proof rather than by bsched.c
 * (bsched/proofs/cbmc/<harness>/, with proof_model.h):
 *     offset_i = rev_P(A_i mod 2^P) mod 2^pv_i, A_i 2^P = sum of 2^(P - pv_j), j < i
 *         (the closed form that `init` checks bsched_init computes),
 *     class k: first = #{i : pv_i < k}, size = #{i : pv_i == k},
 *         lead = 2^k - (B_k mod 2^k), B_k = A 2^k at the class's first member;
 *         the first entries of empty classes hold anything, their leads anything
 *         in 0..2^k (bsched_init's are 2^k - s_k there too),
 *     cycle = t, reversed = rev_maxpv(t), perfect = ceil(U),
 *     ran[] and ran_count anything (the last cycle's record).
 * Entries at and after n are filled too (the library never reads them): then
 * order[id] = id is a constant for CBMC.
 */
#ifndef PROOF_PLAN_H
#define PROOF_PLAN_H

#include "proof_model.h"

/* rev_bits(x): the low `bits` (<= P) bits of x in reverse order. */
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

/* *s := the plan of `set` at the start of minor cycle t (t < 2^maxpv). */
static void proof_plan_at(struct bsched *s, const struct proof_set *set, uint32_t t)
{
    uint32_t area = 0u; /* A_i 2^P */
    uint32_t minpv = PROOF_P;
    uint32_t i;
    uint32_t k;

    s->ran_count = nondet_uint16();
    s->count = (uint16_t)set->n;
    s->maxpv = (uint8_t)set->maxpv;
    s->perfect = (uint16_t)set->load_hi;
    s->cycle = t;
    s->reversed = proof_reverse_bits(t, set->maxpv);
    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        uint32_t start = nondet_uint32(); /* an empty class's s_k: any, 0 <= s_k < 2^k */
        __CPROVER_assume(start <= proof_mask(k));
        s->class_first[k] = nondet_uint16();
        s->class_size[k] = 0u;
        s->class_key[k] = proof_class_key(start, k);
    }
    for (i = 0u; i < PROOF_N; i++) {
        uint32_t pv = set->pv[i];
        s->pv[i] = set->pv[i];
        s->order[i] = (uint16_t)i;
        s->offset[i] = proof_interval_offset(area, pv);
        s->ran[i] = nondet_uint16();
        if (i < set->n) {
            if (i == 0u || set->pv[i - 1u] != pv) {
                /* The first member of class pv: B_k mod 2^k, B_k = A 2^k. */
                uint32_t start = (area >> (PROOF_P - pv)) & proof_mask(pv);
                s->class_first[pv] = (uint16_t)i;
                s->class_key[pv] = proof_class_key(start, pv);
            }
            s->class_size[pv]++;
            if (pv < minpv) {
                minpv = pv;
            }
            area += PROOF_UNIT >> pv;
        }
    }
    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        s->class_limit[k] = proof_class_limit(s->class_size[k], k);
    }
    s->minpv = (uint8_t)minpv;
}

/* An arbitrary set (*set) and an arbitrary minor cycle t < 2^maxpv of it,
 * *s := the plan at t; returns t. The start of the step harnesses (step, agree). */
static uint32_t proof_plan_at_any_cycle(struct bsched *s, struct proof_set *set)
{
    uint32_t t;
    proof_nondet_set(set);
    t = nondet_uint32();
    __CPROVER_assume((t >> set->maxpv) == 0u); /* t < 2^maxpv */
    proof_plan_at(s, set, t);
    return t;
}

/* After a step from `before`: is *s the plan of the same set at cycle next?
 * (Only the cycle and the reversed counter move; pv, order and offsets are
 * checked by the caller, entry by entry.) */
static int proof_plan_next_ok(const struct bsched *s, const struct bsched *before, uint32_t next)
{
    uint32_t k;
    int ok = s->cycle == next && s->reversed == proof_reverse_bits(next, before->maxpv) &&
             s->count == before->count && s->maxpv == before->maxpv &&
             s->minpv == before->minpv && s->perfect == before->perfect;
    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        ok = ok && s->class_first[k] == before->class_first[k] &&
             s->class_size[k] == before->class_size[k] && s->class_key[k] == before->class_key[k] && s->class_limit[k] == before->class_limit[k];
    }
    return ok;
}

#endif /* PROOF_PLAN_H */
