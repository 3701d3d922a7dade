/*
 * Shared pieces of the CBMC harnesses for bsched (bsched/proofs/cbmc/<harness>/).
 *
 * Bounds (set by each harness Makefile with -D, reused in its unwind set):
 *   BSCHED_MAX_PROCS  N: the library capacity, also the largest process count tried
 *   PROOF_MAX_PV      P: the largest priority value tried (0 <= P <= 8 keeps the
 *                     fixed-point sums below in 32 bits: N * 2^P <= 65535 * 256)
 *   PROOF_EXACT_N     optional: only sets of exactly this many processes (1..N);
 *                     a Makefile then runs one CBMC job per n (see Makefile.common)
 *
 * The specification side is written from the paper and the hand proof
 * that B-schedules are balanced, not from bsched.c:
 * utilisation is a fixed-point sum with 2^P as the unit, and everything on the
 * hot paths uses masks and shifts, never % or / by a variable.
 */
#ifndef PROOF_MODEL_H
#define PROOF_MODEL_H

#include <stddef.h>
#include <stdint.h>

#include "bsched.h"

#ifndef PROOF_MAX_PV
#error "PROOF_MAX_PV (the largest priority value to try) must be given with -D"
#endif
#ifndef PROOF_SORTED_INPUT
#define PROOF_SORTED_INPUT 0
#endif
#if PROOF_MAX_PV < 0 || PROOF_MAX_PV > 8
#error "PROOF_MAX_PV must be between 0 and 8"
#endif

/* CBMC's nondeterministic values: functions without a body return any value. */
uint8_t nondet_uint8(void);
uint16_t nondet_uint16(void);
uint32_t nondet_uint32(void);
size_t nondet_size(void);
int nondet_int(void);

#define PROOF_N ((uint32_t)BSCHED_MAX_PROCS)
#define PROOF_P ((uint32_t)PROOF_MAX_PV)
/* One unit of utilisation in the fixed-point sums: U = area / PROOF_UNIT. */
#define PROOF_UNIT ((uint32_t)1u << PROOF_MAX_PV)

/* A priority set: n processes, pv[0..n-1] in the caller's order. */
struct proof_set {
    uint32_t n;
    uint8_t pv[BSCHED_MAX_PROCS];
    uint32_t maxpv;   /* the largest pv[i], i < n */
    uint32_t area;    /* sum over i < n of 2^(P - pv[i]): U * 2^P, exact */
    uint32_t load_lo; /* floor(U) */
    uint32_t load_hi; /* ceil(U) */
};

/* Any n in 1..N and any pv[i] in 0..P: every sequence of priority values within
 * the bounds, hence every multiset with every input order. Entries at and after
 * n are also constrained (they are never read by the library). */
static void proof_nondet_set(struct proof_set *set)
{
    uint32_t i;
#ifdef PROOF_EXACT_N
    /* One process count per run (the runs for n = 1..N together cover 1..N):
     * smaller SAT instances, all loop conditions on n concrete. */
    set->n = PROOF_EXACT_N;
#else
    set->n = nondet_uint32();
#endif
    __CPROVER_assume(set->n >= 1u && set->n <= PROOF_N);
    set->maxpv = 0u;
    set->area = 0u;
    for (i = 0u; i < PROOF_N; i++) {
        set->pv[i] = nondet_uint8();
        __CPROVER_assume(set->pv[i] <= PROOF_P);
#if PROOF_SORTED_INPUT
        /* One input order per multiset: ascending, which the stable sort keeps. */
        if (i > 0u) {
            __CPROVER_assume(set->pv[i] >= set->pv[i - 1u]);
        }
#endif
        if (i < set->n) {
            set->area += PROOF_UNIT >> set->pv[i];
            if (set->pv[i] > set->maxpv) {
                set->maxpv = set->pv[i];
            }
        }
    }
    set->load_lo = set->area >> PROOF_MAX_PV;
    set->load_hi = (set->area + PROOF_UNIT - 1u) >> PROOF_MAX_PV;
}

/* 2^pv - 1: the residue mask of a process's period. */
static uint32_t proof_mask(uint32_t pv)
{
    return ((uint32_t)1u << pv) - 1u;
}

/* The residue test's key of a class with start s_k (bsched.h): ((2^k - s_k) mod 2^k)
 * 2^(31-k), in 64-bit arithmetic (the library computes it differently, in 32 bits). */
static uint32_t proof_class_key(uint32_t start, uint32_t pv)
{
    uint64_t period = (uint64_t)1u << pv;
    return (uint32_t)(((period - start) % period) << (31u - pv));
}

/* The residue test's limit of a class of `size` members: min(size, 2^k) 2^(31-k). */
static uint32_t proof_class_limit(uint32_t size, uint32_t pv)
{
    uint64_t period = (uint64_t)1u << pv;
    uint64_t in_use = size < period ? size : period;
    return (uint32_t)(in_use << (31u - pv));
}

/* (w - t) mod 2^pv for w < 2^pv, without wrapping: the wait the periodicity
 * invariant prescribes at the start of minor cycle t. */
static uint32_t proof_wait_at(uint32_t w, uint32_t pv, uint32_t t)
{
    uint32_t m = proof_mask(pv);
    return (w + (m + 1u) - (t & m)) & m;
}

/* Is a process with offset w (w < 2^pv) due in minor cycle t? t = w (mod 2^pv). */
static int proof_due_at(uint32_t w, uint32_t pv, uint32_t t)
{
    return (t & proof_mask(pv)) == w;
}

/* rev_P(x): the low P bits of x in reverse order. A fixed permutation of bits,
 * so it costs the SAT back end nothing. */
static uint32_t proof_reverse_p(uint32_t x)
{
    uint32_t r = 0u;
    uint32_t b;
    for (b = 0u; b < PROOF_P; b++) {
        r |= ((x >> b) & 1u) << (PROOF_P - 1u - b);
    }
    return r;
}

/* The offset the hand proof assigns to a process with priority value k whose
 * interval [A, A + 2^-k) starts at A = before / 2^P (Lemmas 1 and 2):
 * rev_k(offset) = 2^k A mod 2^k, the top k of the P fraction bits of A. As
 * rev_k of the top k bits of a P-bit number is the low k bits of its rev_P:
 * offset = rev_P(before mod 2^P) mod 2^k. */
static uint32_t proof_interval_offset(uint32_t before, uint32_t k)
{
    return proof_reverse_p(before & (PROOF_UNIT - 1u)) & proof_mask(k);
}

/* A checked lemma: asserted (CBMC reports it like any other property, and a
 * run where it fails fails the check), then assumed, so that the properties
 * after it may use it. This splits one hard SAT question into local steps. */
/* (A block, not do-while(0): that would be one more loop in the unwind set.) */
#define PROOF_LEMMA(cond, name) \
    { \
        __CPROVER_assert((cond), name); \
        __CPROVER_assume((cond)); \
    }

/* Laps below y: #{m >= 0 : x + m 2^P < y}, for a point x < 2^P of the circle
 * [0, 2^P) unrolled onto [0, U 2^P): floor(y / 2^P) + (y mod 2^P > x).
 * Only a shift, a mask and a comparison. */
static uint32_t proof_laps_below(uint32_t y, uint32_t x)
{
    return (y >> PROOF_MAX_PV) + (((y & (PROOF_UNIT - 1u)) > x) ? 1u : 0u);
}

/* Execution order key: ascending pv, ties in input order (a stable sort). */
static uint32_t proof_order_key(const struct proof_set *set, uint32_t index)
{
    return (uint32_t)set->pv[index] * 65536u + index;
}

#endif /* PROOF_MODEL_H */
