/*
 * bsched/spec/bsched_fold.h: the fold of bsched_init computes ceil(U).
 *
 * U = sum_i 2^-pv_i. area (per process) and total_area (per class) are two
 * ways of writing U * 2^31 (bsched_logic.h); lemma_area_regroup shows they
 * agree, lemma_fold that perfect_of, the fold carry_k = ceil((c_k +
 * carry_(k+1)) / 2), equals ceil(total_area / 2^31) = ceil(U).
 *
 * Helper logic (prefix fold_), in units of 2^-31 of a minor cycle:
 *   fold_csum(pv, n, K) = sum_{k < K}  c_k * 2^(31-k)  (classes below K)
 *   fold_tail(pv, n, K) = sum_{K <= k <= 31} c_k * 2^(31-k)  (classes K and up)
 * Only ghost code and annotations; included by bsched.c after the other
 * spec headers.
 */
#ifndef BSCHED_SPEC_FOLD_H
#define BSCHED_SPEC_FOLD_H

/*@
  logic integer fold_csum{L}(uint8_t *pv, integer n, integer k) =
      k <= 0 ? 0
             : fold_csum{L}(pv, n, k - 1) +
               class_count{L}(pv, n, k - 1) * pow2(BSCHED_MAX_PV - (k - 1));

  logic integer fold_tail{L}(uint8_t *pv, integer n, integer k) =
      k < 0 || k > BSCHED_MAX_PV ? 0
             : class_count{L}(pv, n, k) * pow2(BSCHED_MAX_PV - k) + fold_tail{L}(pv, n, k + 1);

  // t = ceil(d / q) for d >= 0, q >= 1, stated without division. The
  // recursive call (q <= 0 only) is there so that the provers get the
  // predicate as a symbol with a defining axiom, not as a macro: quantified
  // facts about it then have it as their instantiation trigger.
  predicate fold_is_ceil(integer t, integer d, integer q) =
      q <= 0 ? fold_is_ceil(t, d, 1) : d <= t * q < d + q;

  // c >= 0, as a symbol for the same reason.
  predicate fold_nat(integer c) = c < -1 ? fold_nat(-1) : c >= 0;
*/

// Adding process m to the prefix adds 2^(31 - pv[m]) to every class sum
// that includes its class.
/*@ ghost
  /@ assigns \nothing;
     ensures csum_step: \forall integer K; 0 <= K <= BSCHED_MAX_PV + 1 ==>
         fold_csum(pv, m + 1, K) ==
         fold_csum(pv, m, K) + (pv[m] < K ? pow2(BSCHED_MAX_PV - pv[m]) : 0);
  @/
  void fold_csum_step(const uint8_t *pv, size_t m)
  {
    int x = 0;
    /@ loop invariant 0 <= x <= BSCHED_MAX_PV + 1;
       loop invariant \forall integer K; 0 <= K <= x ==>
           fold_csum(pv, m + 1, K) ==
           fold_csum(pv, m, K) + (pv[m] < K ? pow2(BSCHED_MAX_PV - pv[m]) : 0);
       loop assigns x;
       loop variant BSCHED_MAX_PV + 1 - x;
    @/
    while (x < BSCHED_MAX_PV + 1) {
      /@ assert un1: fold_csum(pv, m + 1, x + 1) == fold_csum(pv, m + 1, x) +
             class_count(pv, m + 1, x) * pow2(BSCHED_MAX_PV - x); @/
      /@ assert un0: fold_csum(pv, m, x + 1) == fold_csum(pv, m, x) +
             class_count(pv, m, x) * pow2(BSCHED_MAX_PV - x); @/
      /@ assert cnt: class_count(pv, m + 1, x) ==
             class_count(pv, m, x) + (pv[m] == x ? 1 : 0); @/
      /@ assert dist: class_count(pv, m + 1, x) * pow2(BSCHED_MAX_PV - x) ==
             class_count(pv, m, x) * pow2(BSCHED_MAX_PV - x) +
             (pv[m] == x ? pow2(BSCHED_MAX_PV - x) : 0); @/
      x = x + 1;
    }
  }
*/

// The empty prefix has no area in any class.
/*@ ghost
  /@ assigns \nothing;
     ensures csum_empty: \forall integer K; 0 <= K <= BSCHED_MAX_PV + 1 ==>
         fold_csum(pv, 0, K) == 0;
  @/
  void fold_csum_empty(const uint8_t *pv)
  {
    int x = 0;
    /@ loop invariant 0 <= x <= BSCHED_MAX_PV + 1;
       loop invariant \forall integer K; 0 <= K <= x ==> fold_csum(pv, 0, K) == 0;
       loop assigns x;
       loop variant BSCHED_MAX_PV + 1 - x;
    @/
    while (x < BSCHED_MAX_PV + 1) {
      /@ assert c: class_count(pv, 0, x) == 0; @/
      /@ assert s: fold_csum(pv, 0, x + 1) == fold_csum(pv, 0, x) +
             class_count(pv, 0, x) * pow2(BSCHED_MAX_PV - x); @/
      x = x + 1;
    }
  }
*/

// Horner form to sum form: class_area(K) * 2^(31-K) == fold_csum(K), K <= 31.
/*@ ghost
  /@ assigns \nothing;
     ensures class_sum: total_area(pv, n) == fold_csum(pv, n, BSCHED_MAX_PV + 1);
  @/
  void fold_class_sum(const uint8_t *pv, size_t n)
  {
    int x = 0;
    /@ loop invariant 0 <= x <= BSCHED_MAX_PV;
       loop invariant class_area(pv, n, x) * pow2(BSCHED_MAX_PV - x) == fold_csum(pv, n, x);
       loop assigns x;
       loop variant BSCHED_MAX_PV - x;
    @/
    while (x < BSCHED_MAX_PV) {
      /@ assert s: fold_csum(pv, n, x + 1) == fold_csum(pv, n, x) +
             class_count(pv, n, x) * pow2(BSCHED_MAX_PV - x); @/
      /@ assert a: class_area(pv, n, x + 1) == 2 * (class_area(pv, n, x) + class_count(pv, n, x)); @/
      /@ assert p: pow2(BSCHED_MAX_PV - x) == 2 * pow2(BSCHED_MAX_PV - (x + 1)); @/
      /@ assert m: class_area(pv, n, x + 1) * pow2(BSCHED_MAX_PV - (x + 1)) ==
             (class_area(pv, n, x) + class_count(pv, n, x)) * pow2(BSCHED_MAX_PV - x); @/
      x = x + 1;
    }
    /@ assert pow2(0) == 1; @/
    /@ assert fold_csum(pv, n, BSCHED_MAX_PV + 1) == fold_csum(pv, n, BSCHED_MAX_PV) +
           class_count(pv, n, BSCHED_MAX_PV); @/
  }
*/

// The per-process area equals the per-class area (induction on the prefix).
/*@ ghost
  /@ requires n <= 65535;
     requires \forall integer i; 0 <= i < n ==> pv[i] <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures area_by_class: area(pv, n) == total_area(pv, n);
  @/
  void lemma_area_regroup(const uint8_t *pv, size_t n)
  {
    size_t m = 0;
    fold_csum_empty(pv);
    /@ loop invariant 0 <= m <= n;
       loop invariant area(pv, m) == fold_csum(pv, m, BSCHED_MAX_PV + 1);
       loop assigns m;
       loop variant n - m;
    @/
    while (m < n) {
      fold_csum_step(pv, m);
      /@ assert step: fold_csum(pv, m + 1, BSCHED_MAX_PV + 1) ==
             fold_csum(pv, m, BSCHED_MAX_PV + 1) + pow2(BSCHED_MAX_PV - pv[m]); @/
      /@ assert area(pv, m + 1) == area(pv, m) + pow2(BSCHED_MAX_PV - pv[m]); @/
      m = m + 1;
    }
    fold_class_sum(pv, n);
  }
*/

// The classes below K plus the classes from K on are all classes.
/*@ ghost
  /@ assigns \nothing;
     ensures tail_csum: fold_csum(pv, n, BSCHED_MAX_PV + 1) == fold_tail(pv, n, 0);
  @/
  void fold_tail_csum(const uint8_t *pv, size_t n)
  {
    int x = 0;
    /@ loop invariant 0 <= x <= BSCHED_MAX_PV + 1;
       loop invariant fold_csum(pv, n, x) + fold_tail(pv, n, x) == fold_tail(pv, n, 0);
       loop assigns x;
       loop variant BSCHED_MAX_PV + 1 - x;
    @/
    while (x < BSCHED_MAX_PV + 1) {
      /@ assert s: fold_csum(pv, n, x + 1) == fold_csum(pv, n, x) +
             class_count(pv, n, x) * pow2(BSCHED_MAX_PV - x); @/
      /@ assert t: fold_tail(pv, n, x) ==
             class_count(pv, n, x) * pow2(BSCHED_MAX_PV - x) + fold_tail(pv, n, x + 1); @/
      x = x + 1;
    }
    /@ assert fold_tail(pv, n, BSCHED_MAX_PV + 1) == 0; @/
  }
*/

// Arithmetic of ceilings, on plain integers: ceil((c + ceil(d/q)) / 2) =
// ceil((c q + d) / (2 q)), c + ceil(d/q) = ceil((c q + d) / q), and
// ceil(d/q) = (d + q - 1) / q.
/*@ ghost
  /@ assigns \nothing;
     ensures ceil_step: \forall integer c, t, d, q; fold_nat(c) && t >= 0 && q >= 1 &&
         fold_is_ceil(t, d, q) ==> fold_is_ceil((c + t + 1) / 2, c * q + d, 2 * q);
     ensures ceil_shift: \forall integer c, t, d, q; fold_nat(c) && q >= 1 &&
         fold_is_ceil(t, d, q) ==> fold_is_ceil(c + t, c * q + d, q);
     ensures ceil_div: \forall integer t, d, q; d >= 0 && q >= 1 &&
         fold_is_ceil(t, d, q) ==> (d + q - 1) / q == t;
  @/
  void fold_ceil_facts(void)
  {
    /@ assert halve: \forall integer c, t, q; c >= 0 && t >= 0 ==>
           ((c + t + 1) / 2) * (2 * q) == c * q + t * q + ((c + t) % 2) * q; @/
    /@ assert odd: \forall integer w, q; w >= 0 && q >= 1 ==> 0 <= (w % 2) * q <= q; @/
    /@ assert mono1: \forall integer d, w; d >= 1 && w >= 1 ==> d * w >= d; @/
    /@ assert mono2: \forall integer d, w; d >= 1 && w <= -1 ==> d * w <= -d; @/
    /@ assert dist: \forall integer d, u, v; d * u - d * v == d * (u - v); @/
    /@ assert euclid: \forall integer x, d; x >= 0 && d >= 1 ==>
           x == d * (x / d) + x % d && 0 <= x % d < d; @/
    /@ assert unique: \forall integer x, d, u, s; d >= 1 && u >= 0 && 0 <= s < d &&
           x == d * u + s ==> x / d == u; @/
    /@ assert tpos: \forall integer t, d, q; d >= 0 && q >= 1 && fold_is_ceil(t, d, q) ==>
           t >= 0; @/
  }
*/

// The fold is the ceiling of the total area: carry_from(k) = ceil(fold_tail(k) /
// 2^(32-k)) by downward induction on k, then perfect = c_0 + carry_from(1) =
// ceil(fold_tail(0) / 2^31) and fold_tail(0) == total_area.
/*@ ghost
  /@ requires n <= 65535;
     requires \forall integer i; 0 <= i < n ==> pv[i] <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures fold_is_ceiling: perfect_of(pv, n) ==
         (total_area(pv, n) + pow2(BSCHED_MAX_PV) - 1) / pow2(BSCHED_MAX_PV);
  @/
  void lemma_fold(const uint8_t *pv, size_t n)
  {
    int k = BSCHED_MAX_PV + 1;
    lemma_pow2(BSCHED_MAX_PV);
    lemma_count(pv, n);
    fold_ceil_facts();
    /@ loop invariant 1 <= k <= BSCHED_MAX_PV + 1;
       loop invariant tail_nonneg: fold_tail(pv, n, k) >= 0;
       loop invariant carry_nonneg: carry_from(pv, n, k) >= 0;
       loop invariant carry_ceil: fold_is_ceil(carry_from(pv, n, k), fold_tail(pv, n, k),
                                               pow2(BSCHED_MAX_PV + 1 - k));
       loop assigns k;
       loop variant k;
    @/
    while (k > 1) {
      /@ assert c: fold_nat(class_count(pv, n, k - 1)); @/
      /@ assert q: pow2(BSCHED_MAX_PV + 1 - k) >= 1; @/
      /@ assert p: pow2(BSCHED_MAX_PV + 1 - (k - 1)) == 2 * pow2(BSCHED_MAX_PV + 1 - k); @/
      /@ assert t: fold_tail(pv, n, k - 1) ==
             class_count(pv, n, k - 1) * pow2(BSCHED_MAX_PV + 1 - k) + fold_tail(pv, n, k); @/
      /@ assert f: carry_from(pv, n, k - 1) ==
             (class_count(pv, n, k - 1) + carry_from(pv, n, k) + 1) / 2; @/
      k = k - 1;
    }
    /@ assert k1: k == 1; @/
    /@ assert t0: fold_tail(pv, n, 0) ==
           class_count(pv, n, 0) * pow2(BSCHED_MAX_PV) + fold_tail(pv, n, 1); @/
    /@ assert c0: fold_nat(class_count(pv, n, 0)); @/
    /@ assert q0: pow2(BSCHED_MAX_PV) >= 1; @/
    /@ assert shifted: fold_is_ceil(class_count(pv, n, 0) + carry_from(pv, n, 1),
                                    fold_tail(pv, n, 0), pow2(BSCHED_MAX_PV)); @/
    fold_tail_csum(pv, n);
    fold_class_sum(pv, n);
    /@ assert total: total_area(pv, n) == fold_tail(pv, n, 0); @/
    /@ assert perfect: perfect_of(pv, n) == class_count(pv, n, 0) + carry_from(pv, n, 1); @/
  }
*/

#endif /* BSCHED_SPEC_FOLD_H */
