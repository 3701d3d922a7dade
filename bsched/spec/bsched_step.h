/*
 * bsched/spec/bsched_step.h: lemma functions for the O(classes + due) minor
 * cycle (collect_due, bsched_step, bsched_due, bsched_wait in bsched.c).
 *
 * Ghost code only (a comment to a C compiler). Included by bsched.c after
 * bsched_slots.h. The argument, per class k with c members starting at slot
 * f of order[] (P = 2^k, B = B_k the area below class k, Y = rev_k(t mod 2^k)):
 *   - member j is due in cycle t iff (B + j) mod P == Y (lemma_slots_slot);
 *   - Y is the top k of the maxpv bits of rev_maxpv(t) (lemma_rev_top), and
 *     j0 = (Y + 2^k - s_k) mod P with s_k = B mod P (lemma_start_is_area)
 *     satisfies B + j0 == Y + q P for an integer q >= 0 (step_residue);
 *   - so the due members are j0, j0 + P, ...: member j0 + i P is due
 *     (step_due_member), their number is below(B + c) - below(B) = hits
 *     (step_class_count, with lemma_hits and lemma_slots_class), and every due
 *     member is one of them (step_member_index);
 *   - rev_maxpv(t + 1) follows from rev_maxpv(t) by a carry from the top bit
 *     downwards (lemma_rev_carry, lemma_rev_zero).
 * Also: classes below minpv and above maxpv are empty (step_first_min,
 * step_first_max); due_slots grows with the slot (step_due_slots_mono);
 * residue facts of bsched_due and bsched_wait (step_mod_add, step_wait).
 */
#ifndef BSCHED_SPEC_STEP_H
#define BSCHED_SPEC_STEP_H

/*@ ghost
  /@ assigns \nothing;
     ensures rev_zero: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==> rev(k, 0) == 0;
  @/
  void lemma_rev_zero(void)
  {
    int k = 0;
    rev_pow2_facts();
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV;
       loop invariant \forall integer j; 0 <= j <= k ==> rev(j, 0) == 0;
       loop assigns k;
       loop variant BSCHED_MAX_PV - k;
    @/
    while (k < BSCHED_MAX_PV) {
      /@ assert step: rev(k + 1, 0) == 2 * rev(k, 0) + bit_of(0, k); @/
      /@ assert bit: bit_of(0, k) == 0; @/
      k = k + 1;
    }
  }
*/

/* rev_m(x) / 2^(m-k) == rev_k(x mod 2^k): the top k of the m reversed bits are
 * the reversal of the low k bits. By induction on m: rev_(m+1)(x) =
 * 2 rev_m(x) + bit, so rev_(m+1)(x) / 2 == rev_m(x). */
/*@ ghost
  /@ assigns \nothing;
     ensures rev_half: \forall integer m, x; 0 <= m < BSCHED_MAX_PV && x >= 0 ==>
         rev(m + 1, x) / 2 == rev(m, x);
     ensures rev_top: \forall integer k, m, x; 0 <= k <= m <= BSCHED_MAX_PV && x >= 0 ==>
         rev(m, x) / pow2(m - k) == rev(k, x % pow2(k));
  @/
  void lemma_rev_top(void)
  {
    int m = 0;
    rev_pow2_facts();
    lemma_rev_range();
    rev_mod_inv();
    /@ assert half: \forall integer m1, x; 0 <= m1 < BSCHED_MAX_PV && x >= 0 ==>
           rev(m1 + 1, x) == 2 * rev(m1, x) + bit_of(x, m1) && 0 <= bit_of(x, m1) <= 1 &&
           rev(m1 + 1, x) / 2 == rev(m1, x); @/
    /@ assert same_low: \forall integer k, x; 0 <= k <= BSCHED_MAX_PV && x >= 0 ==>
           rev(k, x % pow2(k)) == rev(k, x); @/
    /@ loop invariant 0 <= m <= BSCHED_MAX_PV;
       loop invariant \forall integer k, j, x; 0 <= k <= j <= m && x >= 0 ==>
           rev(j, x) / pow2(j - k) == rev(k, x);
       loop assigns m;
       loop variant BSCHED_MAX_PV - m;
    @/
    while (m < BSCHED_MAX_PV) {
      /@ assert base: \forall integer x; x >= 0 ==> rev(m + 1, x) / pow2(0) == rev(m + 1, x); @/
      /@ assert up: \forall integer k, x; 0 <= k <= m && x >= 0 ==>
             rev(m + 1, x) / pow2(m + 1 - k) == (rev(m + 1, x) / 2) / pow2(m - k); @/
      /@ assert up2: \forall integer k, x; 0 <= k <= m && x >= 0 ==>
             rev(m + 1, x) / pow2(m + 1 - k) == rev(m, x) / pow2(m - k); @/
      m = m + 1;
    }
  }
*/

/* One step of the reversed counter's carry: with R == rev_e(u) and e >= 1,
 * the top bit 2^(e-1) of R is bit 0 of u. */
/*@ ghost
  /@ requires 1 <= e <= BSCHED_MAX_PV && u >= 0;
     assigns \nothing;
     ensures carry_split: rev(e, u) == rev(e - 1, u / 2) + (u % 2 == 1 ? pow2(e - 1) : 0);
     ensures carry_low: 0 <= rev(e - 1, u / 2) < pow2(e - 1);
     ensures carry_next: rev(e, u + 1) == rev(e - 1, (u + 1) / 2) + ((u + 1) % 2 == 1 ? pow2(e - 1) : 0);
     ensures carry_odd: u % 2 == 1 ==> (u + 1) / 2 == u / 2 + 1 && (u + 1) % 2 == 0;
     ensures carry_even: u % 2 == 0 ==> (u + 1) / 2 == u / 2 && (u + 1) % 2 == 1;
  @/
  void lemma_rev_carry(int e, uint64_t u)
  {
    rev_bottom_up();
    lemma_rev_range();
  }
*/

/* Classes below the smallest priority value are empty, so class minpv starts
 * at slot 0; classes above the largest are empty, so class maxpv ends at n. */
/*@ ghost
  /@ requires n <= 65535;
     requires 0 <= lo <= hi <= BSCHED_MAX_PV;
     requires \forall integer i; 0 <= i < n ==> lo <= pv[i] <= hi;
     assigns \nothing;
     ensures empty: \forall integer k; (0 <= k < lo || hi < k <= BSCHED_MAX_PV) ==>
         class_count(pv, n, k) == 0;
     ensures first_min: class_first(pv, n, lo) == 0;
     ensures first_max: class_first(pv, n, hi + 1) == n;
  @/
  void step_first_bounds(const uint8_t *pv, size_t n, int lo, int hi)
  {
    size_t m = 0;
    int k = 0;
    lemma_first(pv, n);
    /@ loop invariant 0 <= m <= n;
       loop invariant \forall integer j; (0 <= j < lo || hi < j <= BSCHED_MAX_PV) ==>
           class_count(pv, m, j) == 0;
       loop assigns m;
       loop variant n - m;
    @/
    while (m < n) {
      m = m + 1;
    }
    /@ loop invariant 0 <= k <= lo;
       loop invariant class_first(pv, n, k) == 0;
       loop assigns k;
       loop variant lo - k;
    @/
    while (k < lo) {
      k = k + 1;
    }
    k = hi + 1;
    /@ loop invariant hi + 1 <= k <= BSCHED_MAX_PV + 1;
       loop invariant class_first(pv, n, k) == class_first(pv, n, hi + 1);
       loop assigns k;
       loop variant BSCHED_MAX_PV + 1 - k;
    @/
    while (k < BSCHED_MAX_PV + 1) {
      k = k + 1;
    }
  }
*/

/* due_slots grows with the slot: a due slot below n leaves room in the count. */
/*@ ghost
  /@ requires \valid_read(s) && 0 <= n <= BSCHED_MAX_PROCS;
     assigns \nothing;
     ensures due_monotone: \forall integer a, b; 0 <= a <= b <= n ==>
         due_slots(s, t, a) <= due_slots(s, t, b);
  @/
  void step_due_slots_mono(struct bsched *s, uint32_t t, uint32_t n)
  {
    uint32_t x = 0;
    /@ loop invariant 0 <= x <= n;
       loop invariant \forall integer a, b; 0 <= a <= b <= x ==>
           due_slots(s, t, a) <= due_slots(s, t, b);
       loop assigns x;
       loop variant n - x;
    @/
    while (x < n) {
      x = x + 1;
    }
  }
*/

/* The first due member: j0 = (Y + lead) mod P with lead = P - B mod P gives
 * B + j0 == Y + q P, q = B / P + 1 - (Y + lead) / P >= 0. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= b <= 281474976710656 && 0 <= y < p;
     requires lead == p - b % p && j0 == (y + lead) % p;
     assigns \nothing;
     ensures residue: b + j0 == y + p * (b / p + 1 - (y + lead) / p);
     ensures residue_q: b / p + 1 - (y + lead) / p >= 0;
     ensures j0_range: 0 <= j0 < p;
  @/
  void step_residue(int64_t p, int64_t b, int64_t y, int64_t lead, int64_t j0)
  {
    /@ assert euclid_b: b == p * (b / p) + b % p && 0 <= b % p < p && b / p >= 0; @/
    /@ assert lead_range: 1 <= lead <= p && 1 <= y + lead < 2 * p; @/
    /@ assert euclid_j: y + lead == p * ((y + lead) / p) + j0 && 0 <= j0 < p; @/
    /@ assert q1: 0 <= (y + lead) / p <= 1; @/
    /@ assert sum: b + j0 == p * (b / p) + b % p + y + lead - p * ((y + lead) / p); @/
    /@ assert sum2: b + j0 == y + p * (b / p) + p - p * ((y + lead) / p); @/
    /@ assert q_nonneg: (y + lead) / p == 1 ==> b / p + 1 - (y + lead) / p == b / p; @/
  }
*/

/* Member j0 + i P of the class is at residue Y. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= y < p && 0 <= q && 0 <= i <= 65536;
     requires 0 <= b && b + j0 == y + p * q;
     requires q <= 281474976710656;
     assigns \nothing;
     ensures member_due: (b + (j0 + i * p)) % p == y;
  @/
  void step_due_member(int64_t p, int64_t b, int64_t y, int64_t q, int64_t j0, int64_t i)
  {
    /@ assert form: b + (j0 + i * p) == p * (q + i) + y; @/
    lemma_div_unique((uint64_t)(b + (j0 + i * p)), (uint64_t)p, (uint64_t)(q + i), (uint64_t)y);
  }
*/

/* below(B) == q: no member before j0 is at residue Y. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= y < p && 0 <= j0 < p && 0 <= q;
     requires 0 <= b && b + j0 == y + p * q && q <= 281474976710656;
     assigns \nothing;
     ensures below_b: (b - y + p - 1) / p == q;
  @/
  void step_class_start(int64_t p, int64_t b, int64_t y, int64_t q, int64_t j0)
  {
    /@ assert form_b: b - y + p - 1 == p * q + (p - 1 - j0) && 0 <= p - 1 - j0 < p; @/
    lemma_div_unique((uint64_t)(b - y + p - 1), (uint64_t)p, (uint64_t)q, (uint64_t)(p - 1 - j0));
  }
*/

/* While member j0 + i P is still in the class (j0 + i P < c), below(B + c)
 * counts it: below(B + c) >= q + i + 1. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= y < p && 0 <= j0 < p && 0 <= q && 0 <= i <= 65536;
     requires 0 <= b && b + j0 == y + p * q && q <= 281474976710656;
     requires 0 <= c <= 65535 && j0 + i * p < c;
     assigns \nothing;
     ensures below_more: q + i + 1 <= (b + c - y + p - 1) / p;
  @/
  void step_class_more(int64_t p, int64_t b, int64_t y, int64_t q, int64_t j0, int64_t i, int64_t c)
  {
    /@ assert lower: b + c - y + p - 1 >= p * (q + i + 1); @/
    /@ assert euclid: b + c - y + p - 1 == p * ((b + c - y + p - 1) / p) + (b + c - y + p - 1) % p &&
           0 <= (b + c - y + p - 1) % p < p; @/
    /@ assert mono: p * (q + i + 1) < p * ((b + c - y + p - 1) / p) + p; @/
    lemma_bal_mul_mono();
  }
*/

/* How many members of the class are due: with B + j0 == Y + q P and the walk
 * stopped at the first j0 + i P >= c (i >= 1 only if j0 + (i - 1) P < c),
 * below(B + c) - below(B) == i. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= y < p && 0 <= j0 < p && 0 <= q && 0 <= i <= 65536;
     requires 0 <= b && b + j0 == y + p * q && q <= 281474976710656;
     requires 0 <= c <= 65535;
     requires stopped: c <= j0 + i * p;
     requires last: i == 0 || j0 + (i - 1) * p < c;
     assigns \nothing;
     ensures below_end: (b + c - y + p - 1) / p == q + i;
  @/
  void step_class_count(int64_t p, int64_t b, int64_t y, int64_t q, int64_t j0, int64_t i, int64_t c)
  {
    /@ assert form_c: b + c - y + p - 1 == p * (q + i) + (c - j0 - i * p + p - 1); @/
    /@ assert rest_hi: c - j0 - i * p + p - 1 < p; @/
    /@ assert rest_lo: 0 <= c - j0 - i * p + p - 1; @/
    lemma_div_unique((uint64_t)(b + c - y + p - 1), (uint64_t)p, (uint64_t)(q + i),
                     (uint64_t)(c - j0 - i * p + p - 1));
  }
*/

/* Every member j < c at residue Y is j0 + m P for an m below i. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= y < p && 0 <= j0 < p && 0 <= q && 0 <= i <= 65536;
     requires 0 <= b && b + j0 == y + p * q;
     requires 0 <= c && c <= j0 + i * p;
     assigns \nothing;
     ensures member_index: \forall integer j; 0 <= j < c && (b + j) % p == y ==>
         0 <= (b + j) / p - q < i && j == j0 + ((b + j) / p - q) * p;
  @/
  void step_member_index(int64_t p, int64_t b, int64_t y, int64_t q, int64_t j0, int64_t i, int64_t c)
  {
    lemma_bal_div_bounds();
    lemma_bal_mul_mono();
    /@ assert euclid: \forall integer j; 0 <= j < c ==>
           b + j == p * ((b + j) / p) + (b + j) % p; @/
    /@ assert offset: \forall integer j; 0 <= j < c && (b + j) % p == y ==>
           j == j0 + p * ((b + j) / p) - p * q; @/
    /@ assert offset2: \forall integer j; 0 <= j < c && (b + j) % p == y ==>
           j == j0 + p * ((b + j) / p - q); @/
    /@ assert lower: \forall integer j; 0 <= j < c && (b + j) % p == y ==>
           p * 0 < p * ((b + j) / p - q) + p; @/
    /@ assert upper: \forall integer j; 0 <= j < c && (b + j) % p == y ==>
           p * ((b + j) / p - q + 1) < p * i + p; @/
    /@ assert upper2: \forall integer j; 0 <= j < c && (b + j) % p == y ==>
           (b + j) / p - q + 1 <= i; @/
  }
*/

/* (a + x mod P) mod P == (a + x) mod P. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= a && 0 <= x <= 4294967295 && a <= 4294967295;
     assigns \nothing;
     ensures mod_add: (a + x % p) % p == (a + x) % p;
  @/
  void step_mod_add(uint64_t a, uint64_t x, uint64_t p)
  {
    /@ assert split: x == p * (x / p) + x % p && 0 <= x % p < p && x / p >= 0; @/
    /@ assert split2: a + x % p == p * ((a + x % p) / p) + (a + x % p) % p &&
           0 <= (a + x % p) % p < p && (a + x % p) / p >= 0; @/
    /@ assert regroup: a + x == p * (x / p + (a + x % p) / p) + (a + x % p) % p; @/
    lemma_div_unique(a + x, p, x / p + (a + x % p) / p, (a + x % p) % p);
  }
*/

/* Fig. 7's wait from the cycle: w = (o + P - c mod P) mod P is below P and
 * (c + w) mod P == o. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= o < p && 0 <= c <= 4294967295;
     requires w == (o + p - c % p) % p;
     assigns \nothing;
     ensures wait_range: 0 <= w < p;
     ensures wait_phase: (c + w) % p == o;
  @/
  void step_wait(uint64_t p, uint64_t o, uint64_t c, uint64_t w)
  {
    /@ assert split_c: c == p * (c / p) + c % p && 0 <= c % p < p && c / p >= 0; @/
    /@ assert range_s: 1 <= o + p - c % p < 2 * p; @/
    /@ assert split_s: o + p - c % p == p * ((o + p - c % p) / p) + w && 0 <= w < p &&
           0 <= (o + p - c % p) / p <= 1; @/
    /@ assert sum: c + w == p * (c / p + 1 - (o + p - c % p) / p) + o; @/
    /@ assert q_nonneg: c / p + 1 - (o + p - c % p) / p >= 0; @/
    lemma_div_unique(c + w, p, c / p + 1 - (o + p - c % p) / p, o);
  }
*/

#endif /* BSCHED_SPEC_STEP_H */
