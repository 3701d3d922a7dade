/*
 * bsched/spec/bsched_lemmas.h: lemma functions for the B-scheduler proof.
 *
 * A lemma function is a ghost function without effect whose contract is the
 * lemma and whose loop invariant carries the induction; WP proves the body
 * like any other code, so the lemma needs neither Coq nor an axiom. The
 * functions exist only for Frama-C (ghost code is a comment to a compiler).
 * Included by bsched.c after bsched_logic.h.
 */
#ifndef BSCHED_SPEC_LEMMAS_H
#define BSCHED_SPEC_LEMMAS_H

/*@ ghost
  /@ requires 0 <= limit <= 62;
     assigns \nothing;
     ensures pow2_positive: \forall integer b; 0 <= b <= limit ==> pow2(b) >= 1;
     ensures pow2_monotone: \forall int a, b; 0 <= a <= b <= limit ==> pow2(a) <= pow2(b);
     ensures pow2_is_shift: \forall integer b; 0 <= b <= limit ==> (1 << b) == pow2(b);
  @/
  void lemma_pow2(int limit)
  {
    int x = 0;
    /@ loop invariant 0 <= x <= limit;
       loop invariant \forall integer b; 0 <= b <= x ==> pow2(b) >= 1;
       loop invariant \forall int a, b; 0 <= a <= b <= x ==> pow2(a) <= pow2(b);
       loop invariant \forall integer b; 0 <= b <= x ==> (1 << b) == pow2(b);
       loop assigns x;
       loop variant limit - x;
    @/
    while (x < limit) {
      /@ assert (1 << (x + 1)) == ((1 << x) << 1) == 2 * (1 << x); @/
      x = x + 1;
    }
  }
*/

/*@ ghost
  /@ requires 0 <= a <= b <= 62;
     assigns \nothing;
     ensures pow2_split: pow2(b) == pow2(a) * pow2(b - a);
  @/
  void lemma_pow2_split(int a, int b)
  {
    int x = a;
    /@ loop invariant a <= x <= b;
       loop invariant pow2(x) == pow2(a) * pow2(x - a);
       loop assigns x;
       loop variant b - x;
    @/
    while (x < b) {
      /@ assert pow2(x + 1) == 2 * pow2(x) && pow2(x + 1 - a) == 2 * pow2(x - a); @/
      x = x + 1;
    }
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures count_range: \forall integer i, k; 0 <= i <= n ==>
         0 <= class_count(pv, i, k) <= i;
     ensures count_monotone: \forall integer i, j, k; 0 <= i <= j <= n ==>
         class_count(pv, i, k) <= class_count(pv, j, k);
     ensures count_strict: \forall integer i, j; 0 <= i < j <= n ==>
         class_count(pv, i, pv[i]) < class_count(pv, j, pv[i]);
  @/
  void lemma_count(const uint8_t *pv, size_t n)
  {
    size_t x = 0;
    /@ loop invariant 0 <= x <= n;
       loop invariant \forall integer i, k; 0 <= i <= x ==> 0 <= class_count(pv, i, k) <= i;
       loop invariant \forall integer i, j, k; 0 <= i <= j <= x ==>
           class_count(pv, i, k) <= class_count(pv, j, k);
       loop invariant \forall integer i, j; 0 <= i < j <= x ==>
           class_count(pv, i, pv[i]) < class_count(pv, j, pv[i]);
       loop assigns x;
       loop variant n - x;
    @/
    while (x < n) {
      x = x + 1;
    }
  }
*/

/*@ ghost
  /@ requires m < 65536;
     assigns \nothing;
     ensures first_step: \forall integer k; 0 <= k <= BSCHED_MAX_PV + 1 ==>
         class_first(pv, m + 1, k) == class_first(pv, m, k) + (pv[m] < k ? 1 : 0);
  @/
  void lemma_first_step(const uint8_t *pv, size_t m)
  {
    int x = 0;
    /@ loop invariant 0 <= x <= BSCHED_MAX_PV + 1;
       loop invariant \forall integer k; 0 <= k <= x ==>
           class_first(pv, m + 1, k) == class_first(pv, m, k) + (pv[m] < k ? 1 : 0);
       loop assigns x;
       loop variant BSCHED_MAX_PV + 1 - x;
    @/
    while (x < BSCHED_MAX_PV + 1) {
      x = x + 1;
    }
  }
*/

/*@ ghost
  /@ requires n <= 65536;
     requires \forall integer i; 0 <= i < n ==> pv[i] <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures first_total: class_first(pv, n, BSCHED_MAX_PV + 1) == n;
     ensures first_monotone: \forall int a, b; 0 <= a <= b <= BSCHED_MAX_PV + 1 ==>
         class_first(pv, n, a) <= class_first(pv, n, b);
     ensures first_next: \forall integer k; 0 <= k ==>
         class_first(pv, n, k + 1) == class_first(pv, n, k) + class_count(pv, n, k);
  @/
  void lemma_first(const uint8_t *pv, size_t n)
  {
    size_t m = 0;
    int k = 0;
    lemma_count(pv, n);
    /@ loop invariant 0 <= m <= n;
       loop invariant class_first(pv, m, BSCHED_MAX_PV + 1) == m;
       loop assigns m;
       loop variant n - m;
    @/
    while (m < n) {
      lemma_first_step(pv, m);
      m = m + 1;
    }
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV + 1;
       loop invariant \forall int a, b; 0 <= a <= b <= k ==>
           class_first(pv, n, a) <= class_first(pv, n, b);
       loop assigns k;
       loop variant BSCHED_MAX_PV + 1 - k;
    @/
    while (k < BSCHED_MAX_PV + 1) {
      k = k + 1;
    }
  }
*/

/*@ ghost
  /@ requires 0 <= m <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures pow2_divides: \forall integer a; 0 <= a <= m ==>
         pow2(m) == pow2(a) * pow2(m - a) && pow2(m - a) >= 1;
  @/
  void lemma_pow2_divides(int m)
  {
    int a = 0;
    lemma_pow2(BSCHED_MAX_PV);
    /@ loop invariant 0 <= a <= m + 1;
       loop invariant \forall integer b; 0 <= b < a ==>
           pow2(m) == pow2(b) * pow2(m - b) && pow2(m - b) >= 1;
       loop assigns a;
       loop variant m + 1 - a;
    @/
    while (a <= m) {
      lemma_pow2_split(a, m);
      a = a + 1;
    }
  }
*/

#endif /* BSCHED_SPEC_LEMMAS_H */
