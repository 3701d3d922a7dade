/*
 * bsched.c: the B-scheduler (Birk, Kenn, Steels 2002, section 4, Figs. 6, 7).
 * See bsched.h for the interface and bsched/spec/ for what is proven about it.
 *
 * Arithmetic is written with *2, /2, %2 and masks on unsigned values so that
 * the same text is efficient on a CPU32 and close to its arithmetic ACSL spec.
 */
#include "bsched.h"
#include "spec/bsched_logic.h"
#include "spec/bsched_lemmas.h"
#include "spec/bsched_order.h"
#include "spec/bsched_fold.h"
#include "spec/bsched_rev.h"
#include "spec/bsched_balance.h"
#include "spec/bsched_slots.h"

/* The low `bits` bits of x in reverse order (Fig. 6's reverse()).
 * BSCHED_MUTANT_NO_REVERSE builds a deliberately wrong variant (identity
 * instead of reversal) for the negative checks of the proof jobs: the
 * schedule stays periodic per class but is no longer balanced. */
/*@ requires bits_range: bits <= BSCHED_MAX_PV;
    requires x_range: x < pow2(bits);
    assigns \nothing;
    ensures reversal: \result == fig6_map(bits, x);
    ensures below_period: \result < pow2(bits);
*/
static uint32_t reverse_bits(uint32_t x, uint32_t bits)
{
#ifdef BSCHED_MUTANT_NO_REVERSE
    (void)bits;
    return x;
#else
    uint32_t reversed = 0u;
    uint32_t rest = x;
    uint32_t b;
    /*@ ghost lemma_pow2(BSCHED_MAX_PV); */
    /*@ ghost lemma_div_pow2_half(); */
    /*@ loop invariant b_range: 0 <= b <= bits;
        loop invariant reversed_so_far: reversed == rev(b, x);
        loop invariant rest_is_shifted: rest == x / pow2(b);
        loop invariant reversed_range: reversed < pow2(b);
        loop assigns b, reversed, rest;
        loop variant bits - b;
    */
    for (b = 0u; b < bits; b++) {
        /*@ assert next_rest: (x / pow2(b)) / 2 == x / pow2(b + 1); */
        reversed = reversed * 2u + rest % 2u;
        rest = rest / 2u;
    }
    return reversed;
#endif
}

/* 2^pv as the period of a class, pv <= BSCHED_MAX_PV. */
/*@ requires pv_range: pv <= BSCHED_MAX_PV;
    assigns \nothing;
    ensures is_pow2: \result == pow2(pv);
*/
static uint32_t period_of(uint8_t pv)
{
    /*@ ghost lemma_pow2(BSCHED_MAX_PV); */
    return (uint32_t)1u << pv;
}

/*@ predicate plausible{L}(struct bsched *s) =
      1 <= s->count <= BSCHED_MAX_PROCS && s->maxpv <= BSCHED_MAX_PV && s->perfect >= 1;
*/

/* A cheap check that *s came from bsched_init (a zeroed struct does not):
 * 1 <= count <= BSCHED_MAX_PROCS, maxpv <= BSCHED_MAX_PV, perfect >= 1. */
/*@ requires \valid_read(s);
    assigns \nothing;
    ensures plausible_iff: \result != 0 <==> plausible(s);
*/
static int plausible_state(const struct bsched *s)
{
    /* count - 1 < MAX is the upper bound in a form that stays meaningful (no
     * always-true comparison) when MAX is 65535; count != 0 first, so it never wraps. */
    return s->count != 0u && (uint32_t)s->count - 1u < (uint32_t)BSCHED_MAX_PROCS &&
           s->maxpv <= BSCHED_MAX_PV && s->perfect >= 1u;
}

/* Per priority class k, the working state of bsched_init. */
struct bsched_classes {
    uint32_t size[BSCHED_MAX_PV + 1];   /* c_k: processes in class k */
    uint32_t next[BSCHED_MAX_PV + 1];   /* next free slot of class k in order[] */
    uint32_t cursor[BSCHED_MAX_PV + 1]; /* s_k + members of class k placed so far */
};

/* Class sizes, first slots and Fig. 6 start values; returns maxpv. */
/*@ requires 1 <= n <= BSCHED_MAX_PROCS;
    requires \valid(c) && \valid_read(pv + (0 .. n - 1));
    requires \separated(c, pv + (0 .. n - 1));
    requires \forall integer i; 0 <= i < n ==> pv[i] <= BSCHED_MAX_PV;
    assigns *c;
    ensures sizes: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
        c->size[k] == class_count(pv, n, k) <= n;
    ensures firsts: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
        c->next[k] == class_first(pv, n, k);
    ensures starts: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
        c->cursor[k] == class_start(pv, n, k) < pow2(k);
    ensures maxpv: \result == max_pv(pv, n) <= BSCHED_MAX_PV;
    ensures maxpv_bounds: \forall integer i; 0 <= i < n ==> pv[i] <= \result;
*/
static uint32_t plan_classes(struct bsched_classes *c, const uint8_t *pv, size_t n)
{
    uint32_t maxpv = 0u;
    uint32_t first = 0u;
    uint32_t start = 0u;
    uint32_t slots = 1u;
    uint32_t i;
    uint32_t k;

    /*@ ghost lemma_pow2(BSCHED_MAX_PV); */
    /*@ ghost lemma_count(pv, n); */
    /*@ loop invariant 0 <= k <= BSCHED_MAX_PV + 1;
        loop invariant \forall integer j; 0 <= j < k ==> c->size[j] == 0;
        loop assigns k, c->size[0 .. BSCHED_MAX_PV];
        loop variant BSCHED_MAX_PV + 1 - k;
    */
    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        c->size[k] = 0u;
    }
    /*@ loop invariant 0 <= i <= n;
        loop invariant size_is_count: \forall integer j; 0 <= j <= BSCHED_MAX_PV ==>
            c->size[j] == class_count(pv, i, j);
        loop invariant maxpv_is_max: maxpv == max_pv(pv, i) <= BSCHED_MAX_PV;
        loop invariant maxpv_bounds: \forall integer j; 0 <= j < i ==> pv[j] <= maxpv;
        loop assigns i, maxpv, c->size[0 .. BSCHED_MAX_PV];
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        c->size[pv[i]]++;
        if (pv[i] > maxpv) {
            maxpv = pv[i];
        }
    }
    /*@ loop invariant 0 <= k <= BSCHED_MAX_PV + 1;
        loop invariant first_is_sum: first == class_first(pv, n, k);
        loop invariant first_bound: first <= k * BSCHED_MAX_PROCS;
        loop invariant \forall integer j; 0 <= j < k ==> c->next[j] == class_first(pv, n, j);
        loop assigns k, first, c->next[0 .. BSCHED_MAX_PV];
        loop variant BSCHED_MAX_PV + 1 - k;
    */
    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        /*@ assert size_bound: c->size[k] <= n; */
        /*@ assert first_step: class_first(pv, n, k + 1) == first + c->size[k]; */
        c->next[k] = first;
        first += c->size[k];
    }
    /* Fig. 6's start and n_slots, for every class at once: s_0 = 0, and
     * s_(k+1) = 2 * ((s_k + c_k) mod 2^k). Class 0 has one slot, so it leaves
     * start at 0, as Fig. 6 (whose loop begins at class 1) has it. */
    /*@ loop invariant 0 <= k <= BSCHED_MAX_PV + 1;
        loop invariant k <= BSCHED_MAX_PV ==> start == class_start(pv, n, k) && slots == pow2(k);
        loop invariant k <= BSCHED_MAX_PV ==> start < slots;
        loop invariant \forall integer j; 0 <= j < k ==>
            c->cursor[j] == class_start(pv, n, j) < pow2(j);
        loop assigns k, start, slots, c->cursor[0 .. BSCHED_MAX_PV];
        loop variant BSCHED_MAX_PV + 1 - k;
    */
    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        c->cursor[k] = start;
        start = (start + c->size[k]) % slots;
        if (k < BSCHED_MAX_PV) {
            start = start * 2u;
            slots = slots * 2u;
        }
    }
    return maxpv;
}

/* Stable counting sort (ties keep the caller's order) and, per process,
 * Fig. 6: member j of class k waits reverse_k((s_k + j) mod 2^k). */
/*@ requires 1 <= n <= BSCHED_MAX_PROCS;
    requires \valid(s) && \valid(c) && \valid_read(pv + (0 .. n - 1));
    requires \separated(s, c, pv + (0 .. n - 1));
    requires \forall integer i; 0 <= i < n ==> pv[i] <= BSCHED_MAX_PV;
    requires \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
        c->next[k] == class_first(pv, n, k) &&
        c->cursor[k] == class_start(pv, n, k) < pow2(k);
    assigns s->order[0 .. n - 1], s->offset[0 .. n - 1], c->next[0 .. BSCHED_MAX_PV],
        c->cursor[0 .. BSCHED_MAX_PV];
    ensures offsets: \forall integer i; 0 <= i < n ==>
        s->offset[i] == init_wait(pv, n, i) && s->offset[i] < pow2(pv[i]);
    ensures order_range: \forall integer id; 0 <= id < n ==> s->order[id] < n;
    ensures sorted_slots: \forall integer d; 0 <= d < n ==>
        s->order[d] < n && sorted_pos(pv, n, s->order[d]) == d;
    ensures sorted_procs: \forall integer i; 0 <= i < n ==>
        0 <= sorted_pos(pv, n, i) < n && s->order[sorted_pos(pv, n, i)] == i;
*/
static void place_processes(struct bsched *s, struct bsched_classes *c,
                            const uint8_t *pv, size_t n)
{
    uint32_t i;

    /*@ ghost lemma_pow2_bound(); */
    /* Slot d of class k is written once, by the member of class k whose
     * sorted position is d; the slots filled so far are the first
     * class_count(pv, i, k) of every class. */
    /*@ loop invariant 0 <= i <= n;
        loop invariant next_is_slot: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
            c->next[k] == class_first(pv, n, k) + class_count(pv, i, k);
        loop invariant cursor_is_rank: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
            c->cursor[k] == class_start(pv, n, k) + class_count(pv, i, k);
        loop invariant start_below: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
            class_start(pv, n, k) < pow2(k);
        loop invariant offset_closed: \forall integer j; 0 <= j < i ==>
            s->offset[j] == init_wait(pv, n, j) && s->offset[j] < pow2(pv[j]);
        loop invariant slots_filled: \forall integer k, d; 0 <= k <= BSCHED_MAX_PV &&
            class_first(pv, n, k) <= d < class_first(pv, n, k) + class_count(pv, i, k) ==>
            s->order[d] < i && sorted_pos(pv, n, s->order[d]) == d;
        loop invariant procs_placed: \forall integer j; 0 <= j < i ==>
            s->order[sorted_pos(pv, n, j)] == j;
        loop assigns i, c->next[0 .. BSCHED_MAX_PV], c->cursor[0 .. BSCHED_MAX_PV],
            s->order[0 .. n - 1], s->offset[0 .. n - 1];
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        uint8_t pvi = pv[i];
        uint32_t wait;
        /*@ ghost lemma_place_step(pv, n, i); */
        /*@ assert slot_is_pos: c->next[pvi] == sorted_pos(pv, n, i); */
        s->order[c->next[pvi]] = (uint16_t)i;
        /*@ assert cursor_is: c->cursor[pvi] == class_start(pv, n, pvi) + class_count(pv, i, pvi); */
        /*@ assert cursor_bound: c->cursor[pvi] < pow2(pvi) + BSCHED_MAX_PROCS; */
        /*@ assert cursor_no_wrap: c->cursor[pvi] < 4294967295; */
        wait = reverse_bits(c->cursor[pvi] % period_of(pvi), pvi);
        /*@ assert wait_closed: wait == init_wait(pv, n, i); */
        s->offset[i] = wait;
        /*@ assert offset_next: \forall integer j; 0 <= j <= i ==>
                s->offset[j] == init_wait(pv, n, j) && s->offset[j] < pow2(pv[j]); */
        /*@ assert next_bound: c->next[pvi] == sorted_pos(pv, n, i) < n; */
        c->next[pvi]++;
        c->cursor[pvi]++;
        /*@ assert next_this: c->next[pvi] == sorted_pos(pv, n, i) + 1; */
        /*@ assert next_others: \forall integer k; 0 <= k <= BSCHED_MAX_PV && k != pvi ==>
                c->next[k] == \at(c->next[k], LoopCurrent); */
        /*@ assert new_slot: s->order[sorted_pos(pv, n, i)] == i; */
        /*@ assert old_slots: \forall integer d; 0 <= d < n && d != sorted_pos(pv, n, i) ==>
                s->order[d] == \at(s->order[d], LoopCurrent); */
    }
    /* Every slot d < n lies in some class range [first(k), first(k + 1)). */
    /*@ ghost
      int k = 0;
      lemma_classes(pv, n);
      /@ loop invariant k_range: 0 <= k <= BSCHED_MAX_PV + 1;
         loop invariant slots_below: \forall integer d; 0 <= d < class_first(pv, n, k) ==>
             s->order[d] < n && sorted_pos(pv, n, s->order[d]) == d;
         loop assigns k;
         loop variant BSCHED_MAX_PV + 1 - k;
      @/
      while (k < BSCHED_MAX_PV + 1) {
        /@ assert first_next: class_first(pv, n, k + 1) == class_first(pv, n, k) + class_count(pv, n, k); @/
        k = k + 1;
      }
    */
    /*@ ghost lemma_pos_range(pv, n); */
}

/* perfect = ceil(sum_k c_k 2^-k), folded from the top class down:
 * ceil(c_(k-1) + x/2) = c_(k-1) + ceil(ceil(x)/2), so 32 bits suffice. */
/*@ requires 1 <= n <= BSCHED_MAX_PROCS;
    requires \valid_read(c) && \valid_read(pv + (0 .. n - 1));
    requires \forall integer i; 0 <= i < n ==> pv[i] <= BSCHED_MAX_PV;
    requires \forall integer k; 0 <= k <= BSCHED_MAX_PV ==> c->size[k] == class_count(pv, n, k);
    assigns \nothing;
    ensures fold: \result == perfect_of(pv, n);
    ensures bounds: 1 <= \result <= n;
*/
static uint32_t perfect_load(const struct bsched_classes *c, const uint8_t *pv, size_t n)
{
    uint32_t carry = 0u;
    uint32_t k;

    (void)pv; /* pv and n name the set in the specification only */
    (void)n;
    /*@ ghost lemma_count(pv, n); */
    /*@ ghost lemma_first(pv, n); */
    /*@ loop invariant 0 <= k <= BSCHED_MAX_PV;
        loop invariant carry == carry_from(pv, n, k + 1);
        loop invariant carry + class_first(pv, n, k + 1) <= n;
        loop invariant carry == 0 ==> class_first(pv, n, k + 1) == n;
        loop assigns k, carry;
        loop variant k;
    */
    for (k = BSCHED_MAX_PV; k > 0u; k--) {
        /*@ assert class_step: class_first(pv, n, k + 1) == class_first(pv, n, k) + c->size[k]; */
        /*@ assert fold_fits: (c->size[k] + carry + 1) / 2 + class_first(pv, n, k) <= n; */
        carry = (c->size[k] + carry + 1u) / 2u;
    }
    /*@ assert k == 0; */
    /*@ assert carry_is_fold: carry == carry_from(pv, n, 1); */
    /*@ assert first_1: class_first(pv, n, 1) == c->size[0]; */
    /*@ assert sum_bound: c->size[0] + carry <= n; */
    /*@ assert sum_positive: carry == 0 ==> c->size[0] == n; */
    return c->size[0] + carry;
}

/*@ requires valid_state: s == \null || \valid(s);
    requires valid_input: pv != \null && 1 <= count <= BSCHED_MAX_PROCS ==>
        \valid_read(pv + (0 .. count - 1));
    requires separated: s != \null && pv != \null && 1 <= count <= BSCHED_MAX_PROCS ==>
        \separated(s, pv + (0 .. count - 1));
    assigns *s;

    behavior null:
      assumes s == \null || pv == \null;
      assigns \nothing;
      ensures \result == BSCHED_ERR_NULL;
    behavior no_procs:
      assumes s != \null && pv != \null && count == 0;
      assigns \nothing;
      ensures \result == BSCHED_ERR_NO_PROCS;
    behavior too_many:
      assumes s != \null && pv != \null && count > BSCHED_MAX_PROCS;
      assigns \nothing;
      ensures \result == BSCHED_ERR_TOO_MANY;
    behavior pv_range:
      assumes s != \null && pv != \null && 1 <= count <= BSCHED_MAX_PROCS;
      assumes \exists integer i; 0 <= i < count && pv[i] > BSCHED_MAX_PV;
      assigns \nothing;
      ensures \result == BSCHED_ERR_PV_RANGE;
    behavior ok:
      assumes s != \null && pv != \null && 1 <= count <= BSCHED_MAX_PROCS;
      assumes \forall integer i; 0 <= i < count ==> pv[i] <= BSCHED_MAX_PV;
      ensures ok_result: \result == BSCHED_OK;
      ensures ok_well_formed: well_formed(s);
      ensures ok_in_phase: in_phase(s);
      ensures ok_count: s->count == count && s->cycle == 0 && s->ran_count == 0;
      ensures ok_maxpv: s->maxpv == max_pv{Pre}(pv, count);
      ensures ok_pv: \forall integer i; 0 <= i < count ==> s->pv[i] == pv[i];
      ensures ok_closed_form: \forall integer i; 0 <= i < count ==>
          s->offset[i] == init_wait{Pre}(pv, count, i);
      ensures ok_wait_offset: \forall integer i; 0 <= i < count ==>
          s->wait[i] == s->offset[i] < pow2(pv[i]);
      ensures ok_order_range: \forall integer id; 0 <= id < count ==> s->order[id] < count;
      ensures ok_perfect: s->perfect == perfect_of{Pre}(pv, count);
      ensures ok_perfect_ceil: s->perfect ==
          (area(&s->pv[0], count) + pow2(BSCHED_MAX_PV) - 1) / pow2(BSCHED_MAX_PV);
      ensures ok_scheduled: scheduled(s);
      ensures ok_sorted: sorted_order(s);
      ensures ok_closed: closed_form(s);
    complete behaviors;
    disjoint behaviors;
*/
int32_t bsched_init(struct bsched *s, const uint8_t *pv, size_t count)
{
    struct bsched_classes classes;
    uint32_t n;
    uint32_t maxpv;
    uint32_t perfect;
    uint32_t i;

    if (s == NULL || pv == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (count == 0u) {
        return BSCHED_ERR_NO_PROCS;
    }
    if (count > (size_t)BSCHED_MAX_PROCS) {
        return BSCHED_ERR_TOO_MANY;
    }
    n = (uint32_t)count;
    /* Validate everything before writing anything: bad input leaves *s as it was. */
    /*@ loop invariant 0 <= i <= n;
        loop invariant \forall integer j; 0 <= j < i ==> pv[j] <= BSCHED_MAX_PV;
        loop assigns i;
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        if (pv[i] > BSCHED_MAX_PV) {
            return BSCHED_ERR_PV_RANGE;
        }
    }
    /*@ ghost lemma_wait_form(pv, count); */
    maxpv = plan_classes(&classes, pv, count);
    place_processes(s, &classes, pv, count);
    perfect = perfect_load(&classes, pv, count);
    /*@ loop invariant 0 <= i <= n;
        loop invariant \forall integer j; 0 <= j < i ==> s->wait[j] == s->offset[j];
        loop invariant \forall integer j; 0 <= j < i ==> s->pv[j] == pv[j];
        loop invariant offsets_kept: \forall integer j; 0 <= j < n ==>
            s->offset[j] == init_wait{Pre}(pv, count, j);
        loop assigns i, s->wait[0 .. n - 1], s->pv[0 .. n - 1];
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        s->pv[i] = pv[i];
        s->wait[i] = s->offset[i];
    }
    s->perfect = (uint16_t)perfect;
    s->count = (uint16_t)count;
    s->maxpv = (uint8_t)maxpv;
    s->cycle = 0u;
    s->ran_count = 0u;
    /*@ assert wf_sizes: 1 <= s->count <= BSCHED_MAX_PROCS && s->maxpv <= BSCHED_MAX_PV &&
            1 <= s->perfect <= s->count && s->cycle < pow2(s->maxpv); */
    /*@ assert wf_procs: \forall integer j; 0 <= j < s->count ==>
            s->pv[j] <= s->maxpv && s->wait[j] < pow2(s->pv[j]) && s->offset[j] < pow2(s->pv[j]); */
    /*@ assert wf_order: \forall integer id; 0 <= id < s->count ==> s->order[id] < s->count; */
    /* s->pv is a copy of pv, so the class layout of s->pv is that of pv. */
    /*@ assert pv_copied: \forall integer j; 0 <= j < n ==> (&s->pv[0])[j] == \at(pv[j], Pre); */
    /*@ ghost
      uint32_t m = 0u;
      int k = 0;
      /@ loop invariant m_range: 0 <= m <= n;
         loop invariant same_count: \forall integer m0, k0; 0 <= m0 <= m ==>
             class_count(&s->pv[0], m0, k0) == \at(class_count(pv, m0, k0), Pre);
         loop assigns m;
         loop variant n - m;
      @/
      while (m < n) {
        m = m + 1u;
      }
      /@ loop invariant k_range: 0 <= k <= BSCHED_MAX_PV + 1;
         loop invariant same_first: \forall integer k0; 0 <= k0 <= k ==>
             class_first(&s->pv[0], count, k0) == \at(class_first(pv, count, k0), Pre) &&
             class_start(&s->pv[0], count, k0) == \at(class_start(pv, count, k0), Pre);
         loop assigns k;
         loop variant BSCHED_MAX_PV + 1 - k;
      @/
      while (k < BSCHED_MAX_PV + 1) {
        k = k + 1;
      }
    */
    /*@ assert same_count_own: \forall integer j; 0 <= j < n ==>
            class_count(&s->pv[0], j, (&s->pv[0])[j]) == \at(class_count(pv, j, pv[j]), Pre); */
    /*@ assert same_first_own: \forall integer j; 0 <= j < n ==>
            class_first(&s->pv[0], count, (&s->pv[0])[j]) == \at(class_first(pv, count, pv[j]), Pre) &&
            class_start(&s->pv[0], count, (&s->pv[0])[j]) == \at(class_start(pv, count, pv[j]), Pre); */
    /*@ assert same_pos: \forall integer j; 0 <= j < n ==>
            sorted_pos(&s->pv[0], count, j) == \at(sorted_pos(pv, count, j), Pre); */
    /*@ assert same_arg: \forall integer j; 0 <= j < n ==>
            (&s->pv[0])[j] == \at(pv[j], Pre) &&
            class_start(&s->pv[0], count, (&s->pv[0])[j]) + class_count(&s->pv[0], j, (&s->pv[0])[j]) ==
            \at(class_start(pv, count, pv[j]) + class_count(pv, j, pv[j]), Pre); */
    /*@ ghost lemma_wait_form(&s->pv[0], count); */
    /*@ assert same_wait: \forall integer j; 0 <= j < n ==>
            init_wait(&s->pv[0], count, j) == \at(init_wait(pv, count, j), Pre); */
    /*@ assert sorted_slots: \forall integer d; 0 <= d < n ==>
            s->order[d] < n && sorted_pos(&s->pv[0], count, s->order[d]) == d; */
    /*@ assert sorted_procs: \forall integer j; 0 <= j < n ==>
            0 <= sorted_pos(&s->pv[0], count, j) < n && s->order[sorted_pos(&s->pv[0], count, j)] == j; */
    /*@ assert closed: \forall integer j; 0 <= j < n ==>
            s->offset[j] == init_wait(&s->pv[0], count, j); */
    /*@ ghost
      int c = BSCHED_MAX_PV + 1;
      /@ loop invariant c_range: 1 <= c <= BSCHED_MAX_PV + 1;
         loop invariant same_carry: \forall integer k0; c <= k0 <= BSCHED_MAX_PV + 1 ==>
             carry_from(&s->pv[0], count, k0) == \at(carry_from(pv, count, k0), Pre);
         loop assigns c;
         loop variant c;
      @/
      while (c > 1) {
        c = c - 1;
      }
    */
    /*@ assert same_perfect: perfect_of(&s->pv[0], count) == \at(perfect_of(pv, count), Pre); */
    /*@ ghost lemma_scheduled(s); */
    /* perfect = ceil(U), U = sum_i 2^-pv_i (spec/bsched_fold.h). */
    /*@ ghost lemma_fold(&s->pv[0], count); */
    /*@ ghost lemma_area_regroup(&s->pv[0], count); */
    /*@ assert perfect_is_fold: s->perfect == perfect_of(&s->pv[0], count); */
    /*@ assert perfect_is_ceil: s->perfect ==
            (total_area(&s->pv[0], count) + pow2(BSCHED_MAX_PV) - 1) / pow2(BSCHED_MAX_PV); */
    /*@ assert area_is_total: area(&s->pv[0], count) == total_area(&s->pv[0], count); */
    /*@ assert perfect_is_area: s->perfect ==
            (area(&s->pv[0], count) + pow2(BSCHED_MAX_PV) - 1) / pow2(BSCHED_MAX_PV); */
    return BSCHED_OK;
}

/* Fig. 7, lines 5-12: run the processes whose wait is 0, in the order of
 * order[], at most `perfect` of them, and restart their waits. The contract
 * says the cap never bites when at most `perfect` waits are 0 (bsched_step
 * shows that from the balance theorem). */
/*@ requires \valid(s);
    requires sizes: 1 <= count <= BSCHED_MAX_PROCS && count == s->count && perfect <= count;
    requires pv_range: \forall integer q; 0 <= q < count ==> s->pv[q] <= BSCHED_MAX_PV;
    requires wait_range: \forall integer q; 0 <= q < count ==> s->wait[q] < pow2(s->pv[q]);
    requires slots: \forall integer d; 0 <= d < count ==> s->order[d] < count;
    requires distinct: \forall integer d, e; 0 <= d < e < count ==> s->order[d] != s->order[e];
    requires onto: \forall integer q; 0 <= q < count ==>
        0 <= sorted_pos(&s->pv[0], count, q) < count &&
        s->order[sorted_pos(&s->pv[0], count, q)] == q;
    requires enough: zero_slots(s, count) <= perfect;
    assigns s->ran[0 .. BSCHED_MAX_PROCS - 1], s->wait[0 .. BSCHED_MAX_PROCS - 1];
    ensures counted: \result == \old(zero_slots(s, count));
    ensures ran_were_zero: \forall integer j; 0 <= j < \result ==>
        s->ran[j] < count && \let q = (integer)s->ran[j]; \old(s->wait[q]) == 0;
    ensures zeros_ran: \forall integer q; 0 <= q < count && \old(s->wait[q]) == 0 ==>
        \exists integer j; 0 <= j < \result && s->ran[j] == q;
    ensures restarted: \forall integer q; 0 <= q < count ==>
        s->wait[q] == (\old(s->wait[q]) == 0 ? pow2(s->pv[q]) : \old(s->wait[q]));
*/
static uint32_t run_due(struct bsched *s, uint32_t count, uint32_t perfect)
{
    uint32_t done = 0u;
    uint32_t id;

    /*@ ghost lemma_zero_slots(s, count); */
    /*@ loop invariant 0 <= id <= count;
        loop invariant 0 <= done <= id && done <= perfect;
        loop invariant counted: done == zero_slots{Pre}(s, id);
        loop invariant order_kept: \forall integer d; 0 <= d < count ==> s->order[d] == \at(s->order[d], Pre);
        loop invariant ran_were_zero: \forall integer j; 0 <= j < done ==>
            s->ran[j] < count && \let q = (integer)s->ran[j]; \at(s->wait[q], Pre) == 0;
        loop invariant zeros_ran: \forall integer d; 0 <= d < id && \at(s->wait[s->order[d]], Pre) == 0 ==>
            \exists integer j; 0 <= j < done && s->ran[j] == s->order[d];
        loop invariant visited: \forall integer d; 0 <= d < id ==>
            s->wait[s->order[d]] == (\at(s->wait[s->order[d]], Pre) == 0 ?
                pow2(s->pv[s->order[d]]) : \at(s->wait[s->order[d]], Pre));
        loop invariant not_visited: \forall integer d; id <= d < count ==>
            s->wait[s->order[d]] == \at(s->wait[s->order[d]], Pre);
        loop assigns id, done, s->ran[0 .. BSCHED_MAX_PROCS - 1], s->wait[0 .. BSCHED_MAX_PROCS - 1];
        loop variant count - id;
    */
    for (id = 0u; id < count && done < perfect; id++) {
        uint16_t p = s->order[id];
        if (s->wait[p] == 0u) {
            /*@ assert was_zero: p < count && \let q = (integer)p; \at(s->wait[q], Pre) == 0; */
            s->ran[done] = p;
            done++;
            s->wait[p] = period_of(s->pv[p]);
            /*@ assert ran_kept: \forall integer j; 0 <= j < done - 1 ==>
                    s->ran[j] == \at(s->ran[j], LoopCurrent); */
            /*@ assert ran_new: s->ran[done - 1] == p; */
        }
    }
    /* Stopped early only with `perfect` runs, when no 0 is left. */
    /*@ assert rest_nonzero: \forall integer d; id <= d < count ==>
            \at(s->wait[s->order[d]], Pre) != 0; */
    /*@ assert every_slot: \forall integer q; 0 <= q < count ==>
            (sorted_pos(&s->pv[0], count, q) < id &&
             s->wait[q] == (\at(s->wait[q], Pre) == 0 ? pow2(s->pv[q]) : \at(s->wait[q], Pre)) &&
             (\at(s->wait[q], Pre) == 0 ==> \exists integer j; 0 <= j < done && s->ran[j] == q)) ||
            (sorted_pos(&s->pv[0], count, q) >= id && \at(s->wait[q], Pre) != 0 &&
             s->wait[q] == \at(s->wait[q], Pre)); */
    return done;
}

/*@ requires valid_state: s == \null || \valid(s);
    requires from_init: s != \null && plausible(s) ==> scheduled(s);
    assigns s->wait[0 .. BSCHED_MAX_PROCS - 1], s->ran[0 .. BSCHED_MAX_PROCS - 1],
            s->ran_count, s->cycle;

    behavior null:
      assumes s == \null;
      assigns \nothing;
      ensures \result == BSCHED_ERR_NULL;
    behavior bad_state:
      assumes s != \null && !plausible(s);
      assigns \nothing;
      ensures \result == BSCHED_ERR_STATE;
    behavior ok:
      assumes s != \null && plausible(s);
      ensures ok_count: 0 <= \result <= s->perfect && \result == s->ran_count;
      ensures ok_well_formed: well_formed(s);
      ensures ok_in_phase: in_phase(s);
      ensures ok_sorted: sorted_order(s);
      ensures ok_closed: closed_form(s);
      ensures ok_perfect: s->perfect == perfect_of(&s->pv[0], s->count);
      ensures ok_cycle: s->cycle == (\old(s->cycle) + 1) % pow2(s->maxpv);
      ensures ok_ran_range: \forall integer j; 0 <= j < \result ==> 0 <= s->ran[j] < s->count;
      ensures ok_periodic: \forall integer i; 0 <= i < s->count ==>
          (ran_last(s, i) <==> \old(s->cycle) % pow2(s->pv[i]) == s->offset[i]);
      ensures ok_load: \result == load(&s->pv[0], s->count, \old(s->cycle));
      ensures ok_no_idle: total_area(&s->pv[0], s->count) / pow2(BSCHED_MAX_PV) <= \result;
    complete behaviors;
    disjoint behaviors;
*/
int32_t bsched_step(struct bsched *s)
{
    uint32_t done;
    uint32_t i;
    uint32_t count;
    uint32_t perfect;

    if (s == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!plausible_state(s)) {
        return BSCHED_ERR_STATE;
    }
    count = s->count;
    perfect = s->perfect;
    /*@ ghost uint32_t t = s->cycle; */
    /*@ ghost uint32_t g; */
    /* In phase, a wait is 0 exactly when its process is due in cycle t. */
    /*@ ghost
      /@ loop invariant 0 <= g <= count;
         loop invariant due_is_zero: \forall integer q; 0 <= q < g ==>
             (s->wait[q] == 0 <==> t % pow2(s->pv[q]) == s->offset[q]);
         loop assigns g;
         loop variant count - g;
      @/
      for (g = 0u; g < count; g++) {
        lemma_due_iff_zero(t, s->wait[g], s->offset[g], s->pv[g]);
      }
    */
    /*@ ghost
      /@ loop invariant 0 <= g <= count;
         loop invariant zeros_are_due: zero_slots(s, g) == due_slots(s, t, g);
         loop assigns g;
         loop variant count - g;
      @/
      for (g = 0u; g < count; g++) {
      }
    */
    /* The balance theorem for this cycle: at most `perfect` processes are due
     * (spec/bsched_slots.h, bsched_balance.h, bsched_fold.h), so the cap of
     * run_due never defers one. */
    /*@ ghost lemma_slots_by_class(s, t); */
    /*@ ghost lemma_balance(&s->pv[0], count, t); */
    /*@ ghost lemma_fold(&s->pv[0], count); */
    /*@ assert load_bound: zero_slots(s, count) == due_slots(s, t, count) <= perfect; */
    /*@ assert distinct: \forall integer d, e; 0 <= d < e < count ==> s->order[d] != s->order[e]; */
    done = run_due(s, count, perfect);
    /*@ assert ran_due: \forall integer j; 0 <= j < done ==>
            s->ran[j] < count && \let q = (integer)s->ran[j]; \at(s->wait[q], Pre) == 0; */
    /*@ assert offsets_same: \forall integer q; 0 <= q < count ==> s->offset[q] == \at(s->offset[q], Pre); */
    /*@ assert due_ran: \forall integer q; 0 <= q < count && \at(s->wait[q], Pre) == 0 ==>
            \exists integer j; 0 <= j < done && s->ran[j] == q; */
    /*@ assert ran_due_now: \forall integer j; 0 <= j < done ==>
            s->ran[j] < count && t % pow2(s->pv[s->ran[j]]) == s->offset[s->ran[j]]; */
    /*@ assert periodic_only: \forall integer q; 0 <= q < count ==>
            (\exists integer j; 0 <= j < done && s->ran[j] == q) ==> t % pow2(s->pv[q]) == s->offset[q]; */
    /*@ assert periodic_all: \forall integer q; 0 <= q < count ==>
            t % pow2(s->pv[q]) == s->offset[q] ==> \exists integer j; 0 <= j < done && s->ran[j] == q; */
    /*@ assert order_same: \forall integer d; 0 <= d < count ==> s->order[d] == \at(s->order[d], Pre); */
    /*@ assert waits_positive: \forall integer q; 0 <= q < count ==> 1 <= s->wait[q] <= pow2(s->pv[q]); */
    /* Fig. 7, line 13: every positive wait counts down one cycle (after
     * run_due every wait is positive). */
    /*@ loop invariant 0 <= i <= count;
        loop invariant counted_down: \forall integer q; 0 <= q < i ==>
            s->wait[q] == \at(s->wait[q], LoopEntry) - 1;
        loop invariant not_yet: \forall integer q; i <= q < count ==>
            s->wait[q] == \at(s->wait[q], LoopEntry);
        loop assigns i, s->wait[0 .. BSCHED_MAX_PROCS - 1];
        loop variant count - i;
    */
    for (i = 0u; i < count; i++) {
        if (s->wait[i] > 0u) {
            s->wait[i]--;
        }
    }
    /*@ assert next_waits: \forall integer q; 0 <= q < count ==>
            s->wait[q] == (\at(s->wait[q], Pre) == 0 ? pow2(s->pv[q]) - 1 : \at(s->wait[q], Pre) - 1); */
    s->ran_count = (uint16_t)done;
    s->cycle = (s->cycle + 1u) % period_of(s->maxpv);
    /*@ assert next_phase: \forall integer q; 0 <= q < count ==>
            (s->wait[q] + 1 == pow2(s->pv[q]) && t % pow2(s->pv[q]) == s->offset[q]) ||
            (t + s->wait[q] + 1) % pow2(s->pv[q]) == s->offset[q]; */
    /*@ ghost lemma_next_phase(s, t); */
    /*@ assert order_final: \forall integer d; 0 <= d < count ==> s->order[d] == \at(s->order[d], Pre); */
    /*@ assert sorted_slots_final: \forall integer d; 0 <= d < count ==>
            s->order[d] < count && sorted_pos(&s->pv[0], count, s->order[d]) == d; */
    /*@ assert sorted_procs_final: \forall integer q; 0 <= q < count ==>
            0 <= sorted_pos(&s->pv[0], count, q) < count &&
            s->order[sorted_pos(&s->pv[0], count, q)] == q; */
    return (int32_t)done;
}

/* Not analysed by WP: the process bodies are called through a pointer, which
 * WP cannot follow without a `calls` clause; make prove skips it (README "Proofs"). */
int32_t bsched_run_cycle(struct bsched *s, bsched_process_fn run, void *context)
{
    int32_t ran;
    uint32_t k;

    if (run == NULL) {
        return BSCHED_ERR_NULL;
    }
    ran = bsched_step(s);
    for (k = 0u; ran > 0 && k < (uint32_t)ran; k++) {
        run(context, s->ran[k]);
    }
    return ran;
}

/*@ requires valid_state: s == \null || \valid_read(s);
    requires from_init: s != \null && plausible(s) ==> well_formed(s);
    requires valid_due: due == \null || (s != \null && plausible(s) ==> \valid(due + (0 .. s->perfect - 1)));
    requires separated: s != \null && due != \null && plausible(s) ==>
        \separated(s, due + (0 .. s->perfect - 1));
    assigns due[0 .. BSCHED_MAX_PROCS - 1];

    behavior null:
      assumes s == \null || due == \null;
      assigns \nothing;
      ensures \result == BSCHED_ERR_NULL;
    behavior bad_state:
      assumes s != \null && due != \null && !plausible(s);
      assigns \nothing;
      ensures \result == BSCHED_ERR_STATE;
    behavior ok:
      assumes s != \null && due != \null && plausible(s);
      assigns due[0 .. s->perfect - 1];
      ensures ok_count: 0 <= \result <= s->perfect;
      ensures ok_due_range: \forall integer j; 0 <= j < \result ==> 0 <= due[j] < s->count;
    complete behaviors;
    disjoint behaviors;
*/
int32_t bsched_due(const struct bsched *s, uint32_t ahead, uint16_t *due)
{
    uint32_t done = 0u;
    uint32_t id;
    uint32_t count;
    uint32_t perfect;

    if (s == NULL || due == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!plausible_state(s)) {
        return BSCHED_ERR_STATE;
    }
    count = s->count;
    perfect = s->perfect;
    /* wait < 2^pv always, so p is due `ahead` cycles on iff wait == ahead mod 2^pv. */
    /*@ loop invariant 0 <= id <= count;
        loop invariant 0 <= done <= id && done <= perfect;
        loop invariant \forall integer j; 0 <= j < done ==> 0 <= due[j] < count;
        loop invariant \forall integer d; 0 <= d < count ==>
            s->order[d] == \at(s->order[d], Pre) && s->pv[s->order[d]] == \at(s->pv[s->order[d]], Pre);
        loop assigns id, done, due[0 .. perfect - 1];
        loop variant count - id;
    */
    for (id = 0u; id < count && done < perfect; id++) {
        uint16_t p = s->order[id];
        if (s->wait[p] == ahead % period_of(s->pv[p])) {
            due[done] = p;
            done++;
        }
    }
    return (int32_t)done;
}
