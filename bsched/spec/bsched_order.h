/*
 * bsched/spec/bsched_order.h: lemma functions for the sorted order of
 * bsched_init (order[] is the stable sort by priority value).
 *
 * Ghost code only: a C compiler sees comments. Included by bsched.c after
 * bsched_lemmas.h. The class ranges [class_first(k), class_first(k + 1)) of
 * order[] are disjoint, ordered by k, and tile 0 .. n-1; sorted_pos(i) lies
 * in the range of pv[i]. Used by place_processes (lemma_pow2_bound,
 * lemma_place_step, lemma_classes, lemma_pos_range) and bsched_init
 * (lemma_wait_form).
 *
 * New logic definition: order_wait(k, start, rank), init_wait without memory
 * reads, so that init_wait over two arrays in two memory states compares by
 * congruence.
 */
#ifndef BSCHED_SPEC_ORDER_H
#define BSCHED_SPEC_ORDER_H

/*@ ghost
  /@ requires n <= 65536;
     requires \forall integer i; 0 <= i < n ==> pv[i] <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures classes_disjoint: \forall integer a, b; 0 <= a < b <= BSCHED_MAX_PV + 1 ==>
         class_first(pv, n, a) + class_count(pv, n, a) <= class_first(pv, n, b);
     ensures first_nonneg: \forall integer k; 0 <= k <= BSCHED_MAX_PV + 1 ==>
         0 <= class_first(pv, n, k);
     ensures first_total: class_first(pv, n, BSCHED_MAX_PV + 1) == n;
  @/
  void lemma_classes(const uint8_t *pv, size_t n)
  {
    lemma_first(pv, n);
    /@ assert first_zero: class_first(pv, n, 0) == 0; @/
  }
*/

/*@ ghost
  /@ requires n <= 65536;
     requires \forall integer i; 0 <= i < n ==> pv[i] <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures pos_in_class: \forall integer i; 0 <= i < n ==>
         class_first(pv, n, pv[i]) <= sorted_pos(pv, n, i) <
             class_first(pv, n, pv[i]) + class_count(pv, n, pv[i]);
     ensures pos_range: \forall integer i; 0 <= i < n ==> 0 <= sorted_pos(pv, n, i) < n;
  @/
  void lemma_pos_range(const uint8_t *pv, size_t n)
  {
    lemma_count(pv, n);
    lemma_classes(pv, n);
    /@ assert strict: \forall integer i; 0 <= i < n ==>
           0 <= class_count(pv, i, pv[i]) < class_count(pv, n, pv[i]); @/
    /@ assert top: \forall integer i; 0 <= i < n ==>
           0 <= class_first(pv, n, pv[i]) &&
           class_first(pv, n, pv[i]) + class_count(pv, n, pv[i]) <= n; @/
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures pow2_bounds: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
         1 <= pow2(k) <= 2147483648;
  @/
  void lemma_pow2_bound(void)
  {
    int k = 0;
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV;
       loop invariant below_k: \forall integer b; 0 <= b <= k ==> 1 <= pow2(b) <= pow2(k);
       loop invariant split_top: pow2(k) * pow2(BSCHED_MAX_PV - k) == 2147483648;
       loop invariant rest_positive: pow2(BSCHED_MAX_PV - k) >= 1;
       loop assigns k;
       loop variant BSCHED_MAX_PV - k;
    @/
    while (k < BSCHED_MAX_PV) {
      /@ assert step_up: pow2(k + 1) == 2 * pow2(k); @/
      /@ assert step_down: pow2(BSCHED_MAX_PV - k) == 2 * pow2(BSCHED_MAX_PV - k - 1); @/
      k = k + 1;
    }
  }
*/

/*@ ghost
  /@ requires i < n <= 65536;
     requires \forall integer j; 0 <= j < n ==> pv[j] <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures step_count: \forall integer k;
         class_count(pv, i + 1, k) == class_count(pv, i, k) + (pv[i] == k ? 1 : 0);
     ensures step_pos: sorted_pos(pv, n, i) ==
         class_first(pv, n, pv[i]) + class_count(pv, i, pv[i]);
     ensures step_pos_range: 0 <= sorted_pos(pv, n, i) < n;
     ensures step_rank: 0 <= class_count(pv, i, pv[i]) <= i;
     ensures step_fresh: \forall integer k, d; 0 <= k <= BSCHED_MAX_PV &&
         class_first(pv, n, k) <= d < class_first(pv, n, k) + class_count(pv, i, k) ==>
         d != sorted_pos(pv, n, i);
     ensures step_ranges: \forall integer k, d; 0 <= k <= BSCHED_MAX_PV &&
         class_first(pv, n, k) <= d < class_first(pv, n, k) + class_count(pv, i + 1, k) ==>
         d == sorted_pos(pv, n, i) ||
         class_first(pv, n, k) <= d < class_first(pv, n, k) + class_count(pv, i, k);
     ensures step_injective: \forall integer j; 0 <= j < i ==>
         sorted_pos(pv, n, j) != sorted_pos(pv, n, i);
  @/
  void lemma_place_step(const uint8_t *pv, size_t n, size_t i)
  {
    lemma_count(pv, n);
    lemma_classes(pv, n);
    /@ assert rank: class_count(pv, i, pv[i]) < class_count(pv, n, pv[i]); @/
    /@ assert below: \forall integer k; 0 <= k < pv[i] ==>
           class_first(pv, n, k) + class_count(pv, i, k) <= class_first(pv, n, pv[i]); @/
    /@ assert above: \forall integer k; pv[i] < k <= BSCHED_MAX_PV ==>
           sorted_pos(pv, n, i) < class_first(pv, n, k); @/
    /@ assert filled_own: \forall integer j; 0 <= j < i ==>
           class_first(pv, n, pv[j]) <= sorted_pos(pv, n, j) <
               class_first(pv, n, pv[j]) + class_count(pv, i, pv[j]); @/
  }
*/

/*@
  // init_wait with its memory reads taken out: member `rank` of class k whose
  // start value is `start` waits fig6_map(k, (start + rank) mod 2^k), i.e.
  // rev_k((start + rank) mod 2^k).
  logic integer order_wait(integer k, integer start, integer rank) =
      fig6_map(k, (start + rank) % pow2(k));
*/

/*@ ghost
  /@ assigns \nothing;
     ensures wait_form: \forall integer i; 0 <= i < n ==>
         init_wait(pv, n, i) ==
         order_wait(pv[i], class_start(pv, n, pv[i]), class_count(pv, i, pv[i]));
  @/
  void lemma_wait_form(const uint8_t *pv, size_t n)
  {
  }
*/

#endif /* BSCHED_SPEC_ORDER_H */
