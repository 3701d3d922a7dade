/*
 * bsched/spec/bsched_balance.h: the balance of a B-schedule (helper H2).
 *
 * The load of minor cycle t, counted class by class (load in bsched_logic.h),
 * has the closed form below(31, rev_31(t mod 2^31), total_area): the number of
 * points Y, Y + 2^31, Y + 2 * 2^31, ... below the total area, Y = rev_31(t mod 2^31).
 * Hence every cycle runs between floor(U) and ceil(U) processes, U = total_area / 2^31
 * (lemma_balance: no_idle, bounded_load).
 *
 * The steps (bsched/proofs/README.md, how the balance theorem is proven):
 *   lemma_below_step    below(k, r, x + 1) = below(k, r, x) + [x mod 2^k == r]
 *   lemma_hits          hits(k, b, c, r) = below(k, r, b + c) - below(k, r, b)
 *                       (quantified over c <= 2^31 - 1: a lemma function proves an
 *                       unbounded induction only up to its loop bound; c is a class
 *                       size, <= 65535, in every use)
 *   lemma_below_double  below(k + 1, 2r + e, 2x) = below(k, r, x), e in {0, 1}
 *   lemma_balance       load_upto(t, K + 1) = below(K, Y_K, B_K + c_K) by induction
 *                       on K (telescoping), then the floor/ceil bounds.
 *
 * Only lemma functions (ghost, no effect, proven by WP with CVC4) and one logic
 * definition, bal_below(P, r, x): below with the period P as an argument.
 * Prover notes: arithmetic facts are stated for a generic period P > 0, and
 * every lemma is phrased so that its variables occur as plain arguments of a
 * div, mod or logic-function term (CVC4 does not instantiate quantifiers on
 * terms with + or * in them); bounds of the form "x <= 2 * P <= x" instead of
 * "x == 2 * P" keep Qed from substituting the variable away.
 * Included by bsched.c after bsched_rev.h (uses its lemma_rev_range and
 * lemma_rev_next); lemma_bal_area_nonneg proves B_k >= 0 itself.
 */
#ifndef BSCHED_SPEC_BALANCE_H
#define BSCHED_SPEC_BALANCE_H

/*@
  // bal_below(P, r, x) = below(k, r, x) for P = pow2(k): the same count for any period P > 0.
  logic integer bal_below(integer P, integer r, integer x) = (x - r + P - 1) / P;
*/

/*@ ghost
  /@ assigns \nothing;
     ensures mul_mono: \forall integer P, a, b; P > 0 && P * a < P * b + P ==> a <= b;
  @/
  void lemma_bal_mul_mono(void)
  {
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures div_bounds: \forall integer P, y; P > 0 && y >= 0 ==>
         0 <= y / P && P * (y / P) <= y < P * (y / P) + P;
     ensures mod_is: \forall integer P, y; P > 0 && y >= 0 ==> y % P == y - P * (y / P);
  @/
  void lemma_bal_div_bounds(void)
  {
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures div_monotone: \forall integer P, a, b; P > 0 && 0 <= a <= b ==> a / P <= b / P;
  @/
  void lemma_bal_div_monotone(void)
  {
    lemma_bal_div_bounds();
    lemma_bal_mul_mono();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures mul_two: \forall integer P, m; P > 0 && m >= 2 ==> 2 * P <= P * m;
  @/
  void lemma_bal_mul_two(void)
  {
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures mul_gap2: \forall integer P, a, d; P > 0 && P * d < P * a + 2 * P ==> d <= a + 1;
  @/
  void lemma_bal_mul_gap2(void)
  {
    lemma_bal_mul_two();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures mul_near: \forall integer P, a, d; P > 0 && a <= d <= a + 1 ==>
         (d == a && P * d == P * a) || (d == a + 1 && P * d == P * a + P);
  @/
  void lemma_bal_mul_near(void)
  {
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures div_gap: \forall integer P, y, z; P > 0 && 0 <= y <= z <= y + P ==> z / P <= y / P + 1;
  @/
  void lemma_bal_div_gap(void)
  {
    lemma_bal_div_bounds();
    lemma_bal_mul_gap2();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures div_pair: \forall integer P, y, z; P > 0 && 0 <= y <= z <= y + P ==>
         (z / P == y / P && P * (z / P) == P * (y / P)) ||
         (z / P == y / P + 1 && P * (z / P) == P * (y / P) + P);
  @/
  void lemma_bal_div_pair(void)
  {
    lemma_bal_div_monotone();
    lemma_bal_div_gap();
    lemma_bal_mul_near();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures div_succ: \forall integer P, y, z; P > 0 && y >= 0 && z == y + 1 ==>
         z / P == y / P + (z % P == 0 ? 1 : 0);
  @/
  void lemma_bal_div_succ(void)
  {
    lemma_bal_div_bounds();
    lemma_bal_div_pair();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures mod_shift: \forall integer P, x, w; P > 0 && x >= 0 && 0 <= x - w + P < P ==>
         (w % P == 0 <==> x % P == x - w + P);
  @/
  void lemma_bal_mod_shift(void)
  {
    lemma_bal_div_bounds();
    lemma_bal_div_pair();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures step_P: \forall integer P, r, x; P > 0 && 0 <= r < P && x >= 0 ==>
        bal_below(P, r, x + 1) == bal_below(P, r, x) + (x % P == r ? 1 : 0);
  @/
  void lemma_bal_step_P(void)
  {
    lemma_bal_div_succ();
    lemma_bal_mod_shift();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures half_le: \forall integer P, Q, y, z; P > 0 && Q <= 2 * P <= Q && y >= 0 &&
         2 * y <= z <= 2 * y + 1 ==> z / Q <= y / P;
     ensures half_ge: \forall integer P, Q, y, z; P > 0 && Q <= 2 * P <= Q && y >= 0 &&
         2 * y <= z <= 2 * y + 1 ==> y / P <= z / Q;
  @/
  void lemma_bal_div_half2(void)
  {
    lemma_bal_div_bounds();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures div_half: \forall integer P, Q, y, z; P > 0 && Q <= 2 * P <= Q && y >= 0 &&
         2 * y <= z <= 2 * y + 1 ==> z / Q == y / P;
  @/
  void lemma_bal_div_half(void)
  {
    lemma_bal_div_half2();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures double_gen_P: \forall integer P, Q, r, s, x, z; P > 0 && Q <= 2 * P <= Q && 0 <= r < P &&
         2 * r <= s <= 2 * r + 1 && x >= 0 && z <= 2 * x <= z ==> bal_below(Q, s, z) == bal_below(P, r, x);
  @/
  void lemma_bal_double_P(void)
  {
    lemma_bal_div_half();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures below_is: \forall integer k, r, x; below(k, r, x) == bal_below(pow2(k), r, x);
  @/
  void lemma_bal_below_is(void)
  {
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures pow2_pos: \forall integer k; 0 <= k <= BSCHED_MAX_PV + 1 ==> pow2(k) >= 1;
     ensures pow2_next: \forall integer k; 0 <= k ==> pow2(k + 1) == 2 * pow2(k);
  @/
  void lemma_bal_pow2(void)
  {
    lemma_pow2(BSCHED_MAX_PV + 1);
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures below_step: \forall integer k, r, x; 0 <= k <= BSCHED_MAX_PV && 0 <= r < pow2(k) && x >= 0 ==>
         below(k, r, x + 1) == below(k, r, x) + (x % pow2(k) == r ? 1 : 0);
  @/
  void lemma_below_step(void)
  {
    lemma_bal_pow2();
    lemma_bal_below_is();
    lemma_bal_step_P();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures hits_below: \forall integer k, b, c, r; 0 <= k <= BSCHED_MAX_PV && b >= 0 &&
         0 <= c <= 2147483647 && 0 <= r < pow2(k) ==>
         hits(k, b, c, r) == below(k, r, b + c) - below(k, r, b);
  @/
  void lemma_hits(void)
  {
    int32_t x = 0; // not int: 2^31 - 1 must fit where int has 16 bits (-machdep x86_16)
    lemma_below_step();
    /@ loop invariant 0 <= x <= 2147483647;
       loop invariant \forall integer k, b, c, r; 0 <= k <= BSCHED_MAX_PV && b >= 0 &&
         0 <= c <= x && 0 <= r < pow2(k) ==>
         hits(k, b, c, r) == below(k, r, b + c) - below(k, r, b);
       loop assigns x;
       loop variant 2147483647 - x;
    @/
    while (x < 2147483647) {
      x = x + 1;
    }
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures double_gen: \forall integer k, k1, r, s, x, z; 0 <= k < BSCHED_MAX_PV && k1 <= k + 1 <= k1 &&
         0 <= r < pow2(k) && 2 * r <= s <= 2 * r + 1 && x >= 0 && z <= 2 * x <= z ==>
         below(k1, s, z) == below(k, r, x);
  @/
  void lemma_bal_double_gen(void)
  {
    lemma_bal_pow2();
    lemma_bal_below_is();
    lemma_bal_double_P();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures below_double: \forall integer k, r, e, x; 0 <= k < BSCHED_MAX_PV && 0 <= r < pow2(k) &&
         0 <= e <= 1 && x >= 0 ==> below(k + 1, 2 * r + e, 2 * x) == below(k, r, x);
     ensures below_double0: \forall integer k, r, x; 0 <= k < BSCHED_MAX_PV && 0 <= r < pow2(k) &&
         x >= 0 ==> below(k + 1, 2 * r, 2 * x) == below(k, r, x);
     ensures below_double1: \forall integer k, r, x; 0 <= k < BSCHED_MAX_PV && 0 <= r < pow2(k) &&
         x >= 0 ==> below(k + 1, 2 * r + 1, 2 * x) == below(k, r, x);
  @/
  void lemma_below_double(void)
  {
    lemma_bal_double_gen();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures below_bounds_P: \forall integer P, y, a; P > 0 && 0 <= y < P && a >= 0 ==>
         a / P <= bal_below(P, y, a) <= (a + P - 1) / P;
  @/
  void lemma_bal_below_bounds_P(void)
  {
    lemma_bal_div_monotone();
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures area_nonneg: \forall integer k; 0 <= k <= BSCHED_MAX_PV + 1 ==> class_area(pv, n, k) >= 0;
  @/
  void lemma_bal_area_nonneg(const uint8_t *pv, size_t n)
  {
    int k = 0;
    lemma_count(pv, n);
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV + 1;
       loop invariant \forall integer j; 0 <= j <= k ==> class_area(pv, n, j) >= 0;
       loop assigns k;
       loop variant BSCHED_MAX_PV + 1 - k;
    @/
    while (k < BSCHED_MAX_PV + 1) {
      /@ assert class_area(pv, n, k + 1) == 2 * (class_area(pv, n, k) + class_count(pv, n, k)); @/
      k = k + 1;
    }
  }
*/

/*@ ghost
  /@ requires n <= 65535;
     assigns \nothing;
     ensures base: load_upto(pv, n, t, 1) ==
         below(0, rev(0, t % pow2(0)), class_area(pv, n, 0) + class_count(pv, n, 0));
  @/
  void lemma_bal_load_base(const uint8_t *pv, size_t n, uint32_t t)
  {
    /@ assert unfold: load_upto(pv, n, t, 1) == hits(0, 0, class_count(pv, n, 0), 0); @/
    lemma_count(pv, n);
    lemma_bal_pow2();
    lemma_hits();
    /@ assert b0: below(0, 0, 0) == 0; @/
  }
*/

/*@ ghost
  /@ requires n <= 65535;
     requires 0 <= K < BSCHED_MAX_PV;
     requires upto_K: load_upto(pv, n, t, K + 1) ==
         below(K, rev(K, t % pow2(K)), class_area(pv, n, K) + class_count(pv, n, K));
     assigns \nothing;
     ensures upto_K1: load_upto(pv, n, t, K + 2) ==
         below(K + 1, rev(K + 1, t % pow2(K + 1)), class_area(pv, n, K + 1) + class_count(pv, n, K + 1));
  @/
  void lemma_bal_load_step(const uint8_t *pv, size_t n, uint32_t t, int K)
  {
    /@ assert upto_k1: load_upto(pv, n, t, K + 2) == load_upto(pv, n, t, K + 1) +
           hits(K + 1, class_area(pv, n, K + 1), class_count(pv, n, K + 1), rev(K + 1, t % pow2(K + 1))); @/
    /@ assert area_k1: class_area(pv, n, K + 1) == 2 * (class_area(pv, n, K) + class_count(pv, n, K)); @/
    lemma_count(pv, n);
    lemma_bal_area_nonneg(pv, n);
    lemma_rev_range();
    lemma_rev_next();
    lemma_bal_pow2();
    /@ assert rev_k1: rev(K + 1, t % pow2(K + 1)) == 2 * rev(K, t % pow2(K)) + bit_of(t, K); @/
    /@ assert bit_k: bit_of(t, K) == 0 || bit_of(t, K) == 1; @/
    /@ assert ranges: 0 <= rev(K, t % pow2(K)) < pow2(K) && 0 <= rev(K + 1, t % pow2(K + 1)) < pow2(K + 1) &&
           class_area(pv, n, K) >= 0 && class_area(pv, n, K + 1) >= 0 &&
           0 <= class_count(pv, n, K) <= 65535 && 0 <= class_count(pv, n, K + 1) <= 65535; @/
    lemma_hits();
    /@ assert hits_k1: hits(K + 1, class_area(pv, n, K + 1), class_count(pv, n, K + 1), rev(K + 1, t % pow2(K + 1))) ==
           below(K + 1, rev(K + 1, t % pow2(K + 1)), class_area(pv, n, K + 1) + class_count(pv, n, K + 1)) -
           below(K + 1, rev(K + 1, t % pow2(K + 1)), class_area(pv, n, K + 1)); @/
    lemma_bal_double_gen();
    /@ assert double_k: below(K + 1, rev(K + 1, t % pow2(K + 1)), class_area(pv, n, K + 1)) ==
           below(K, rev(K, t % pow2(K)), class_area(pv, n, K) + class_count(pv, n, K)); @/
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures below_bounds: \forall integer y, a; 0 <= y < pow2(BSCHED_MAX_PV) && a >= 0 ==>
         a / pow2(BSCHED_MAX_PV) <= below(BSCHED_MAX_PV, y, a) <=
         (a + pow2(BSCHED_MAX_PV) - 1) / pow2(BSCHED_MAX_PV);
  @/
  void lemma_bal_below_bounds(void)
  {
    lemma_bal_pow2();
    lemma_bal_below_is();
    lemma_bal_below_bounds_P();
  }
*/

/*@ ghost
  /@ requires n <= 65535;
     assigns \nothing;
     ensures load_closed: load(pv, n, t) ==
         below(BSCHED_MAX_PV, rev(BSCHED_MAX_PV, t % pow2(BSCHED_MAX_PV)), total_area(pv, n));
     ensures no_idle: total_area(pv, n) / pow2(BSCHED_MAX_PV) <= load(pv, n, t);
     ensures bounded_load: load(pv, n, t) <=
         (total_area(pv, n) + pow2(BSCHED_MAX_PV) - 1) / pow2(BSCHED_MAX_PV);
  @/
  void lemma_balance(const uint8_t *pv, size_t n, uint32_t t)
  {
    int K = 0;
    lemma_bal_load_base(pv, n, t);
    /@ loop invariant 0 <= K <= BSCHED_MAX_PV;
       loop invariant upto: load_upto(pv, n, t, K + 1) ==
           below(K, rev(K, t % pow2(K)), class_area(pv, n, K) + class_count(pv, n, K));
       loop assigns K;
       loop variant BSCHED_MAX_PV - K;
    @/
    while (K < BSCHED_MAX_PV) {
      lemma_bal_load_step(pv, n, t, K);
      K = K + 1;
    }
    /@ assert k_end: K == BSCHED_MAX_PV; @/
    /@ assert upto_end: load_upto(pv, n, t, BSCHED_MAX_PV + 1) ==
         below(BSCHED_MAX_PV, rev(BSCHED_MAX_PV, t % pow2(BSCHED_MAX_PV)),
               class_area(pv, n, BSCHED_MAX_PV) + class_count(pv, n, BSCHED_MAX_PV)); @/
    /@ assert total_def: total_area(pv, n) == class_area(pv, n, BSCHED_MAX_PV) + class_count(pv, n, BSCHED_MAX_PV); @/
    /@ assert load_def: load(pv, n, t) == load_upto(pv, n, t, BSCHED_MAX_PV + 1); @/
    /@ assert closed: load(pv, n, t) ==
         below(BSCHED_MAX_PV, rev(BSCHED_MAX_PV, t % pow2(BSCHED_MAX_PV)), total_area(pv, n)); @/
    lemma_count(pv, n);
    lemma_bal_area_nonneg(pv, n);
    lemma_rev_range();
    lemma_bal_pow2();
    /@ assert nonneg: total_area(pv, n) >= 0 && 0 <= rev(BSCHED_MAX_PV, t % pow2(BSCHED_MAX_PV)) < pow2(BSCHED_MAX_PV); @/
    lemma_bal_below_bounds();
  }
*/

#endif /* BSCHED_SPEC_BALANCE_H */
