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
  /@ requires d > 0 && 0 <= r < d && x == d * q + r;
     assigns \nothing;
     ensures div_is: x / d == q;
     ensures mod_is: x % d == r;
  @/
  void lemma_div_unique(uint64_t x, uint64_t d, uint64_t q, uint64_t r)
  {
    /@ assert identity: x == d * (x / d) + x % d && 0 <= x % d < d && x / d >= 0; @/
    /@ assert difference: d * (q - x / d) == x % d - r; @/
    /@ assert small: -d < d * (q - x / d) < d; @/
    /@ assert zero: q - x / d == 0; @/
  }
*/

/*@ ghost
  /@ requires p > 0 && big == p * q && big <= 4294967296 && w <= 4294967296;
     requires x + 1 <= big && c == (x + 1) % big;
     assigns \nothing;
     ensures wrap: (c + w) % p == (x + 1 + w) % p;
  @/
  void lemma_cycle_wrap(uint64_t c, uint64_t w, uint64_t x, uint64_t p, uint64_t q,
                        uint64_t big)
  {
    // Either the counter did not wrap (c == x + 1), or it wrapped from
    // big == p * q to 0, and big + w is q whole periods of p past w.
    if (x + 1 < big) {
      /@ assert no_wrap: c == x + 1; @/
    } else {
      /@ assert wrapped: x + 1 == big && c == 0; @/
      /@ assert split: w == p * (w / p) + w % p && 0 <= w % p < p && w / p >= 0; @/
      /@ assert regroup: big + w == p * (q + w / p) + w % p; @/
      lemma_div_unique(big + w, p, q + w / p, w % p);
    }
  }
*/

/*@ ghost
  /@ requires p > 0 && 0 <= w < p && 0 <= o < p && (t + w) % p == o;
     assigns \nothing;
     ensures phase_due: w == 0 <==> t % p == o;
  @/
  void lemma_phase_due(uint64_t p, uint64_t t, uint64_t w, uint64_t o)
  {
    /@ assert ids: t == p * (t / p) + t % p && 0 <= t % p < p &&
           t + w == p * ((t + w) / p) + o; @/
    /@ assert diff: p * ((t + w) / p - t / p) == t % p + w - o; @/
  }
*/

/* Facts about residues for periods 2^k given by their exponent, so that
 * ghost code passes plain C values (lemma_due_iff_zero: Fig. 7's wait is 0
 * exactly in the cycles t = offset mod 2^k, for the reference engine). */
/*@ ghost
  /@ requires 0 <= k <= BSCHED_MAX_PV && w < pow2(k) && o < pow2(k);
     requires (t + w) % pow2(k) == o;
     assigns \nothing;
     ensures due_iff_zero: w == 0 <==> t % pow2(k) == o;
  @/
  void lemma_due_iff_zero(uint64_t t, uint64_t w, uint64_t o, int k)
  {
    uint64_t p = (uint64_t)1 << k;
    lemma_pow2(BSCHED_MAX_PV);
    /@ assert p == pow2(k) && p >= 1; @/
    lemma_phase_due(p, t, w, o);
  }
*/

/*@ ghost
  /@ requires 0 <= k <= BSCHED_MAX_PV && t <= 4294967296;
     assigns \nothing;
     ensures full_period: (t + pow2(k)) % pow2(k) == t % pow2(k);
  @/
  void lemma_full_period(uint64_t t, int k)
  {
    uint64_t p = (uint64_t)1 << k;
    lemma_pow2(BSCHED_MAX_PV);
    /@ assert p == pow2(k) && 1 <= p <= 2147483648; @/
    /@ assert t == p * (t / p) + t % p && 0 <= t % p < p; @/
    lemma_div_unique(t + p, p, t / p + 1u, t % p);
  }
*/

/*@ ghost
  /@ requires 0 <= k <= m <= BSCHED_MAX_PV && w <= 4294967296;
     requires x + 1 <= pow2(m) && c == (x + 1) % pow2(m);
     assigns \nothing;
     ensures wrap: (c + w) % pow2(k) == (x + 1 + w) % pow2(k);
  @/
  void lemma_wrap_pow2(uint64_t c, uint64_t w, uint64_t x, int k, int m)
  {
    uint64_t p = (uint64_t)1 << k;
    uint64_t q = (uint64_t)1 << (m - k);
    uint64_t big = (uint64_t)1 << m;
    lemma_pow2(BSCHED_MAX_PV);
    lemma_pow2_split(k, m);
    /@ assert p == pow2(k) && q == pow2(m - k) && big == pow2(m) && big == p * q && p >= 1 &&
           big <= 2147483648; @/
    lemma_cycle_wrap(c, w, x, p, q, big);
  }
*/

/* The parts of scheduled(s), one goal each where this is called. */
/*@ ghost
  /@ requires \valid_read(s);
     requires part_well_formed: well_formed(s);
     requires part_sorted: sorted_order(s);
     requires part_closed: closed_form(s);
     requires part_perfect: s->perfect == perfect_of(&s->pv[0], s->count);
     requires part_class_table: class_table(s);
     requires part_reversed: s->reversed == rev(s->maxpv, s->cycle);
     assigns \nothing;
     ensures scheduled: scheduled(s);
  @/
  void lemma_scheduled(struct bsched *s)
  {
  }
*/

#endif /* BSCHED_SPEC_LEMMAS_H */
