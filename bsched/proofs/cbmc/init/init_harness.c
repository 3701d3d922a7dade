/*
 * CBMC harness `init`: bsched_init on every priority set within the bounds
 * (n in 1..N processes, each pv in 0..P, in every input order).
 *
 * Checks, besides memory safety and the absence of undefined behaviour
 * (property flags in ../Makefile.common), in three parts:
 *   state:   it succeeds and fills count, maxpv, minpv, pv[], cycle = 0,
 *            reversed = 0, ran_count = 0, class_size[k] = #{i : pv_i == k};
 *            every offset is below 2^pv;
 *            order[] lists every process once, stably sorted by ascending pv;
 *   perfect: perfect = ceil(sum 2^-pv);
 *   offsets: the offsets are the bit-reversed interval positions of the hand
 *            proof (Lemmas 1 and 2): the process at position a of the order,
 *            with pv = k, owns the interval starting at A = sum of 2^-pv over
 *            the processes before it; A is a multiple of 2^-k and
 *            rev_k(offset) = 2^k A mod 2^k. This is the closed form the balance
 *            theorem rests on (harness `balance`), stated without Fig. 6's
 *            start/slots bookkeeping; and at the first member of each class
 *            k: class_first[k] = a, class_key[k] = ((2^k - s_k) mod 2^k) 2^(31-k) with
 *            s_k = 2^k A mod 2^k; and class_limit[k] = min(c_k, 2^k) 2^(31-k).
 *
 * PROOF_PARTS (a bit set of the parts, default all) selects what one CBMC run
 * asserts. One SAT instance with all three parts is much harder than the three
 * apart, so the large-bound runs check one part each (cbmc.mk); together they
 * check everything. The only fact one part takes from another is the order
 * (`offsets` indexes through it): it is asserted in `state` and assumed
 * everywhere (PROOF_LEMMA), so a run of `offsets` alone relies on `state`.
 */
#include "proof_model.h"

#define PART_STATE 1
#define PART_PERFECT 2
#define PART_OFFSETS 4
#ifndef PROOF_PARTS
#define PROOF_PARTS (PART_STATE | PART_PERFECT | PART_OFFSETS)
#endif

/* Assert `cond` if this run checks `part`; otherwise nothing. */
#define CHECK(part, cond, name) \
    if ((PROOF_PARTS) & (part)) { \
        __CPROVER_assert((cond), name); \
    }
/* Assert `cond` if this run checks `part`; assume it in every run. */
#define CHECK_AND_USE(part, cond, name) \
    { \
        CHECK(part, cond, name) \
        __CPROVER_assume((cond)); \
    }

void harness(void)
{
    static struct bsched s;
    struct proof_set set;
    uint32_t a;
    uint32_t i;
    uint32_t before; /* 2^P * A: area of the processes earlier in the order */
    uint32_t sizes[BSCHED_MAX_PV + 1];
    uint32_t minpv = PROOF_P;
    uint32_t k;
    int32_t rc;

    proof_nondet_set(&set);
    rc = bsched_init(&s, set.pv, (size_t)set.n);

    CHECK(PART_STATE, rc == BSCHED_OK, "init: a valid set is accepted");
    CHECK(PART_STATE, s.count == set.n, "init: count is the number of processes");
    CHECK(PART_STATE, s.maxpv == set.maxpv, "init: maxpv is the largest priority value");
    CHECK(PART_STATE, s.cycle == 0u, "init: the schedule starts at minor cycle 0");
    CHECK(PART_STATE, s.ran_count == 0u, "init: nothing has run yet");
    CHECK(PART_STATE, s.reversed == 0u, "init: the reversed counter starts at rev(0) = 0");
    CHECK(PART_PERFECT, s.perfect == set.load_hi, "init: perfect = ceil(sum 2^-pv)");

    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        sizes[k] = 0u;
    }
    for (i = 0u; i < PROOF_N; i++) {
        if (i < set.n) {
            sizes[set.pv[i]]++;
            if (set.pv[i] < minpv) {
                minpv = set.pv[i];
            }
            CHECK(PART_STATE, s.pv[i] == set.pv[i], "init: priority values kept in input order");
            CHECK(PART_STATE, (s.offset[i] >> set.pv[i]) == 0u, "init: offset below 2^pv");
        }
    }

#if PROOF_SORTED_INPUT
    /* Ascending input: the stable sort by pv is the identity. The offsets part
     * then indexes offset[] directly. */
    for (a = 0u; a < PROOF_N; a++) {
        if (a < set.n) {
            CHECK_AND_USE(PART_STATE, s.order[a] == a,
                          "init: order is stable and ascending in pv (the identity for ascending input)");
        }
    }
#else
    /* Strictly increasing (pv, index) keys over n positions, each naming a process
     * below n: a permutation, sorted by pv, ties in input order. */
    for (a = 0u; a < PROOF_N; a++) {
        if (a < set.n) {
            CHECK_AND_USE(PART_STATE, s.order[a] < set.n, "init: order names a process");
            if (a + 1u < set.n) {
                CHECK_AND_USE(PART_STATE, s.order[a + 1u] < set.n, "init: order names a process");
                CHECK_AND_USE(PART_STATE,
                              proof_order_key(&set, s.order[a]) < proof_order_key(&set, s.order[a + 1u]),
                              "init: order is stable and ascending in pv");
            }
        }
    }
#endif

    before = 0u;
    for (a = 0u; a < PROOF_N; a++) {
        if (a < set.n) {
#if PROOF_SORTED_INPUT
            uint32_t p = a;
#else
            uint32_t p = s.order[a];
#endif
            k = set.pv[p];
            if (a == 0u || set.pv[s.order[a - 1u]] != k) {
                /* the first member of class k: where the class starts, and its key from s_k */
                CHECK(PART_OFFSETS, s.class_first[k] == a, "init: class_first is the class's first slot");
                CHECK(PART_OFFSETS, s.class_key[k] == proof_class_key((before >> (PROOF_P - k)) & proof_mask(k), k),
                      "init: class_key = ((2^k - s_k) mod 2^k) 2^(31-k), s_k = 2^k A mod 2^k");
            }
            /* A * 2^k is an integer: before is a multiple of 2^(P - k) */
            CHECK(PART_OFFSETS, (before & proof_mask(PROOF_P - k)) == 0u,
                  "init: each interval starts at a multiple of its length");
            CHECK(PART_OFFSETS, s.offset[p] == proof_interval_offset(before, k),
                  "init: offset = rev_pv(interval position mod 2^pv)");
            before += PROOF_UNIT >> k;
        }
    }
    CHECK(PART_OFFSETS, before == set.area, "init: the intervals tile [0, U)");
    CHECK(PART_STATE, s.minpv == minpv, "init: minpv is the smallest priority value");
    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        CHECK(PART_STATE, s.class_size[k] == sizes[k], "init: class_size is the class's number of members");
        CHECK(PART_STATE, s.class_limit[k] == proof_class_limit(sizes[k], k),
              "init: class_limit = min(c_k, 2^k) 2^(31-k)");
    }
}
