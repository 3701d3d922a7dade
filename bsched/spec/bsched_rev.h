/*
 * bsched/spec/bsched_rev.h: lemma functions about bit reversal and the
 * class cursor, for the balance proof.
 *
 * Ghost code only (a comment to a C compiler). Included by bsched.c after
 * bsched_lemmas.h. Helpers are prefixed rev_; the lemmas other files call
 * are lemma_rev_range, lemma_rev_next, lemma_rev_involution and
 * lemma_start_is_area. New logic: rev_area_high and the predicate rev_split
 * (class_area(k) == 2^k * rev_area_high(k) + class_start(k), 0 <= class_start(k) < 2^k).
 */
#ifndef BSCHED_SPEC_REV_H
#define BSCHED_SPEC_REV_H

/*@ ghost
  /@ assigns \nothing;
     ensures div_unique: \forall integer x, d, q, r; d > 0 && q >= 0 && 0 <= r < d && x == d * q + r ==>
         x / d == q && x % d == r;
  @/
  void rev_div_unique(void)
  {
    /@ assert euclid: \forall integer x, d; x >= 0 && d > 0 ==>
           x == d * (x / d) + x % d && 0 <= x % d < d; @/
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures mod_half: \forall integer x, q; x >= 0 && q > 0 ==>
         x / (2 * q) == (x / 2) / q && x % (2 * q) == 2 * ((x / 2) % q) + x % 2;
     ensures mod_one: \forall integer r, p; 0 <= r < p ==>
         (p + r) / p == 1 && (p + r) % p == r && r / p == 0 && r % p == r;
  @/
  void rev_mod_facts(void)
  {
    rev_div_unique();
    /@ assert euclid: \forall integer x, d; x >= 0 && d > 0 ==>
           x == d * (x / d) + x % d && 0 <= x % d < d && x / d >= 0; @/
    /@ assert half_split: \forall integer x, q; x >= 0 && q > 0 ==>
           x == 2 * q * ((x / 2) / q) + (2 * ((x / 2) % q) + x % 2); @/
    /@ assert half_range: \forall integer x, q; x >= 0 && q > 0 ==>
           0 <= 2 * ((x / 2) % q) + x % 2 < 2 * q && (x / 2) / q >= 0; @/
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures pow2_pos: \forall integer b; 0 <= b <= BSCHED_MAX_PV + 1 ==> pow2(b) >= 1;
     ensures pow2_div: \forall integer x, k; x >= 0 && 1 <= k <= BSCHED_MAX_PV + 1 ==>
         x / pow2(k) == (x / 2) / pow2(k - 1);
     ensures pow2_mod: \forall integer x, k; x >= 0 && 1 <= k <= BSCHED_MAX_PV + 1 ==>
         x % pow2(k) == 2 * ((x / 2) % pow2(k - 1)) + x % 2;
     ensures bit_shift: \forall integer x, b; x >= 0 && 0 <= b <= BSCHED_MAX_PV ==>
         bit_of(x, b + 1) == bit_of(x / 2, b);
     ensures bit_zero: \forall integer x; x >= 0 ==> bit_of(x, 0) == x % 2;
     ensures bit_range: \forall integer x, b; x >= 0 && 0 <= b <= BSCHED_MAX_PV + 1 ==>
         0 <= bit_of(x, b) <= 1;
  @/
  void rev_pow2_facts(void)
  {
    lemma_pow2(BSCHED_MAX_PV + 1);
    rev_mod_facts();
    /@ assert twice: \forall integer k; 1 <= k <= BSCHED_MAX_PV + 1 ==>
           pow2(k) == 2 * pow2(k - 1) && pow2(k - 1) >= 1; @/
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures pow2_one: \forall integer k, r; 0 <= k <= BSCHED_MAX_PV + 1 && 0 <= r < pow2(k) ==>
         (pow2(k) + r) / pow2(k) == 1 && (pow2(k) + r) % pow2(k) == r &&
         r / pow2(k) == 0 && r % pow2(k) == r;
  @/
  void rev_pow2_one(void)
  {
    rev_mod_facts();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures rev_range: \forall integer k, x; 0 <= k <= BSCHED_MAX_PV && x >= 0 ==> 0 <= rev(k, x) < pow2(k);
     ensures bit_range: \forall integer x, b; x >= 0 && 0 <= b <= BSCHED_MAX_PV ==> 0 <= bit_of(x, b) <= 1;
  @/
  void lemma_rev_range(void)
  {
    int k = 0;
    rev_pow2_facts();
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV;
       loop invariant \forall integer j, x; 0 <= j <= k && x >= 0 ==> 0 <= rev(j, x) < pow2(j);
       loop assigns k;
       loop variant BSCHED_MAX_PV - k;
    @/
    while (k < BSCHED_MAX_PV) {
      /@ assert step: \forall integer x; x >= 0 ==>
             rev(k + 1, x) == 2 * rev(k, x) + bit_of(x, k) && pow2(k + 1) == 2 * pow2(k); @/
      k = k + 1;
    }
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures bit_mod: \forall integer x, b, m; x >= 0 && 0 <= b < m <= BSCHED_MAX_PV ==>
         bit_of(x % pow2(m), b) == bit_of(x, b);
  @/
  void rev_bit_mod(void)
  {
    int b = 0;
    rev_pow2_facts();
    /@ loop invariant 0 <= b <= BSCHED_MAX_PV;
       loop invariant \forall integer j, x, m; x >= 0 && 0 <= j < b && j < m <= BSCHED_MAX_PV ==>
           bit_of(x % pow2(m), j) == bit_of(x, j);
       loop assigns b;
       loop variant BSCHED_MAX_PV - b;
    @/
    while (b < BSCHED_MAX_PV) {
      /@ assert mod_nonneg: \forall integer x, m; x >= 0 && 0 <= m <= BSCHED_MAX_PV ==>
             0 <= x % pow2(m) && 0 <= x / 2; @/
      /@ assert mod_halves: \forall integer x, m; x >= 0 && 1 <= m <= BSCHED_MAX_PV ==>
             (x % pow2(m)) / 2 == (x / 2) % pow2(m - 1) && (x % pow2(m)) % 2 == x % 2; @/
      if (b == 0) {
        /@ assert base: \forall integer x, m; x >= 0 && 0 < m <= BSCHED_MAX_PV ==>
               bit_of(x % pow2(m), 0) == bit_of(x, 0); @/
      } else {
        /@ assert shift_mod: \forall integer x, m; x >= 0 && b < m <= BSCHED_MAX_PV ==>
               bit_of(x % pow2(m), b) == bit_of((x / 2) % pow2(m - 1), b - 1); @/
        /@ assert ih: \forall integer x, m; x >= 0 && b < m <= BSCHED_MAX_PV ==>
               bit_of((x / 2) % pow2(m - 1), b - 1) == bit_of(x / 2, b - 1); @/
        /@ assert shift: \forall integer x, m; x >= 0 && b < m <= BSCHED_MAX_PV ==>
               bit_of(x % pow2(m), b) == bit_of(x, b); @/
      }
      b = b + 1;
    }
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures rev_mod: \forall integer k, m, x; 0 <= k <= m <= BSCHED_MAX_PV && x >= 0 ==>
         rev(k, x % pow2(m)) == rev(k, x);
  @/
  void rev_mod_inv(void)
  {
    int k = 0;
    rev_pow2_facts();
    rev_bit_mod();
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV;
       loop invariant \forall integer j, m, x; 0 <= j <= k && j <= m <= BSCHED_MAX_PV && x >= 0 ==>
           rev(j, x % pow2(m)) == rev(j, x);
       loop assigns k;
       loop variant BSCHED_MAX_PV - k;
    @/
    while (k < BSCHED_MAX_PV) {
      /@ assert nonneg: \forall integer x, m; x >= 0 && 0 <= m <= BSCHED_MAX_PV ==> 0 <= x % pow2(m); @/
      /@ assert unfold: \forall integer x, m; x >= 0 && k + 1 <= m <= BSCHED_MAX_PV ==>
             rev(k + 1, x % pow2(m)) == 2 * rev(k, x % pow2(m)) + bit_of(x % pow2(m), k) &&
             rev(k + 1, x) == 2 * rev(k, x) + bit_of(x, k); @/
      k = k + 1;
    }
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures rev_next: \forall integer k, t; 0 <= k < BSCHED_MAX_PV && t >= 0 ==>
         rev(k + 1, t % pow2(k + 1)) == 2 * rev(k, t % pow2(k)) + bit_of(t, k);
  @/
  void lemma_rev_next(void)
  {
    rev_mod_inv();
    /@ assert unfold: \forall integer k, t; 0 <= k < BSCHED_MAX_PV && t >= 0 ==>
           rev(k + 1, t) == 2 * rev(k, t) + bit_of(t, k); @/
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures bottom_up: \forall integer k, x; 0 <= k < BSCHED_MAX_PV && x >= 0 ==>
         rev(k + 1, x) == rev(k, x / 2) + (x % 2 == 1 ? pow2(k) : 0);
  @/
  void rev_bottom_up(void)
  {
    int k = 0;
    rev_pow2_facts();
    /@ assert base: \forall integer x; x >= 0 ==>
           rev(1, x) == 2 * rev(0, x) + bit_of(x, 0) && rev(0, x) == 0 && rev(0, x / 2) == 0 &&
           pow2(0) == 1; @/
    /@ loop invariant 0 <= k < BSCHED_MAX_PV;
       loop invariant \forall integer j, x; 0 <= j <= k && x >= 0 ==>
           rev(j + 1, x) == rev(j, x / 2) + (x % 2 == 1 ? pow2(j) : 0);
       loop assigns k;
       loop variant BSCHED_MAX_PV - k;
    @/
    while (k < BSCHED_MAX_PV - 1) {
      /@ assert unfold: \forall integer x; x >= 0 ==>
             rev(k + 2, x) == 2 * rev(k + 1, x) + bit_of(x, k + 1) &&
             rev(k + 1, x / 2) == 2 * rev(k, x / 2) + bit_of(x / 2, k) &&
             pow2(k + 1) == 2 * pow2(k) && x / 2 >= 0; @/
      /@ assert step: \forall integer x; x >= 0 ==>
             rev(k + 2, x) == rev(k + 1, x / 2) + (x % 2 == 1 ? pow2(k + 1) : 0); @/
      k = k + 1;
    }
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures involution: \forall integer k, x; 0 <= k <= BSCHED_MAX_PV && 0 <= x < pow2(k) ==>
         rev(k, rev(k, x)) == x;
     ensures due_iff: \forall integer k, t, r; 0 <= k <= BSCHED_MAX_PV && t >= 0 && 0 <= r < pow2(k) ==>
         (t % pow2(k) == rev(k, r) <==> rev(k, t % pow2(k)) == r);
  @/
  void lemma_rev_involution(void)
  {
    int k = 0;
    rev_pow2_facts();
    rev_mod_facts();
    lemma_rev_range();
    rev_mod_inv();
    rev_bottom_up();
    rev_pow2_one();
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV;
       loop invariant \forall integer j, x; 0 <= j <= k && 0 <= x < pow2(j) ==> rev(j, rev(j, x)) == x;
       loop assigns k;
       loop variant BSCHED_MAX_PV - k;
    @/
    while (k < BSCHED_MAX_PV) {
      /@ assert half: \forall integer x; 0 <= x < pow2(k + 1) ==>
             0 <= x / 2 < pow2(k) && x == 2 * (x / 2) + x % 2 && 0 <= x % 2 <= 1 &&
             0 <= rev(k, x / 2) < pow2(k); @/
      /@ assert y_is: \forall integer x; 0 <= x < pow2(k + 1) ==>
             rev(k + 1, x) == rev(k, x / 2) + (x % 2 == 1 ? pow2(k) : 0); @/
      /@ assert y_low0: \forall integer x; 0 <= x < pow2(k + 1) && x % 2 == 0 ==>
             rev(k + 1, x) == rev(k, x / 2); @/
      /@ assert y_low1: \forall integer x; 0 <= x < pow2(k + 1) && x % 2 != 0 ==>
             rev(k + 1, x) == pow2(k) + rev(k, x / 2); @/
      /@ assert y_parts: \forall integer x; 0 <= x < pow2(k + 1) ==>
             rev(k, x / 2) % pow2(k) == rev(k, x / 2) && rev(k, x / 2) / pow2(k) == 0 &&
             (pow2(k) + rev(k, x / 2)) % pow2(k) == rev(k, x / 2) &&
             (pow2(k) + rev(k, x / 2)) / pow2(k) == 1; @/
      /@ assert y_low: \forall integer x; 0 <= x < pow2(k + 1) ==>
             rev(k + 1, x) % pow2(k) == rev(k, x / 2) &&
             rev(k + 1, x) / pow2(k) == x % 2 && rev(k + 1, x) >= 0; @/
      /@ assert y_rev: \forall integer x; 0 <= x < pow2(k + 1) ==>
             rev(k, rev(k + 1, x)) == rev(k, rev(k + 1, x) % pow2(k)); @/
      /@ assert y_rev2: \forall integer x; 0 <= x < pow2(k + 1) ==>
             rev(k, rev(k + 1, x)) == x / 2; @/
      /@ assert y_bit: \forall integer x; 0 <= x < pow2(k + 1) ==>
             bit_of(rev(k + 1, x), k) == x % 2; @/
      /@ assert unfold: \forall integer x; 0 <= x < pow2(k + 1) ==>
             rev(k + 1, rev(k + 1, x)) == 2 * rev(k, rev(k + 1, x)) + bit_of(rev(k + 1, x), k); @/
      k = k + 1;
    }
    /@ assert residue: \forall integer k, t; 0 <= k <= BSCHED_MAX_PV && t >= 0 ==>
           0 <= t % pow2(k) < pow2(k); @/
  }
*/

/*@
  // The whole periods of the cursor: class_area(k) == 2^k * rev_area_high(k) + class_start(k)
  // (rev_split_step). rev_area_high(k) counts what Fig. 6's `mod 2^k` drops up to class k.
  logic integer rev_area_high{L}(uint8_t *pv, integer n, integer k) =
      k <= 0 ? 0
             : rev_area_high{L}(pv, n, k - 1) +
               (class_start{L}(pv, n, k - 1) + class_count{L}(pv, n, k - 1)) / pow2(k - 1);

  predicate rev_split{L}(uint8_t *pv, integer n, integer k) =
      class_area{L}(pv, n, k) == pow2(k) * rev_area_high{L}(pv, n, k) + class_start{L}(pv, n, k) &&
      0 <= class_start{L}(pv, n, k) < pow2(k) && rev_area_high{L}(pv, n, k) >= 0;
*/

/*@ ghost
  /@ requires 0 <= k < BSCHED_MAX_PV;
     requires rev_split(pv, n, k);
     requires count_nonneg: class_count(pv, n, k) >= 0;
     assigns \nothing;
     ensures split_next: class_area(pv, n, k + 1) ==
         pow2(k + 1) * rev_area_high(pv, n, k + 1) + class_start(pv, n, k + 1);
     ensures start_range: 0 <= class_start(pv, n, k + 1) < pow2(k + 1);
     ensures high_nonneg: rev_area_high(pv, n, k + 1) >= 0;
  @/
  void rev_split_step(const uint8_t *pv, size_t n, int k)
  {
    lemma_pow2(BSCHED_MAX_PV);
    /@ assert unfold: \let s = class_start(pv, n, k); \let c = class_count(pv, n, k);
           \let P = pow2(k);
           class_area(pv, n, k + 1) == 2 * (class_area(pv, n, k) + c) &&
           class_start(pv, n, k + 1) == 2 * ((s + c) % P) &&
           rev_area_high(pv, n, k + 1) == rev_area_high(pv, n, k) + (s + c) / P &&
           pow2(k + 1) == 2 * P && P >= 1 && c >= 0; @/
    /@ assert euclid: \let s = class_start(pv, n, k); \let c = class_count(pv, n, k);
           \let P = pow2(k);
           s + c == P * ((s + c) / P) + (s + c) % P && 0 <= (s + c) % P < P && (s + c) / P >= 0; @/
    /@ assert prod: \let s = class_start(pv, n, k); \let c = class_count(pv, n, k);
           \let P = pow2(k); \let h = rev_area_high(pv, n, k);
           pow2(k + 1) * rev_area_high(pv, n, k + 1) == 2 * P * h + 2 * P * ((s + c) / P); @/
    /@ assert next: class_area(pv, n, k + 1) ==
           pow2(k + 1) * rev_area_high(pv, n, k + 1) + class_start(pv, n, k + 1) &&
           0 <= class_start(pv, n, k + 1) < pow2(k + 1) && rev_area_high(pv, n, k + 1) >= 0; @/
  }
*/

/*@ ghost
  /@ requires 0 <= k <= BSCHED_MAX_PV;
     requires rev_split(pv, n, k);
     assigns \nothing;
     ensures start_mod: class_start(pv, n, k) == class_area(pv, n, k) % pow2(k);
  @/
  void rev_split_mod(const uint8_t *pv, size_t n, int k)
  {
    rev_div_unique();
    /@ assert le: \let B = class_area(pv, n, k); \let P = pow2(k); \let h = rev_area_high(pv, n, k);
           P * h <= B < P * h + P && P > 0 && h >= 0 && B == P * h + class_start(pv, n, k); @/
    /@ assert q: class_area(pv, n, k) / pow2(k) == rev_area_high(pv, n, k); @/
  }
*/

/*@ ghost
  /@ requires n <= 65535;
     assigns \nothing;
     ensures area_nonneg: \forall integer k; 0 <= k <= BSCHED_MAX_PV + 1 ==> class_area(pv, n, k) >= 0;
     ensures start_is_area: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
         class_start(pv, n, k) == class_area(pv, n, k) % pow2(k);
  @/
  void lemma_start_is_area(const uint8_t *pv, size_t n)
  {
    int k = 0;
    lemma_count(pv, n);
    /@ assert counts: \forall integer j; class_count(pv, n, j) >= 0; @/
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV + 1;
       loop invariant \forall integer j; 0 <= j <= k ==> class_area(pv, n, j) >= 0;
       loop assigns k;
       loop variant BSCHED_MAX_PV + 1 - k;
    @/
    while (k < BSCHED_MAX_PV + 1) {
      k = k + 1;
    }
    k = 0;
    /@ assert base: class_start(pv, n, 0) == 0 && class_area(pv, n, 0) == 0 && pow2(0) == 1 &&
           rev_area_high(pv, n, 0) == 0; @/
    /@ assert split0: rev_split(pv, n, 0); @/
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV;
       loop invariant split_k: rev_split(pv, n, k);
       loop invariant \forall integer j; 0 <= j < k ==>
           class_start(pv, n, j) == class_area(pv, n, j) % pow2(j);
       loop assigns k;
       loop variant BSCHED_MAX_PV - k;
    @/
    while (k < BSCHED_MAX_PV) {
      rev_split_mod(pv, n, k);
      rev_split_step(pv, n, k);
      k = k + 1;
    }
    rev_split_mod(pv, n, k);
  }
*/

/* Halving after dividing by 2^b is dividing by 2^(b+1): the step of
 * reverse_bits' `rest`. */
/*@ ghost
  /@ assigns \nothing;
     ensures half_after: \forall integer y, b; y >= 0 && 0 <= b <= BSCHED_MAX_PV ==>
         (y / pow2(b)) / 2 == y / pow2(b + 1);
  @/
  void lemma_div_pow2_half(void)
  {
    int b = 0;
    rev_pow2_facts();
    /@ loop invariant 0 <= b <= BSCHED_MAX_PV;
       loop invariant \forall integer y, c; y >= 0 && 0 <= c <= b ==>
           (y / pow2(c)) / 2 == y / pow2(c + 1);
       loop assigns b;
       loop variant BSCHED_MAX_PV - b;
    @/
    while (b < BSCHED_MAX_PV) {
      /@ assert shift_in: \forall integer y; y >= 0 ==>
             y / pow2(b + 1) == (y / 2) / pow2(b) && y / pow2(b + 2) == (y / 2) / pow2(b + 1); @/
      /@ assert halves: \forall integer y; y >= 0 ==> y / 2 >= 0; @/
      b = b + 1;
    }
  }
*/

#endif /* BSCHED_SPEC_REV_H */
