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
#include "spec/bsched_step.h"
#include "spec/bsched_word.h"

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
static uint32_t period_of(uint32_t pv)
{
    /*@ ghost lemma_pow2(BSCHED_MAX_PV); */
    return (uint32_t)1u << pv;
}

/* Class k's key of the residue test (bsched.h): ((2^k - start) mod 2^k) * 2^(31-k). */
/*@ requires k <= BSCHED_MAX_PV && start < pow2(k);
    assigns \nothing;
    ensures key: \result == class_key_of(start, k);
*/
static uint32_t class_key(uint32_t start, uint32_t k)
{
    uint32_t unit = period_of((uint32_t)BSCHED_MAX_PV - k);
    /*@ ghost
      lemma_pow2(BSCHED_MAX_PV);
      uint64_t pk = (uint64_t)1 << k;
    */
    /*@ assert pk_is: pk == pow2(k); */
    /*@ ghost word_init((int)k, pk, unit, start); */
    /* (2^k - start) mod 2^k times 2^(31-k), in fewer instructions (spec/bsched_word.h). */
    return (0x80000000u - start * unit) % 0x80000000u;
}

/* Class k's limit of the residue test (bsched.h): min(size, 2^k) * 2^(31-k);
 * 0 for an empty class, which then never passes the test. */
/*@ requires k <= BSCHED_MAX_PV;
    assigns \nothing;
    ensures limit: \result == class_limit_of(size, k);
*/
static uint32_t class_limit(uint32_t size, uint32_t k)
{
    uint32_t period = period_of(k);
    uint32_t unit = period_of((uint32_t)BSCHED_MAX_PV - k);
    uint32_t in_use = size < period ? size : period;
    /*@ ghost word_init((int)k, period, unit, in_use); */
    return in_use * unit;
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
      ensures ok_count: s->count == count && s->cycle == 0 && s->ran_count == 0 && s->reversed == 0;
      ensures ok_maxpv: s->maxpv == max_pv{Pre}(pv, count);
      ensures ok_pv: \forall integer i; 0 <= i < count ==> s->pv[i] == pv[i];
      ensures ok_closed_form: \forall integer i; 0 <= i < count ==>
          s->offset[i] == init_wait{Pre}(pv, count, i);
      ensures ok_offset_range: \forall integer i; 0 <= i < count ==> s->offset[i] < pow2(pv[i]);
      ensures ok_minpv: \forall integer i; 0 <= i < count ==> s->minpv <= pv[i];
      ensures ok_class_table: class_table(s);
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
    uint32_t minpv;
    uint32_t pvk;
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
    /*@ assert maxpv_pre: maxpv == \at(max_pv(pv, count), Pre) <= BSCHED_MAX_PV; */
    /* The class table of bsched_step, before place_processes moves the cursors. */
    /*@ ghost lemma_first(pv, count); */
    /*@ loop invariant 0 <= pvk <= BSCHED_MAX_PV + 1;
        loop invariant table_first: \forall integer j; 0 <= j < pvk ==>
            s->class_first[j] == class_first(pv, count, j);
        loop invariant table_size: \forall integer j; 0 <= j < pvk ==>
            s->class_size[j] == class_count(pv, count, j);
        loop invariant table_key: \forall integer j; 0 <= j < pvk ==>
            s->class_key[j] == class_key_of(class_start(pv, count, j), j);
        loop invariant table_limit: \forall integer j; 0 <= j < pvk ==>
            s->class_limit[j] == class_limit_of(class_count(pv, count, j), j);
        loop assigns pvk, s->class_first[0 .. BSCHED_MAX_PV], s->class_size[0 .. BSCHED_MAX_PV],
            s->class_key[0 .. BSCHED_MAX_PV], s->class_limit[0 .. BSCHED_MAX_PV];
        loop variant BSCHED_MAX_PV + 1 - pvk;
    */
    for (pvk = 0u; pvk <= BSCHED_MAX_PV; pvk++) {
        /*@ assert first_bound: classes.next[pvk] == class_first(pv, count, pvk) <= count; */
        /*@ assert size_bound: classes.size[pvk] == class_count(pv, count, pvk) <= count; */
        /*@ assert start_bound: classes.cursor[pvk] == class_start(pv, count, pvk) < pow2(pvk); */
        s->class_first[pvk] = classes.next[pvk];
        s->class_size[pvk] = classes.size[pvk];
        s->class_key[pvk] = class_key(classes.cursor[pvk], pvk);
        s->class_limit[pvk] = class_limit(classes.size[pvk], pvk);
        /*@ assert stored: s->class_first[pvk] == class_first(pv, count, pvk) &&
                s->class_size[pvk] == class_count(pv, count, pvk) &&
                s->class_key[pvk] == class_key_of(class_start(pv, count, pvk), pvk) &&
                s->class_limit[pvk] == class_limit_of(class_count(pv, count, pvk), pvk); */
    }
    place_processes(s, &classes, pv, count);
    /* The order in terms of the input as it was on entry: what sorted_slots below
     * needs, stated where little else is known. */
    /*@ assert order_pre: \forall integer d; 0 <= d < n ==>
            s->order[d] < n && \let x = s->order[d]; \at(sorted_pos(pv, count, x), Pre) == d; */
    perfect = perfect_load(&classes, pv, count);
    minpv = maxpv;
    /*@ loop invariant 0 <= i <= n;
        loop invariant \forall integer j; 0 <= j < i ==> s->pv[j] == pv[j];
        loop invariant copied_pre: \forall integer j; 0 <= j < i ==> s->pv[j] == \at(pv[j], Pre);
        loop invariant minpv_is_min: minpv <= maxpv && \forall integer j; 0 <= j < i ==> minpv <= pv[j];
        loop invariant offsets_kept: \forall integer j; 0 <= j < n ==>
            s->offset[j] == init_wait{Pre}(pv, count, j);
        loop assigns i, minpv, s->pv[0 .. n - 1];
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        s->pv[i] = pv[i];
        if (pv[i] < minpv) {
            minpv = pv[i];
        }
    }
    /*@ assert pv_copied_loop: \forall integer j; 0 <= j < n ==> s->pv[j] == \at(pv[j], Pre); */
    s->perfect = (uint16_t)perfect;
    s->count = (uint16_t)count;
    s->maxpv = (uint8_t)maxpv;
    s->minpv = (uint8_t)minpv;
    s->cycle = 0u;
    s->reversed = 0u;
    s->ran_count = 0u;
    /* ok_maxpv where s->maxpv was just written (at the end it is a slow goal). */
    /*@ assert maxpv_stored: s->maxpv == \at(max_pv(pv, count), Pre); */
    /*@ assert wf_sizes: 1 <= s->count <= BSCHED_MAX_PROCS && s->maxpv <= BSCHED_MAX_PV &&
            1 <= s->perfect <= s->count && s->cycle < pow2(s->maxpv); */
    /*@ assert wf_procs: \forall integer j; 0 <= j < s->count ==>
            s->pv[j] <= s->maxpv && s->offset[j] < pow2(s->pv[j]); */
    /*@ assert wf_order: \forall integer id; 0 <= id < s->count ==> s->order[id] < s->count; */
    /* s->pv is a copy of pv, so the class layout of s->pv is that of pv. */
    /*@ assert pv_copied: \forall integer j; 0 <= j < n ==> (&s->pv[0])[j] == \at(pv[j], Pre); */
    /* The class layout of the copy: sizes, first slots and starts, one invariant
     * each (together, same_first and same_start were one goal that only CVC5
     * proved under x86_64 and no prover proved under -machdep x86_32). The asserts
     * in the second loop's body are the steps of same_start, class_start unfolded
     * once on each side: without them its preservation is slow (CVC4 times out). */
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
         loop invariant same_sizes: \forall integer k0; 0 <= k0 <= BSCHED_MAX_PV ==>
             class_count(&s->pv[0], count, k0) == \at(class_count(pv, count, k0), Pre);
         loop invariant same_first: \forall integer k0; 0 <= k0 <= k ==>
             class_first(&s->pv[0], count, k0) == \at(class_first(pv, count, k0), Pre);
         loop invariant same_start: \forall integer k0; 0 <= k0 <= k ==>
             class_start(&s->pv[0], count, k0) == \at(class_start(pv, count, k0), Pre);
         loop invariant start_sum: \forall integer k0; 0 <= k0 < k ==>
             class_start(&s->pv[0], count, k0) + class_count(&s->pv[0], count, k0) ==
             \at(class_start(pv, count, k0) + class_count(pv, count, k0), Pre);
         loop assigns k;
         loop variant BSCHED_MAX_PV + 1 - k;
      @/
      while (k < BSCHED_MAX_PV + 1) {
        /@ assert sum_at_k: \let j = k; class_start(&s->pv[0], count, j) +
               class_count(&s->pv[0], count, j) ==
               \at(class_start(pv, count, j) + class_count(pv, count, j), Pre); @/
        /@ assert unfold_here: class_start(&s->pv[0], count, k + 1) ==
               2 * ((class_start(&s->pv[0], count, k) + class_count(&s->pv[0], count, k)) % pow2(k)); @/
        /@ assert unfold_pre: \let j = k; \at(class_start(pv, count, j + 1), Pre) ==
               2 * (\at(class_start(pv, count, j) + class_count(pv, count, j), Pre) % pow2(j)); @/
        /@ assert start_next: \let j = k + 1; class_start(&s->pv[0], count, j) ==
               \at(class_start(pv, count, j), Pre); @/
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
    /* order_pre again, here: with it, sorted_slots is a quick goal instead of a slow one. */
    /*@ assert order_late: \forall integer d; 0 <= d < n ==>
            s->order[d] < n && \let x = s->order[d]; \at(sorted_pos(pv, count, x), Pre) == d; */
    /*@ assert sorted_slots: \forall integer d; 0 <= d < n ==>
            s->order[d] < n && sorted_pos(&s->pv[0], count, s->order[d]) == d; */
    /*@ assert sorted_procs: \forall integer j; 0 <= j < n ==>
            0 <= sorted_pos(&s->pv[0], count, j) < n && s->order[sorted_pos(&s->pv[0], count, j)] == j; */
    /*@ assert closed: \forall integer j; 0 <= j < n ==>
            s->offset[j] == init_wait(&s->pv[0], count, j); */
    /* ok_closed_form in the ensures' own terms: with it the ensures is a quick goal
     * (without it, a slow one). */
    /*@ assert closed_pre: \forall integer i; 0 <= i < count ==>
            s->offset[i] == \at(init_wait(pv, count, i), Pre); */
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
    /*@ assert same_table: \forall integer k0; 0 <= k0 <= BSCHED_MAX_PV ==>
            s->class_first[k0] == class_first(&s->pv[0], count, k0) &&
            s->class_size[k0] == class_count(&s->pv[0], count, k0) &&
            s->class_key[k0] == class_key_of(class_start(&s->pv[0], count, k0), k0) &&
            s->class_limit[k0] == class_limit_of(class_count(&s->pv[0], count, k0), k0); */
    /*@ assert table: class_table(s); */
    /*@ ghost lemma_rev_zero(); */
    /*@ assert counter: s->reversed == rev(s->maxpv, s->cycle); */
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

/* Writes the class members j0, j0 + p, j0 + 2p, ... below size of the class
 * whose first slot is `first` (order[first + j]) to to[0], to[1], ...;
 * returns the pointer past the last one written. A function of its own so
 * that WP proves the walk in a small context (inside collect_due, every goal
 * of the loop carried all of collect_due's facts and timed out). A pointer,
 * not an index, so that the copy is one move and one step per member on the
 * CPU32 (measured: 4 instructions a member, 5 with an index). */
/*@ requires p_range: 1 <= p <= 2147483648;
    requires walk_range: j0 < size && first + size <= BSCHED_MAX_PROCS;
    requires fits: done + (size - 1 - j0) / p < 65535;
    requires at: to == out + done;
    requires \valid_read(order + (0 .. BSCHED_MAX_PROCS - 1));
    requires room: \valid(out + (done .. done + (size - 1 - j0) / p));
    requires \separated(out + (done .. done + (size - 1 - j0) / p), order + (0 .. BSCHED_MAX_PROCS - 1));
    assigns out[done .. done + (size - 1 - j0) / p];
    ensures count: \result == out + (done + (size - 1 - j0) / p + 1);
    ensures emitted_at: \forall integer x; done <= x <= done + (size - 1 - j0) / p ==>
        out[x] == \old(order[first + (j0 + (x - done) * p)]);
*/
static uint16_t *emit_members(uint16_t *to, const uint16_t *order,
                              uint_fast32_t first, uint_fast32_t j0, uint_fast32_t size, uint_fast32_t p)
    /*@ ghost (uint16_t *out, size_t done) */
{
    /* At least 32-bit slots, not size_t: p is up to 2^31 and size_t may be 16
     * bits (AVR); slot + p stays below 2^32 as slot < first + size <= 65535.
     * "fast": on x86-64 the index then needs no zero extension. */
    uint_fast32_t slot = first + j0;
    uint_fast32_t end = first + size;
    uint16_t *next = to;
    /*@ ghost
      int64_t cnt = ((int64_t)size - 1 - (int64_t)j0) / (int64_t)p + 1;
      int64_t m = 0;
      step_count_members((int64_t)p, (int64_t)j0, (int64_t)size, cnt);
    */
    /*@ loop invariant walk: 0 <= m < cnt && slot == first + (j0 + m * p) && slot < end;
        loop invariant counted: next == out + (done + m);
        loop invariant kept: \forall integer d; 0 <= d < BSCHED_MAX_PROCS ==> order[d] == \at(order[d], Pre);
        loop invariant emitted: \forall integer x; done <= x < done + m ==>
            out[x] == \at(order[first + (j0 + (x - done) * p)], Pre);
        loop assigns slot, next, m, out[done .. done + (size - 1 - j0) / p];
        loop variant end - slot;
    */
    do {
        /*@ assert in_room: m <= (size - 1 - j0) / p; */
        /*@ assert read_old: \let d = first + (j0 + m * p); d == slot && order[d] == \at(order[d], Pre); */
        *next = order[slot];
        /*@ assert wrote_new: \let d = first + (j0 + m * p); out[done + m] == \at(order[d], Pre); */
        /*@ assert wrote_old: \forall integer x; done <= x < done + m ==>
                out[x] == \at(order[first + (j0 + (x - done) * p)], Pre); */
        /*@ assert wrote_kept: \forall integer d; 0 <= d < BSCHED_MAX_PROCS ==> order[d] == \at(order[d], Pre); */
        next++;
        /*@ assert no_wrap: slot + p < 4294967296; */
        slot += p;
        /*@ ghost m = m + 1; */
        /*@ assert next_slot: slot == first + (j0 + m * p); */
    } while (slot < end);
    /*@ assert all: m == cnt; */
    return next;
}

/* Class k's processes due in minor cycle t, written in execution order through
 * the cursor `to` (out + done); returns the cursor past them. With
 * top = rev_k(t mod 2^k), member j of the class is due iff j == j0 (mod 2^k) with
 * j0 = (top + 2^k - s_k) mod 2^k, so the due members are j0, j0 + 2^k, ... below
 * the class size (spec/bsched_step.h). word = rev_maxpv(t) * 2^(31-maxpv) has
 * top in the top k of its 31 bits, so (word + class_key[k]) mod 2^31 has j0
 * there, and is at least class_limit[k] when j0 is not below the class size
 * (spec/bsched_word.h): an add, a mask and a compare for a class with nothing
 * due. 31 bits, not 32: WP cannot reason about a 32-bit wrap.
 * A function of its own so that its proof sees one class's facts, not the
 * whole of collect_due's loop. */
/* out[] may lie in *s (bsched_step passes s->ran): the state's 16-bit fields
 * are read in the pre-state (\old) in the postconditions. */
/*@ requires valid: \valid_read(s) && \valid(out + (done .. s->perfect - 1)) && to == out + done;
    requires separated: \separated(out + (done .. s->perfect - 1), &s->count, &s->perfect,
        &s->pv[0 .. BSCHED_MAX_PROCS - 1], &s->offset[0 .. BSCHED_MAX_PROCS - 1],
        &s->order[0 .. BSCHED_MAX_PROCS - 1], &s->class_first[0 .. BSCHED_MAX_PV],
        &s->class_size[0 .. BSCHED_MAX_PV], &s->class_key[0 .. BSCHED_MAX_PV],
        &s->class_limit[0 .. BSCHED_MAX_PV]);
    requires k_range: k <= BSCHED_MAX_PV && 1 <= pow2(k) <= 2147483648 && (1 << k) == pow2(k);
    requires count: s->count <= BSCHED_MAX_PROCS && done <= s->perfect <= BSCHED_MAX_PROCS;
    requires table: s->class_first[k] == class_first(&s->pv[0], s->count, k) &&
        s->class_size[k] == class_count(&s->pv[0], s->count, k) &&
        class_first(&s->pv[0], s->count, k + 1) == s->class_first[k] + s->class_size[k] &&
        s->class_first[k] + s->class_size[k] <= s->count &&
        s->class_key[k] == class_key_of(class_start(&s->pv[0], s->count, k), k) &&
        s->class_limit[k] == class_limit_of(class_count(&s->pv[0], s->count, k), k);
    requires start: start_area_at(s, k);
    requires top: top == rev(k, t % pow2(k)) && 0 <= top < pow2(k);
    requires word: word == top * pow2(31 - k) + low && 0 <= low < pow2(31 - k) && unit == pow2(31 - k);
    requires due: class_due_at(s, s->count, t, k) && class_member_due_at(s, t, k);
    requires room: done + walk_hits(class_area(&s->pv[0], s->count, k), s->class_size[k], top, pow2(k)) <=
        s->perfect;
    assigns out[done .. s->perfect - 1];
    ensures counted: \result == out + (done + walk_hits(class_area(&s->pv[0], \old(s->count), k),
        \old(s->class_size[k]), top, pow2(k)));
    ensures listed: \forall integer x; done <= x < \result - out ==>
        out[x] < \old(s->count) && t % pow2(s->pv[out[x]]) == s->offset[out[x]];
    ensures all: \forall integer d; \old(s->class_first[k]) <= d < \old(s->class_first[k] + s->class_size[k]) &&
        t % pow2(s->pv[\old(s->order[d])]) == s->offset[\old(s->order[d])] ==>
        \exists integer x; done <= x < \result - out && out[x] == \old(s->order[d]);
    ensures grows: done <= \result - out;
    ensures below: \forall integer x; 0 <= x < done ==> out[x] == \old(out[x]);
    ensures kept: s->count == \old(s->count) && s->perfect == \old(s->perfect) &&
        (\forall integer d; 0 <= d < BSCHED_MAX_PROCS ==> s->order[d] == \old(s->order[d])) &&
        (\forall integer j; 0 <= j <= BSCHED_MAX_PV ==>
            s->class_first[j] == \old(s->class_first[j]) && s->class_size[j] == \old(s->class_size[j]));
*/
static uint16_t *collect_class(const struct bsched *s, uint32_t k, uint32_t word, uint16_t *to)
    /*@ ghost (uint32_t t, uint32_t top, uint32_t low, uint64_t unit, uint16_t *out, size_t done) */
{
    uint32_t period = period_of(k);
    uint32_t first = s->class_first[k];
    uint32_t size = s->class_size[k];
    /* No wrap: word and key are below 2^31 each. */
    uint32_t x = (word + s->class_key[k]) % 0x80000000u;
    /*@ ghost
      int64_t area = slots_area(s->pv, s->count, (int)k);
    */
    /*@ assert area_is: area == class_area(&s->pv[0], s->count, k) &&
            class_start(&s->pv[0], s->count, k) == area % period; */
    /*@ ghost
      int64_t lead = (int64_t)period - area % (int64_t)period;
      int64_t slot = ((int64_t)top + lead) % (int64_t)period;
      int64_t q = area / (int64_t)period + 1 - ((int64_t)top + lead) / (int64_t)period;
      step_class_walk(period, area, top, lead, size, slot, q);
      word_slot((int)k, period, unit, word, top, low,
                (uint64_t)(area % (int64_t)period), size, s->class_key[k], s->class_limit[k]);
      word_lsr();
    */
    /*@ assert slot_is: slot == (top + pow2(k) - class_start(&s->pv[0], s->count, k)) % pow2(k); */
    /*@ ghost size_t next = done; */
    if (x < s->class_limit[k]) {
        uint32_t j0 = x >> ((uint32_t)BSCHED_MAX_PV - k);
        /*@ assert j0_is: j0 == slot < size; */
        /*@ assert fits: done + (size - 1 - j0) / period < s->perfect; */
        to = emit_members(to, s->order, first, j0, size, period) /*@ ghost (out, done) */;
        /*@ assert to_is: to == out + (done + (size - 1 - j0) / period + 1); */
        /*@ ghost next = (size_t)(to - out); */
        /*@ assert next_is: next == done + (size - 1 - j0) / period + 1; */
        /*@ assert to_next: to == out + next; */
        /*@ assert emitted_to: \let f = first; \let j = j0; \let p = period;
                \forall integer x; done <= x < next ==> out[x] == \at(s->order[f + (j + (x - done) * p)], Pre); */
    }
    /*@ assert at_next: to == out + next; */
    /*@ assert hits: next == done + walk_hits(area, size, top, period); */
    /*@ assert walked: \forall integer x; done <= x < next ==>
            walk_residue(area, slot, period, top, size, x - done); */
    /*@ assert emitted: \let f = first; \let j0 = slot; \let p = period;
            \forall integer x; done <= x < next ==> out[x] == \at(s->order[f + (j0 + (x - done) * p)], Pre); */
    /*@ assert listed: \let f = first; \let j0 = slot; \let p = period; \forall integer x; done <= x < next ==>
            walk_residue(area, j0, p, top, size, x - done) &&
            out[x] == \at(s->order[f + (j0 + (x - done) * p)], Pre) &&
            out[x] < \at(s->count, Pre) && t % pow2(s->pv[out[x]]) == s->offset[out[x]]; */
    /*@ assert all: \forall integer d; first <= d < first + size &&
            residue_at(area, period, top, d - first) ==>
            \let m = (area + (d - first)) / period - q;
            walk_index(d - first, slot, period, m, walk_hits(area, size, top, period)) &&
            done <= done + m < next && out[done + m] == \at(s->order[d], Pre); */
    return to;
}

/* rev_maxpv(t) aligned to bit 31: its top k bits are rev_k(t mod 2^k). A
 * function of its own so that WP drops the cast of 31 - maxpv in a small
 * context (inside collect_due it timed out); GCC inlines it. */
/*@ requires maxpv <= BSCHED_MAX_PV && reversed < pow2(maxpv);
    assigns \nothing;
    ensures word: \result == reversed * pow2(31 - maxpv) < 2147483648;
*/
static uint32_t aligned_word(uint32_t reversed, uint32_t maxpv)
{
    /*@ ghost
      int m = (int)maxpv;
      uint64_t f = word_pow2_of(BSCHED_MAX_PV - m);
      word_top(m, m, reversed, 1, f);
    */
    /*@ assert small: reversed * pow2(31 - maxpv) < 2147483648; */
    return reversed * period_of((uint32_t)BSCHED_MAX_PV - maxpv);
}

/* The processes due in minor cycle t, in execution order, into out[], from
 * reversed = rev_maxpv(t): class by class upwards (collect_class), where
 * rev_k(t mod 2^k) is the top k of the maxpv bits of `reversed`
 * (spec/bsched_step.h). Returns how many: load(t), at most `perfect` (the
 * balance theorem), so Fig. 7's cap is not needed. */
/* out[] may lie in *s (bsched_step passes s->ran), so the writes to it change
 * the memory of the state's other 16-bit fields for the provers: every fact
 * about order[] is stated in the pre-state (label Pre), and the fields read
 * are shown unchanged (kept). */
/*@ requires valid: \valid_read(s) && \valid(out + (0 .. s->perfect - 1));
    requires state: well_formed(s) && sorted_order(s) && closed_form(s) && class_table(s) &&
        s->perfect == perfect_of(&s->pv[0], s->count);
    requires separated: \separated(out + (0 .. s->perfect - 1), &s->count, &s->maxpv, &s->minpv,
        &s->perfect, &s->pv[0 .. BSCHED_MAX_PROCS - 1], &s->offset[0 .. BSCHED_MAX_PROCS - 1],
        &s->order[0 .. BSCHED_MAX_PROCS - 1], &s->class_first[0 .. BSCHED_MAX_PV],
        &s->class_size[0 .. BSCHED_MAX_PV], &s->class_key[0 .. BSCHED_MAX_PV],
        &s->class_limit[0 .. BSCHED_MAX_PV], &s->cycle, &s->reversed);
    requires counter: reversed == rev(s->maxpv, t);
    assigns out[0 .. s->perfect - 1];
    ensures load: \result == load(&s->pv[0], \old(s->count), t) == \old(due_slots(s, t, s->count));
    ensures bound: \result <= \old(s->perfect);
    ensures listed_due: \forall integer x; 0 <= x < \result ==>
        out[x] < \old(s->count) && t % pow2(s->pv[out[x]]) == s->offset[out[x]];
    ensures due_listed: \forall integer i; 0 <= i < \old(s->count) &&
        t % pow2(s->pv[i]) == s->offset[i] ==> \exists integer x; 0 <= x < \result && out[x] == i;
    ensures kept: s->count == \old(s->count) && s->perfect == \old(s->perfect) &&
        (\forall integer d; 0 <= d < BSCHED_MAX_PROCS ==> s->order[d] == \old(s->order[d])) &&
        (\forall integer j; 0 <= j <= BSCHED_MAX_PV ==>
            s->class_first[j] == \old(s->class_first[j]) && s->class_size[j] == \old(s->class_size[j]));
*/
static uint32_t collect_due(const struct bsched *s, uint32_t reversed, uint16_t *out)
    /*@ ghost (uint32_t t) */
{
    uint16_t *to = out;
    uint32_t maxpv = s->maxpv;
    uint32_t word;
    uint32_t k;
    ptrdiff_t emitted; /* to - out: the processes written */

    /*@ ghost
      uint32_t n = s->count;
      size_t done = 0u;
      step_collect_facts((struct bsched *)s, t, reversed);
      word_pow2();
    */
    /*@ assert n_is: n == \at(s->count, Pre); */
    /*@ assert rev_range: 0 <= reversed < pow2(maxpv) && maxpv <= BSCHED_MAX_PV; */
    /*@ ghost int m = (int)maxpv; */
    /*@ assert m_is: m == maxpv; */
    /*@ ghost uint64_t f = word_pow2_of(BSCHED_MAX_PV - m); */
    /*@ assert f_is: f == pow2(31 - maxpv) && pow2(0) == 1; */
    /*@ ghost word_top(m, m, reversed, 1, f); */
    /*@ assert word_small: reversed * pow2(31 - maxpv) < 2147483648; */
    word = aligned_word(reversed, maxpv);
    k = s->minpv;
    /*@ ghost int gap = m - (int)s->minpv; */
    /*@ loop invariant k_range: s->minpv <= k <= maxpv && gap == maxpv - k && m == maxpv;
        loop invariant word_kept: f == pow2(31 - maxpv) && 0 <= reversed < pow2(maxpv) && maxpv <= BSCHED_MAX_PV &&
            word == reversed * pow2(31 - maxpv);
        loop invariant at_done: to == out + done && done <= \at(s->perfect, Pre);
        loop invariant kept: s->count == \at(s->count, Pre) && s->perfect == \at(s->perfect, Pre);
        loop invariant kept_order: \forall integer d; 0 <= d < BSCHED_MAX_PROCS ==> s->order[d] == \at(s->order[d], Pre);
        loop invariant kept_first: \forall integer j; 0 <= j <= BSCHED_MAX_PV ==>
                s->class_first[j] == \at(s->class_first[j], Pre);
        loop invariant kept_size: \forall integer j; 0 <= j <= BSCHED_MAX_PV ==>
                s->class_size[j] == \at(s->class_size[j], Pre);
        loop invariant counted: done == due_slots{Pre}(s, t, class_first(&s->pv[0], n, k));
        loop invariant listed_due: \forall integer x; 0 <= x < done ==>
            out[x] < n && t % pow2(s->pv[out[x]]) == s->offset[out[x]];
        loop invariant due_listed: \forall integer d; 0 <= d < class_first(&s->pv[0], n, k) &&
            t % pow2(s->pv[\at(s->order[d], Pre)]) == s->offset[\at(s->order[d], Pre)] ==>
            \exists integer x; 0 <= x < done && out[x] == \at(s->order[d], Pre);
        loop assigns k, gap, done, to, out[0 .. \at(s->perfect, Pre) - 1];
        loop variant maxpv - k;
    */
    do {
        /*@ assert facts: top_at(reversed, maxpv, t, k) && start_area_at{Pre}(s, k) &&
                class_hits_at{Pre}(s, t, k) && class_due_at{Pre}(s, n, t, k); */
        /*@ assert member_facts: class_member_due_at{Pre}(s, t, k); */
        /*@ assert order_same: \forall integer d; class_first(&s->pv[0], n, k) <= d < class_first(&s->pv[0], n, k + 1) ==>
                s->order[d] == \at(s->order[d], Pre) && s->count == \at(s->count, Pre); */
        /*@ assert frame_due_at_pre: \forall integer d; class_first(&s->pv[0], \at(s->count, Pre), k) <= d <
                class_first(&s->pv[0], \at(s->count, Pre), k + 1) ==>
                \at(s->order[d], Pre) < \at(s->count, Pre) &&
                (t % pow2(s->pv[\at(s->order[d], Pre)]) == s->offset[\at(s->order[d], Pre)] <==>
                 residue_at(class_area(&s->pv[0], \at(s->count, Pre), k), pow2(k), rev(k, t % pow2(k)),
                            d - class_first(&s->pv[0], \at(s->count, Pre), k))); */
        /*@ assert frame_due_pre: \forall integer d; class_first(&s->pv[0], n, k) <= d <
                class_first(&s->pv[0], n, k + 1) ==>
                \at(s->order[d], Pre) < n &&
                (t % pow2(s->pv[\at(s->order[d], Pre)]) == s->offset[\at(s->order[d], Pre)] <==>
                 residue_at(class_area(&s->pv[0], n, k), pow2(k), rev(k, t % pow2(k)),
                            d - class_first(&s->pv[0], n, k))); */
        /*@ assert frame_due_order: \forall integer d; class_first(&s->pv[0], n, k) <= d <
                class_first(&s->pv[0], n, k + 1) ==>
                s->order[d] < n &&
                (t % pow2(s->pv[s->order[d]]) == s->offset[s->order[d]] <==>
                 residue_at(class_area(&s->pv[0], n, k), pow2(k), rev(k, t % pow2(k)),
                            d - class_first(&s->pv[0], n, k))); */
        /*@ assert frame_due: class_due_at(s, n, t, k); */
        /* class_member_due_at{Pre} moved to the current state in two steps, each
         * small enough for the provers among this loop's hypotheses. */
        /*@ assert member_pre: \forall integer j; 0 <= j < class_count(&s->pv[0], n, k) &&
                residue_at(class_area(&s->pv[0], n, k), pow2(k), rev(k, t % pow2(k)), j) ==>
                \let d = class_first(&s->pv[0], n, k) + j;
                \at(s->order[d], Pre) < n &&
                t % pow2(s->pv[\at(s->order[d], Pre)]) == s->offset[\at(s->order[d], Pre)]; */
        /*@ assert member_in: \forall integer j; 0 <= j < class_count(&s->pv[0], n, k) ==>
                class_first(&s->pv[0], n, k) <= class_first(&s->pv[0], n, k) + j < class_first(&s->pv[0], n, k + 1); */
        /*@ assert member_order: \forall integer j; 0 <= j < class_count(&s->pv[0], n, k) &&
                residue_at(class_area(&s->pv[0], n, k), pow2(k), rev(k, t % pow2(k)), j) ==>
                \let d = class_first(&s->pv[0], n, k) + j;
                s->order[d] < n && t % pow2(s->pv[s->order[d]]) == s->offset[s->order[d]]; */
        /*@ assert count_same: s->count == n; */
        /*@ assert frame_member: class_member_due_at(s, t, k); */
        /*@ assert frame_start: start_area_at(s, k); */
        /*@ assert room: done + walk_hits(class_area(&s->pv[0], n, k), s->class_size[k], rev(k, t % pow2(k)), pow2(k)) ==
                due_slots{Pre}(s, t, class_first(&s->pv[0], n, k + 1)) <= s->perfect; */
        /*@ ghost
          uint64_t e = word_pow2_of(gap);
        */
        /*@ assert e_is: e == pow2(maxpv - k); */
        /*@ ghost word_top(m, m - gap, reversed, e, f); */
        /*@ assert ef: e * f == pow2(31 - k) && reversed % e * f < pow2(31 - k); */
        /*@ ghost
          uint32_t top = word_top_of(m, m - gap, reversed);
          uint32_t low = word_low_of(m, m - gap, reversed);
        */
        /*@ assert word_is: word == top * pow2(31 - k) + low && 0 <= low < pow2(31 - k); */
        /*@ assert top_is: top == rev(k, t % pow2(k)) && 0 <= top < pow2(k); */
        /*@ ghost size_t done0 = done; */
        to = collect_class(s, k, word, to) /*@ ghost (t, top, low, e * f, out, done) */;
        /* order[] after the call, said once: the preserved `kept_order` and the
         * postcondition `kept` then follow at once (each was slow on its own;
         * this assertion pays the cost once, the frame of the call among this
         * loop's hypotheses). */
        /*@ assert order_kept: \forall integer d; 0 <= d < BSCHED_MAX_PROCS ==> s->order[d] == \at(s->order[d], Pre); */
        /*@ ghost done = (size_t)(to - out); */
        /*@ assert counted_next: done == due_slots{Pre}(s, t, class_first(&s->pv[0], n, k + 1)); */
        /*@ assert listed_old: \forall integer d; 0 <= d < class_first(&s->pv[0], n, k) &&
                t % pow2(s->pv[\at(s->order[d], Pre)]) == s->offset[\at(s->order[d], Pre)] ==>
                \exists integer x; 0 <= x < done0 && out[x] == \at(s->order[d], Pre); */
        /*@ assert listed_class: \forall integer d; class_first(&s->pv[0], n, k) <= d < class_first(&s->pv[0], n, k + 1) &&
                t % pow2(s->pv[\at(s->order[d], Pre)]) == s->offset[\at(s->order[d], Pre)] ==>
                \exists integer x; done0 <= x < done && out[x] == \at(s->order[d], Pre); */
        /*@ assert grows_first: 0 <= class_first(&s->pv[0], n, k) <= class_first(&s->pv[0], n, k + 1) <= n; */
        /*@ assert grows: done0 <= done; */
        /*@ assert grows_mono: due_slots{Pre}(s, t, class_first(&s->pv[0], n, k)) <=
                due_slots{Pre}(s, t, class_first(&s->pv[0], n, k + 1)); */
        /*@ assert listed_next_int: \forall integer d; 0 <= d < class_first(&s->pv[0], n, k + 1) &&
                t % pow2(s->pv[\at(s->order[d], Pre)]) == s->offset[\at(s->order[d], Pre)] ==>
                \exists integer x; 0 <= x < done && out[x] == \at(s->order[d], Pre); */
        /*@ assert k_next: (uint32_t)(k + 1) == k + 1; */
        /*@ assert listed_next: \forall integer d; 0 <= d < class_first(&s->pv[0], n, (uint32_t)(k + 1)) &&
                t % pow2(s->pv[\at(s->order[d], Pre)]) == s->offset[\at(s->order[d], Pre)] ==>
                \exists integer x; 0 <= x < done && out[x] == \at(s->order[d], Pre); */
        k++;
        /*@ ghost gap = gap - 1; */
    } while (k <= maxpv);
    /* The postcondition `kept` as the loop leaves it, before the asserts about
     * the due set crowd the context (without it, `kept` is a slow goal). */
    /*@ assert kept_exit: s->count == \at(s->count, Pre) && s->perfect == \at(s->perfect, Pre) &&
            (\forall integer d; 0 <= d < BSCHED_MAX_PROCS ==> s->order[d] == \at(s->order[d], Pre)) &&
            (\forall integer j; 0 <= j <= BSCHED_MAX_PV ==>
                s->class_first[j] == \at(s->class_first[j], Pre) && s->class_size[j] == \at(s->class_size[j], Pre)); */
    /*@ assert k_end: k == maxpv + 1; */
    /*@ assert all_slots: class_first(&s->pv[0], n, k) == n; */
    /*@ assert all_procs: \forall integer i; 0 <= i < n && t % pow2(s->pv[i]) == s->offset[i] ==>
            \let d = sorted_pos(&s->pv[0], n, i); 0 <= d < n && \at(s->order[d], Pre) == i; */
    /*@ assert done_small: done == due_slots{Pre}(s, t, n) <= \at(s->perfect, Pre) <= n && to - out == done; */
    emitted = to - out;
    return (uint32_t)emitted;
}

/* rev(maxpv, t + 1 mod 2^maxpv) from reversed = rev(maxpv, t): add 1 at the
 * top bit of the reversed counter and carry downwards, as t + 1 carries upwards
 * (at most maxpv carries, one on average; bit is 0 after the last carry only
 * when t + 1 wraps to 0). Given period = 2^maxpv, not maxpv: bsched_step has
 * it at hand for the cycle counter, and one shift less makes the host's
 * bsched_step 2 instructions shorter (GCC does not share 1 << maxpv between
 * the mask and the top bit). */
/*@ requires maxpv <= BSCHED_MAX_PV && t < pow2(maxpv);
    requires period: period == pow2(maxpv);
    requires counter: reversed == rev(maxpv, t);
    assigns \nothing;
    ensures next: \result == rev(maxpv, (t + 1) % pow2(maxpv));
*/
static uint32_t next_reversed(uint32_t reversed, uint32_t period)
    /*@ ghost (uint32_t maxpv, uint32_t t) */
{
    uint32_t low = reversed; /* the counter's bits below `bit`, carried out one by one */
    uint32_t bit = period / 2u;
    /*@ ghost
      int e = (int)maxpv;
      uint64_t u = t;
      lemma_rev_range();
      lemma_rev_zero();
      lemma_pow2(BSCHED_MAX_PV);
    */
    /*@ loop invariant e_range: 0 <= e <= maxpv;
        loop invariant bit_is: (e >= 1 ==> bit == pow2(e - 1)) && (e == 0 ==> bit == 0);
        loop invariant low: low == rev(e, u) && 0 <= u;
        loop invariant goal: rev(maxpv, t + 1) == rev(e, u + 1);
        loop assigns low, bit, e, u;
        loop variant bit;
    */
    while (bit != 0u && low >= bit) {
        /*@ ghost lemma_rev_carry(e, u); */
        /*@ assert odd: u % 2 == 1 && bit == pow2(e - 1); */
        /*@ assert next_goal: rev(e, u + 1) == rev(e - 1, u / 2 + 1); */
        low -= bit;
        bit /= 2u;
        /*@ ghost
          u = u / 2;
          e = e - 1;
        */
    }
    /*@ ghost
      if (e >= 1) {
        lemma_rev_carry(e, u);
      }
    */
    /*@ assert next_reversed: low + bit == rev(maxpv, t + 1); */
    /*@ ghost rev_mod_inv(); */
    /*@ assert next_mod: rev(maxpv, t + 1) == rev(maxpv, (t + 1) % pow2(maxpv)); */
    return low + bit;
}

/*@ requires valid_state: s == \null || \valid(s);
    requires from_init: s != \null && plausible(s) ==> scheduled(s);
    assigns s->ran[0 .. BSCHED_MAX_PROCS - 1], s->ran_count, s->cycle, s->reversed;

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
      ensures ok_sorted: sorted_order(s);
      ensures ok_closed: closed_form(s);
      ensures ok_perfect: s->perfect == perfect_of(&s->pv[0], s->count);
      ensures ok_class_table: class_table(s);
      ensures ok_reversed: s->reversed == rev(s->maxpv, s->cycle);
      ensures ok_scheduled: scheduled(s);
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
    uint32_t reversed;
    uint32_t period; /* 2^maxpv: the major cycle's length */

    if (s == NULL) {
        return BSCHED_ERR_NULL;
    }
    /* plausible_state written out: GCC calls it here instead of inlining it,
     * at about 10 instructions a cycle. */
    if (s->count == 0u || (uint32_t)s->count - 1u >= (uint32_t)BSCHED_MAX_PROCS ||
        s->maxpv > (uint32_t)BSCHED_MAX_PV || s->perfect == 0u) {
        return BSCHED_ERR_STATE;
    }
    /* Stated once, so that the goals below need not each re-derive it. */
    /*@ assert state_ok: plausible(s); */
    reversed = s->reversed;
    /*@ ghost uint32_t t = s->cycle; */
    /* The counters first: collect_due reads neither, and ran[] is then the
     * last thing written but ran_count. */
    period = period_of(s->maxpv);
    s->cycle = (s->cycle + 1u) % period;
    s->reversed = next_reversed(reversed, period) /*@ ghost (s->maxpv, t) */;
    /*@ assert counters: s->cycle == (t + 1) % pow2(s->maxpv) &&
            s->reversed == rev(s->maxpv, s->cycle) && s->cycle < pow2(s->maxpv); */
    done = collect_due(s, reversed, s->ran) /*@ ghost (t) */;
    /*@ assert ran_listed: \forall integer j; 0 <= j < done ==> 0 <= s->ran[j] < s->count; */
    /*@ assert ran_exact: \forall integer i; 0 <= i < s->count ==>
            ((\exists integer j; 0 <= j < done && s->ran[j] == i) <==> t % pow2(s->pv[i]) == s->offset[i]); */
    /*@ ghost lemma_balance(s->pv, s->count, t); */
    /*@ ghost Collected: ; */
    s->ran_count = (uint16_t)done;
    /*@ assert ran_kept: s->count == \at(s->count, Collected) && s->ran_count == done &&
            \forall integer j; 0 <= j < BSCHED_MAX_PROCS ==> s->ran[j] == \at(s->ran[j], Collected); */
    /*@ assert ran_exact_kept: \forall integer i; 0 <= i < s->count ==>
            ((\exists integer j; 0 <= j < done && s->ran[j] == i) <==> t % pow2(s->pv[i]) == s->offset[i]); */
    /*@ assert sizes_same: s->count == \at(s->count, Pre) && s->perfect == \at(s->perfect, Pre); */
    /* order[] shares its memory type with ran[] and ran_count: said once, the
     * goals about the state as a whole need not each show it (sorted_same is
     * slow without it). */
    /*@ assert order_same: \forall integer d; 0 <= d < BSCHED_MAX_PROCS ==>
            s->order[d] == \at(s->order[d], Pre); */
    /*@ assert wf_kept: well_formed(s); */
    /*@ assert sorted_same: sorted_order(s); */
    /*@ assert table_kept: class_table(s); */
    /*@ ghost lemma_scheduled(s); */
    /*@ assert periodic: s->ran_count == done && \forall integer i; 0 <= i < s->count ==>
            (ran_last(s, i) <==> t % pow2(s->pv[i]) == s->offset[i]); */
    return (int32_t)done;
}

/* Not analysed by WP: the process bodies are called through a pointer, which
 * WP cannot follow without a `calls` clause; make prove skips it (README "Proofs"). */
int32_t bsched_run_cycle(struct bsched *s, bsched_process_fn run, void *context)
{
    int32_t ran;
    int32_t k;

    if (run == NULL) {
        return BSCHED_ERR_NULL;
    }
    ran = bsched_step(s);
    /* An error (ran < 0) runs nothing. */
    for (k = 0; k < ran; k++) {
        run(context, s->ran[k]);
    }
    return ran;
}

/*@ requires valid_state: s == \null || \valid_read(s);
    requires from_init: s != \null && plausible(s) ==> scheduled(s);
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
      ensures ok_load: \result == load(&s->pv[0], s->count, (s->cycle + ahead) % pow2(s->maxpv));
      ensures ok_due_range: \forall integer j; 0 <= j < \result ==> 0 <= due[j] < s->count;
      ensures ok_due_exact: \forall integer i; 0 <= i < s->count ==>
          ((\exists integer j; 0 <= j < \result && due[j] == i) <==>
           ((s->cycle + ahead) % pow2(s->maxpv)) % pow2(s->pv[i]) == s->offset[i]);
    complete behaviors;
    disjoint behaviors;
*/
int32_t bsched_due(const struct bsched *s, uint32_t ahead, uint16_t *due)
{
    uint32_t period;
    uint32_t t;
    uint32_t done;

    if (s == NULL || due == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!plausible_state(s)) {
        return BSCHED_ERR_STATE;
    }
    period = period_of(s->maxpv);
    /* Both terms are below 2^31: no wrap. */
    t = (s->cycle + ahead % period) % period;
    /*@ ghost lemma_pow2_bound(); */
    /*@ assert period_range: period == pow2(s->maxpv) && 1 <= period <= 2147483648 &&
            s->cycle < period; */
    /*@ ghost step_mod_add(s->cycle, ahead, period); */
    /*@ assert t_is: t == (s->cycle + ahead) % pow2(s->maxpv) < pow2(s->maxpv); */
    done = collect_due(s, reverse_bits(t, s->maxpv), due) /*@ ghost (t) */;
    /*@ assert due_range: \forall integer j; 0 <= j < done ==> 0 <= due[j] < s->count; */
    /*@ assert due_exact: \forall integer i; 0 <= i < s->count ==>
            ((\exists integer j; 0 <= j < done && due[j] == i) <==> t % pow2(s->pv[i]) == s->offset[i]); */
    return (int32_t)done;
}

/*@ requires valid_state: s == \null || \valid_read(s);
    requires from_init: s != \null && plausible(s) ==> well_formed(s);
    assigns \nothing;

    behavior null:
      assumes s == \null;
      ensures \result == BSCHED_ERR_NULL;
    behavior bad_state:
      assumes s != \null && !plausible(s);
      ensures \result == BSCHED_ERR_STATE;
    behavior bad_index:
      assumes s != \null && plausible(s) && i >= s->count;
      ensures \result == BSCHED_ERR_INDEX;
    behavior ok:
      assumes s != \null && plausible(s) && i < s->count;
      ensures ok_range: 0 <= \result < pow2(s->pv[i]);
      ensures ok_phase: (s->cycle + \result) % pow2(s->pv[i]) == s->offset[i];
      ensures ok_due: \result == 0 <==> s->cycle % pow2(s->pv[i]) == s->offset[i];
    complete behaviors;
    disjoint behaviors;
*/
int32_t bsched_wait(const struct bsched *s, uint16_t i)
{
    uint32_t period;
    uint32_t wait;

    if (s == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!plausible_state(s)) {
        return BSCHED_ERR_STATE;
    }
    if (i >= s->count) {
        return BSCHED_ERR_INDEX;
    }
    period = period_of(s->pv[i]);
    /* (offset - cycle) mod 2^pv without an unsigned wrap: offset < 2^pv <= 2^31. */
    wait = (s->offset[i] + period - s->cycle % period) % period;
    /*@ ghost lemma_pow2_bound(); */
    /*@ assert period_range: period == pow2(s->pv[i]) && 1 <= period <= 2147483648 &&
            s->offset[i] < period; */
    /*@ ghost step_wait(period, s->offset[i], s->cycle, wait); */
    /*@ ghost lemma_phase_due(period, s->cycle, wait, s->offset[i]); */
    return (int32_t)wait;
}
