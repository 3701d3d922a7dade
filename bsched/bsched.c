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

/* The low `bits` bits of x in reverse order (Fig. 6's reverse()).
 * BSCHED_MUTANT_NO_REVERSE builds a deliberately wrong variant (identity
 * instead of reversal) for the negative checks of the proof jobs: the
 * schedule stays periodic per class but is no longer balanced. */
/*@ requires bits_range: bits <= BSCHED_MAX_PV;
    requires x_range: x < pow2(bits);
    assigns \nothing;
    ensures reversal: \result == rev(bits, x);
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
    /*@ loop invariant b_range: 0 <= b <= bits;
        loop invariant carries_rev: rev_acc(bits - b, rest, reversed) == rev(bits, x);
        loop invariant reversed_range: reversed < pow2(b);
        loop assigns b, reversed, rest;
        loop variant bits - b;
    */
    for (b = 0u; b < bits; b++) {
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
*/
static void place_processes(struct bsched *s, struct bsched_classes *c,
                            const uint8_t *pv, size_t n)
{
    uint32_t i;

    /*@ ghost lemma_pow2(BSCHED_MAX_PV); */
    /*@ ghost lemma_count(pv, n); */
    /*@ ghost lemma_first(pv, n); */
    /* Every slot is overwritten below; clearing first keeps order[] within
     * 0..n-1 by construction, whatever the struct held before. */
    /*@ loop invariant 0 <= i <= n;
        loop invariant \forall integer id; 0 <= id < i ==> s->order[id] == 0;
        loop assigns i, s->order[0 .. n - 1];
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        s->order[i] = 0u;
    }
    /*@ loop invariant 0 <= i <= n;
        loop invariant next_is_slot: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
            c->next[k] == class_first{Pre}(pv, n, k) + class_count{Pre}(pv, i, k);
        loop invariant cursor_is_rank: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
            c->cursor[k] == class_start{Pre}(pv, n, k) + class_count{Pre}(pv, i, k);
        loop invariant offset_closed: \forall integer j; 0 <= j < i ==>
            s->offset[j] == init_wait{Pre}(pv, n, j) && s->offset[j] < pow2(pv[j]);
        loop invariant order_range: \forall integer id; 0 <= id < n ==> s->order[id] < n;
        loop assigns i, c->next[0 .. BSCHED_MAX_PV], c->cursor[0 .. BSCHED_MAX_PV],
            s->order[0 .. n - 1], s->offset[0 .. n - 1];
        loop variant n - i;
    */
    for (i = 0u; i < n; i++) {
        uint8_t pvi = pv[i];
        uint32_t wait;
        /*@ assert count_step: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
                class_count{Pre}(pv, i + 1, k) == class_count{Pre}(pv, i, k) + (pv[i] == k ? 1 : 0); */
        /*@ assert rank_below_size: class_count{Pre}(pv, i, pvi) < class_count{Pre}(pv, n, pvi); */
        /*@ assert class_next: class_first{Pre}(pv, n, pvi + 1) ==
                class_first{Pre}(pv, n, pvi) + class_count{Pre}(pv, n, pvi); */
        /*@ assert slot_in_class: c->next[pvi] < class_first{Pre}(pv, n, pvi + 1); */
        /*@ assert first_total: class_first{Pre}(pv, n, BSCHED_MAX_PV + 1) == n; */
        /*@ assert class_in_order: class_first{Pre}(pv, n, pvi + 1) <= class_first{Pre}(pv, n, BSCHED_MAX_PV + 1); */
        s->order[c->next[pvi]] = (uint16_t)i;
        /*@ assert cursor_bound: c->cursor[pvi] < pow2(pvi) + BSCHED_MAX_PROCS; */
        wait = reverse_bits(c->cursor[pvi] % period_of(pvi), pvi);
        /*@ assert wait_closed: wait == init_wait{Pre}(pv, n, i); */
        s->offset[i] = wait;
        c->next[pvi]++;
        c->cursor[pvi]++;
    }
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
    return BSCHED_OK;
}

/*@ requires valid_state: s == \null || \valid(s);
    requires from_init: s != \null && plausible(s) ==> well_formed(s);
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
      ensures ok_cycle: s->cycle == (\old(s->cycle) + 1) % pow2(s->maxpv);
      ensures ok_ran_range: \forall integer j; 0 <= j < \result ==> 0 <= s->ran[j] < s->count;
    complete behaviors;
    disjoint behaviors;
*/
int32_t bsched_step(struct bsched *s)
{
    uint32_t done = 0u;
    uint32_t id;
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

    /* Fig. 7, lines 5-12: run the due processes in order, at most `perfect`. */
    /*@ loop invariant 0 <= id <= count;
        loop invariant 0 <= done <= id && done <= perfect;
        loop invariant ran_range: \forall integer j; 0 <= j < done ==> 0 <= s->ran[j] < count;
        loop invariant order_kept: \forall integer d; 0 <= d < count ==> s->order[d] == \at(s->order[d], Pre);
        loop invariant wait_bound: \forall integer q; 0 <= q < count ==> s->wait[q] <= pow2(s->pv[q]);
        loop assigns id, done, s->ran[0 .. BSCHED_MAX_PROCS - 1], s->wait[0 .. BSCHED_MAX_PROCS - 1];
        loop variant count - id;
    */
    for (id = 0u; id < count && done < perfect; id++) {
        uint16_t p = s->order[id];
        if (s->wait[p] == 0u) {
            s->ran[done] = p;
            done++;
            s->wait[p] = period_of(s->pv[p]);
            /*@ assert s->wait[p] == pow2(s->pv[p]); */
        }
    }
    /* Fig. 7, line 13: every positive wait counts down one cycle. */
    /*@ loop invariant 0 <= i <= count;
        loop invariant counted_down: \forall integer q; 0 <= q < i ==> s->wait[q] < pow2(s->pv[q]);
        loop invariant not_yet: \forall integer q; i <= q < count ==> s->wait[q] <= pow2(s->pv[q]);
        loop assigns i, s->wait[0 .. BSCHED_MAX_PROCS - 1];
        loop variant count - i;
    */
    for (i = 0u; i < count; i++) {
        if (s->wait[i] > 0u) {
            s->wait[i]--;
        }
    }
    s->ran_count = (uint16_t)done;
    s->cycle = (s->cycle + 1u) % period_of(s->maxpv);
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
