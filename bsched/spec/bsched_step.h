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
     ensures residue_q_small: b / p + 1 - (y + lead) / p <= 281474976710656;
     ensures j0_range: 0 <= j0 < p;
  @/
  void step_residue(int64_t p, int64_t b, int64_t y, int64_t lead, int64_t j0)
  {
    lemma_bal_div_bounds();
    lemma_bal_mul_mono();
    /@ assert p_one: p == 1 ==> b / p == b && b % p == 0 && y == 0 && lead == 1 && (y + lead) / p == 1; @/
    /@ assert p_two: p >= 2 ==> 2 * (b / p) <= p * (b / p) <= b; @/
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
     requires 0 <= b <= 281474976710656 && 0 <= j0 < p && b + j0 == y + p * q;
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

/* A class walk from member j0 in steps of p visits cnt = (size - 1 - j0) / p + 1
 * members: the last one is inside the class, the next one past it. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= j0 < size <= 65535;
     requires cnt == (size - 1 - j0) / p + 1;
     assigns \nothing;
     ensures count_range: 1 <= cnt <= size;
     ensures last_in: j0 + (cnt - 1) * p < size;
     ensures next_out: size <= j0 + cnt * p;
  @/
  void step_count_members(int64_t p, int64_t j0, int64_t size, int64_t cnt)
  {
    lemma_div_unique((uint64_t)(size - 1 - j0), (uint64_t)p, (uint64_t)((size - 1 - j0) / p),
                     (uint64_t)((size - 1 - j0) % p));
  }
*/

/*@
  // Member j of a class whose area is b sits at residue y (period p).
  predicate residue_at(integer b, integer p, integer y, integer j) = (b + j) % p == y;

  // Member m of a class walk (from residue j0 in steps of p) is inside the
  // class and at residue y.
  predicate walk_residue(integer b, integer j0, integer p, integer y, integer size, integer m) =
      residue_at(b, p, y, j0 + m * p) && 0 <= j0 + m * p < size;
*/

/* Every member of the walk is at residue y (step_due_member for each). */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= y < p && 0 <= q && 1 <= cnt <= 65536;
     requires 0 <= b <= 281474976710656 && 0 <= j0 < p && b + j0 == y + p * q;
     requires q <= 281474976710656;
     requires last_in: j0 + (cnt - 1) * p < size;
     assigns \nothing;
     ensures members_due: \forall integer m; 0 <= m < cnt ==> walk_residue(b, j0, p, y, size, m);
  @/
  void step_due_members(int64_t p, int64_t b, int64_t y, int64_t q, int64_t j0, int64_t cnt,
                        int64_t size)
  {
    int64_t i = 0;
    /@ loop invariant 0 <= i <= cnt;
       loop invariant \forall integer m; 0 <= m < i ==> walk_residue(b, j0, p, y, size, m);
       loop assigns i;
       loop variant cnt - i;
    @/
    while (i < cnt) {
      step_due_member(p, b, y, q, j0, i);
      /@ assert nonneg: i * p >= 0; @/
      /@ assert rest: (cnt - 1 - i) * p >= 0; @/
      /@ assert inside: j0 + i * p < size; @/
      /@ assert this: walk_residue(b, j0, p, y, size, i); @/
      i = i + 1;
    }
  }
*/

/* below(B) == q: no member before j0 is at residue Y. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= y < p && 0 <= j0 < p && 0 <= q;
     requires 0 <= b <= 281474976710656 && b + j0 == y + p * q && q <= 281474976710656;
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
     requires 0 <= b <= 281474976710656 && b + j0 == y + p * q && q <= 281474976710656;
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
     requires 0 <= b <= 281474976710656 && b + j0 == y + p * q && q <= 281474976710656;
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

/* Every member j < c at residue Y is j0 + m P for an m below i; stated for
 * x = B + j (a plain variable under / and %, so that provers instantiate it). */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= y < p && 0 <= j0 < p && 0 <= q && 0 <= i <= 65536;
     requires 0 <= b && y + p * q <= b + j0 <= y + p * q;
     requires 0 <= c && c <= j0 + i * p;
     assigns \nothing;
     ensures index_lower: \forall integer x; b <= x < b + c && x % p == y ==> 0 <= x / p - q;
     ensures index_upper: \forall integer x; b <= x < b + c && x % p == y ==> x / p - q + 1 <= i;
     ensures index_form: \forall integer x; b <= x < b + c && x % p == y ==>
         x - b == j0 + (x / p - q) * p;
  @/
  void step_member_index(int64_t p, int64_t b, int64_t y, int64_t q, int64_t j0, int64_t i, int64_t c)
  {
    lemma_bal_div_bounds();
    lemma_bal_mul_mono();
    /@ assert euclid: \forall integer x; b <= x < b + c ==> x == p * (x / p) + x % p; @/
    /@ assert offset: \forall integer x; b <= x < b + c && x % p == y ==>
           x - b == j0 + p * (x / p) - p * q; @/
    /@ assert offset2: \forall integer x; b <= x < b + c && x % p == y ==>
           x - b == j0 + p * (x / p - q); @/
    /@ assert lower: \forall integer x; b <= x < b + c && x % p == y ==>
           p * 0 < p * (x / p - q) + p; @/
    /@ assert upper: \forall integer x; b <= x < b + c && x % p == y ==>
           p * (x / p - q + 1) < p * i + p; @/
    /@ assert upper2: \forall integer x; b <= x < b + c && x % p == y ==> x / p - q + 1 <= i; @/
    /@ assert lower2: \forall integer x; b <= x < b + c && x % p == y ==> 0 <= x / p - q; @/
    /@ assert commute: \forall integer x; b <= x < b + c && x % p == y ==>
           x - b == j0 + (x / p - q) * p; @/
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

/*@
  // Class k's due count from its area b, size c and residue y (period p):
  // below(b + c) - below(b), the members j < c with (b + j) mod p == y.
  logic integer walk_hits(integer b, integer c, integer y, integer p) =
      (b + c - y + p - 1) / p - (b - y + p - 1) / p;

  // Member j is the walk's member number (j - j0) / p, one of the first h.
  predicate walk_index(integer j, integer j0, integer p, integer m, integer h) =
      0 <= m < h && j == j0 + m * p;
*/

/* A class's walk in one contract over plain values (area b, size, residue y,
 * lead = p - b mod p): it starts at j0 = (y + lead) mod p, visits
 * walk_hits(b, size, y, p) members, each at residue y, and every member j at
 * residue y is member number (b + j) / p - q of the walk,
 * q = b / p + 1 - (y + lead) / p. */
/*@ ghost
  /@ requires 1 <= p <= 2147483648 && 0 <= b <= 281474976710656 && 0 <= y < p;
     requires lead == p - b % p && 0 <= size <= 65535;
     requires j0 == (y + lead) % p && q == b / p + 1 - (y + lead) / p;
     assigns \nothing;
     ensures j0_range: 0 <= j0 < p;
     ensures none: j0 >= size ==> walk_hits(b, size, y, p) == 0;
     ensures some: j0 < size ==> walk_hits(b, size, y, p) == (size - 1 - j0) / p + 1;
     ensures members: \forall integer m; 0 <= m < walk_hits(b, size, y, p) ==>
         walk_residue(b, j0, p, y, size, m);
     ensures index: \forall integer j; 0 <= j < size && residue_at(b, p, y, j) ==>
         walk_index(j, j0, p, (b + j) / p - q, walk_hits(b, size, y, p));
  @/
  void step_class_walk(int64_t p, int64_t b, int64_t y, int64_t lead, int64_t size,
                       int64_t j0, int64_t q)
  {
    int64_t cnt = 0;
    step_residue(p, b, y, lead, j0);
    step_class_start(p, b, y, q, j0);
    if (j0 < size) {
      cnt = (size - 1 - j0) / p + 1;
      step_count_members(p, j0, size, cnt);
      step_due_members(p, b, y, q, j0, cnt, size);
    }
    step_class_count(p, b, y, q, j0, cnt, size);
    /@ assert hits: walk_hits(b, size, y, p) == cnt; @/
    step_member_index(p, b, y, q, j0, cnt, size);
    /@ assert index_x: \forall integer j; 0 <= j < size && (b + j) % p == y ==>
           0 <= (b + j) / p - q < cnt && j == j0 + ((b + j) / p - q) * p; @/
  }
*/

/* lemma_slots_class for every class at once, so that collect_due can state
 * the class counts in its pre-state (it writes out[], which may share memory
 * with the state's other 16-bit fields). */
/*@ ghost
  /@ requires \valid_read(s);
     requires 1 <= s->count <= BSCHED_MAX_PROCS;
     requires \forall integer i; 0 <= i < s->count ==> s->pv[i] <= BSCHED_MAX_PV;
     requires slots_ok: \forall integer d; 0 <= d < s->count ==> slots_slot_ok(s, t, d);
     assigns \nothing;
     ensures classes_step: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
         due_slots(s, t, class_first(&s->pv[0], s->count, k + 1)) ==
         due_slots(s, t, class_first(&s->pv[0], s->count, k)) +
         hits(k, class_area(&s->pv[0], s->count, k), class_count(&s->pv[0], s->count, k),
              rev(k, t % pow2(k)));
  @/
  void step_slots_classes(struct bsched *s, uint32_t t)
  {
    int k = 0;
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV + 1;
       loop invariant \forall integer j; 0 <= j < k ==>
         due_slots(s, t, class_first(&s->pv[0], s->count, j + 1)) ==
         due_slots(s, t, class_first(&s->pv[0], s->count, j)) +
         hits(j, class_area(&s->pv[0], s->count, j), class_count(&s->pv[0], s->count, j),
              rev(j, t % pow2(j)));
       loop assigns k;
       loop variant BSCHED_MAX_PV + 1 - k;
    @/
    while (k < BSCHED_MAX_PV + 1) {
      lemma_slots_class(s, t, k);
      k = k + 1;
    }
  }
*/

/* Named facts of collect_due. Each is a predicate so that a quantified
 * hypothesis over it has the predicate itself as its only trigger: the
 * instance a goal needs is then found at once, where the unfolded formula
 * (divisions, rev, pow2 over memory) let the provers wander in the large
 * context of collect_due's loops. */
/*@
  // Class k's due members: the class adds its hits to the due slots below it.
  predicate class_hits_at{L}(struct bsched *s, integer t, integer k) =
      due_slots(s, t, class_first(&s->pv[0], s->count, k + 1)) ==
      due_slots(s, t, class_first(&s->pv[0], s->count, k)) +
      walk_hits(class_area(&s->pv[0], s->count, k), class_count(&s->pv[0], s->count, k),
                rev(k, t % pow2(k)), pow2(k));

  // The reversed counter's top k bits are rev_k(t mod 2^k).
  predicate top_at(integer reversed, integer maxpv, integer t, integer k) =
      reversed / pow2(maxpv - k) == rev(k, t % pow2(k)) && 0 <= rev(k, t % pow2(k)) < pow2(k);

  // Fig. 6's start value of class k is its area mod 2^k.
  predicate start_area_at{L}(struct bsched *s, integer k) =
      class_start(&s->pv[0], s->count, k) == class_area(&s->pv[0], s->count, k) % pow2(k);

  // out[x] is a process due in cycle t.
  predicate listed_at{L}(struct bsched *s, uint16_t *out, integer x, integer n, integer t) =
      out[x] < n && t % pow2(s->pv[out[x]]) == s->offset[out[x]];

  // Member m of the class walk whose first slot is `first` holds a process
  // due in cycle t (and its slot fact, which the due-ness comes from).
  predicate walk_member_ok{L}(struct bsched *s, integer t, integer n, integer first,
                              integer j0, integer p, integer m) =
      slots_slot_ok(s, t, first + (j0 + m * p)) &&
      s->order[first + (j0 + m * p)] < n &&
      t % pow2(s->pv[s->order[first + (j0 + m * p)]]) == s->offset[s->order[first + (j0 + m * p)]];

  // The m-th member emitted for a class (first slot first, residue j0, step p).
  predicate emitted_at{L}(struct bsched *s, uint16_t *out, integer done0, integer first,
                          integer j0, integer p, integer m) =
      out[done0 + m] == s->order[first + (j0 + m * p)];
*/

/*@
  // Slot d of class k holds a process, due in cycle t exactly when member
  // d - first of the class sits at residue rev_k(t mod 2^k). Stated per slot
  // d (a bare variable: the trigger is order[d]).
  predicate class_due_at{L}(struct bsched *s, integer n, integer t, integer k) =
      \forall integer d; class_first(&s->pv[0], n, k) <= d <
          class_first(&s->pv[0], n, k + 1) ==>
          s->order[d] < n &&
          (t % pow2(s->pv[s->order[d]]) == s->offset[s->order[d]] <==>
           residue_at(class_area(&s->pv[0], n, k), pow2(k), rev(k, t % pow2(k)),
                      d - class_first(&s->pv[0], n, k)));
*/

/*@
  // The same by member j of class k: a member at residue rev_k(t mod 2^k)
  // holds a process due in cycle t (the trigger is residue_at).
  predicate class_member_due_at{L}(struct bsched *s, integer t, integer k) =
      \forall integer j; 0 <= j < class_count(&s->pv[0], s->count, k) &&
          residue_at(class_area(&s->pv[0], s->count, k), pow2(k), rev(k, t % pow2(k)), j) ==>
          s->order[class_first(&s->pv[0], s->count, k) + j] < s->count &&
          t % pow2(s->pv[s->order[class_first(&s->pv[0], s->count, k) + j]]) ==
              s->offset[s->order[class_first(&s->pv[0], s->count, k) + j]];
*/

/* slots_slot_ok for the slots of one class, with the class's own k in place
 * of pv[order[d]] (the slot ranges are disjoint). in_class_ok states the slot
 * fact with pv[order[d]] named before in_class_due puts k in its place: in one
 * step, CVC5 took 15-17 s. */
/*@ ghost
  /@ requires \valid_read(s) && well_formed(s);
     requires slots: \forall integer d; 0 <= d < s->count ==> slots_slot_ok(s, t, d);
     requires first_next: \forall integer k; lo <= k <= hi ==>
         0 <= class_first(&s->pv[0], s->count, k) &&
         class_first(&s->pv[0], s->count, k) <= class_first(&s->pv[0], s->count, k + 1) <= s->count;
     requires 0 <= lo && hi <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures class_due: \forall integer k; lo <= k <= hi ==> class_due_at(s, s->count, t, k);
     ensures class_due_slots: \forall integer k, d; lo <= k <= hi &&
         class_first(&s->pv[0], s->count, k) <= d < class_first(&s->pv[0], s->count, k + 1) ==>
         s->order[d] < s->count &&
         (t % pow2(s->pv[s->order[d]]) == s->offset[s->order[d]] <==>
          residue_at(class_area(&s->pv[0], s->count, k), pow2(k), rev(k, t % pow2(k)),
                     d - class_first(&s->pv[0], s->count, k)));
  @/
  void step_class_due(struct bsched *s, uint32_t t, int lo, int hi)
  {
    lemma_first(s->pv, s->count);
    /@ assert in_class: \forall integer k, d; lo <= k <= hi &&
           class_first(&s->pv[0], s->count, k) <= d < class_first(&s->pv[0], s->count, k + 1) ==>
           0 <= d < s->count && slots_slot_ok(s, t, d) && s->pv[s->order[d]] == k && s->order[d] < s->count; @/
    /@ assert in_class_ok: \forall integer k, d; lo <= k <= hi &&
           class_first(&s->pv[0], s->count, k) <= d < class_first(&s->pv[0], s->count, k + 1) ==>
           \let q = s->pv[s->order[d]]; q == k &&
           (t % pow2(q) == s->offset[s->order[d]] <==>
            (class_area(&s->pv[0], s->count, q) + (d - class_first(&s->pv[0], s->count, q))) % pow2(q) ==
               rev(q, t % pow2(q))); @/
    /@ assert in_class_due: \forall integer k, d; lo <= k <= hi &&
           class_first(&s->pv[0], s->count, k) <= d < class_first(&s->pv[0], s->count, k + 1) ==>
           (t % pow2(s->pv[s->order[d]]) == s->offset[s->order[d]] <==>
            (class_area(&s->pv[0], s->count, k) + (d - class_first(&s->pv[0], s->count, k))) % pow2(k) ==
               rev(k, t % pow2(k))); @/
  }
*/

/* The same by member: member j of class k is slot class_first(k) + j. It
 * starts from step_class_due's result (class_due_slots), not from the slot
 * facts again: re-deriving them here took CVC5 25-30 s per assertion. */
/*@ ghost
  /@ requires \valid_read(s) && well_formed(s);
     requires class_due_slots: \forall integer k, d; lo <= k <= hi &&
         class_first(&s->pv[0], s->count, k) <= d < class_first(&s->pv[0], s->count, k + 1) ==>
         s->order[d] < s->count &&
         (t % pow2(s->pv[s->order[d]]) == s->offset[s->order[d]] <==>
          residue_at(class_area(&s->pv[0], s->count, k), pow2(k), rev(k, t % pow2(k)),
                     d - class_first(&s->pv[0], s->count, k)));
     requires 0 <= lo && hi <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures member_due: \forall integer k; lo <= k <= hi ==> class_member_due_at(s, t, k);
  @/
  void step_class_member_due(struct bsched *s, uint32_t t, int lo, int hi)
  {
    lemma_first(s->pv, s->count);
    /@ assert by_member: \forall integer k, j; lo <= k <= hi && 0 <= j < class_count(&s->pv[0], s->count, k) ==>
           class_first(&s->pv[0], s->count, k) <= class_first(&s->pv[0], s->count, k) + j <
           class_first(&s->pv[0], s->count, k + 1); @/
    /@ assert by_member_due: \forall integer k, j; lo <= k <= hi && 0 <= j < class_count(&s->pv[0], s->count, k) ==>
           \let d = class_first(&s->pv[0], s->count, k) + j;
           s->order[d] < s->count &&
           (t % pow2(s->pv[s->order[d]]) == s->offset[s->order[d]] <==>
            residue_at(class_area(&s->pv[0], s->count, k), pow2(k), rev(k, t % pow2(k)), j)); @/
    /@ assert by_member_at: \forall integer k, j; lo <= k <= hi && 0 <= j < class_count(&s->pv[0], s->count, k) &&
           residue_at(class_area(&s->pv[0], s->count, k), pow2(k), rev(k, t % pow2(k)), j) ==>
           s->order[class_first(&s->pv[0], s->count, k) + j] < s->count &&
           t % pow2(s->pv[s->order[class_first(&s->pv[0], s->count, k) + j]]) ==
               s->offset[s->order[class_first(&s->pv[0], s->count, k) + j]]; @/
  }
*/

/* The per-class fact in its named form (class_hits_at), proven apart from
 * step_collect_facts' many lemmas, where the unfolding alone timed out. */
/*@ ghost
  /@ requires classes: \forall integer k; s->minpv <= k <= s->maxpv ==>
         due_slots(s, t, class_first(&s->pv[0], s->count, k + 1)) ==
         due_slots(s, t, class_first(&s->pv[0], s->count, k)) +
         (class_area(&s->pv[0], s->count, k) + class_count(&s->pv[0], s->count, k) -
          rev(k, t % pow2(k)) + pow2(k) - 1) / pow2(k) -
         (class_area(&s->pv[0], s->count, k) - rev(k, t % pow2(k)) + pow2(k) - 1) / pow2(k);
     assigns \nothing;
     ensures classes_at: \forall integer k; s->minpv <= k <= s->maxpv ==> class_hits_at(s, t, k);
  @/
  void step_classes_at(struct bsched *s, uint32_t t)
  {
  }
*/

/* Everything collect_due needs about the state and cycle t, in one contract,
 * so that its own goals see these facts and not the lemmas behind them. */
/*@ ghost
  /@ requires \valid_read(s);
     requires state: well_formed(s) && sorted_order(s) && closed_form(s) && class_table(s) &&
         s->perfect == perfect_of(&s->pv[0], s->count);
     requires counter: reversed == rev(s->maxpv, t);
     assigns \nothing;
     ensures pow2_range: \forall integer b; 0 <= b <= BSCHED_MAX_PV ==> 1 <= pow2(b) <= 2147483648;
     ensures pow2_shift: \forall integer b; 0 <= b <= BSCHED_MAX_PV ==> (1 << b) == pow2(b);
     ensures total: due_slots(s, t, s->count) == load(&s->pv[0], s->count, t) <= s->perfect <= s->count;
     ensures first_min: class_first(&s->pv[0], s->count, s->minpv) == 0;
     ensures first_max: class_first(&s->pv[0], s->count, s->maxpv + 1) == s->count;
     ensures first_next: \forall integer k; s->minpv <= k <= s->maxpv ==>
         0 <= class_first(&s->pv[0], s->count, k) &&
         class_first(&s->pv[0], s->count, k + 1) ==
             class_first(&s->pv[0], s->count, k) + class_count(&s->pv[0], s->count, k) &&
         class_first(&s->pv[0], s->count, k + 1) <= s->count;
     ensures sorted: \forall integer i; 0 <= i < s->count ==>
         0 <= sorted_pos(&s->pv[0], s->count, i) < s->count &&
         s->order[sorted_pos(&s->pv[0], s->count, i)] == i;
     ensures slots: \forall integer d; 0 <= d < s->count ==> slots_slot_ok(s, t, d);
     ensures mono: \forall integer a, b; 0 <= a <= b <= s->count ==>
         due_slots(s, t, a) <= due_slots(s, t, b);
     ensures classes: \forall integer k; s->minpv <= k <= s->maxpv ==>
         due_slots(s, t, class_first(&s->pv[0], s->count, k + 1)) ==
         due_slots(s, t, class_first(&s->pv[0], s->count, k)) +
         (class_area(&s->pv[0], s->count, k) + class_count(&s->pv[0], s->count, k) -
          rev(k, t % pow2(k)) + pow2(k) - 1) / pow2(k) -
         (class_area(&s->pv[0], s->count, k) - rev(k, t % pow2(k)) + pow2(k) - 1) / pow2(k);
     ensures classes_at: \forall integer k; s->minpv <= k <= s->maxpv ==> class_hits_at(s, t, k);
     ensures start_area_all: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==> start_area_at(s, k);
     ensures top_all: \forall integer k; s->minpv <= k <= s->maxpv ==> top_at(reversed, s->maxpv, t, k);
     ensures class_due: \forall integer k; s->minpv <= k <= s->maxpv ==> class_due_at(s, s->count, t, k);
     ensures class_due_slots: \forall integer k, d; s->minpv <= k <= s->maxpv &&
         class_first(&s->pv[0], s->count, k) <= d < class_first(&s->pv[0], s->count, k + 1) ==>
         s->order[d] < s->count &&
         (t % pow2(s->pv[s->order[d]]) == s->offset[s->order[d]] <==>
          residue_at(class_area(&s->pv[0], s->count, k), pow2(k), rev(k, t % pow2(k)),
                     d - class_first(&s->pv[0], s->count, k)));
     ensures member_due: \forall integer k; s->minpv <= k <= s->maxpv ==> class_member_due_at(s, t, k);
     ensures start_is_area: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
         class_start(&s->pv[0], s->count, k) == class_area(&s->pv[0], s->count, k) % pow2(k);
     ensures top: \forall integer k; s->minpv <= k <= s->maxpv ==>
         reversed / pow2(s->maxpv - k) == rev(k, t % pow2(k)) && 0 <= rev(k, t % pow2(k)) < pow2(k);
  @/
  void step_collect_facts(struct bsched *s, uint32_t t, uint32_t reversed)
  {
    lemma_pow2(BSCHED_MAX_PV);
    lemma_pow2_bound();
    lemma_count(s->pv, s->count);
    lemma_first(s->pv, s->count);
    lemma_classes(s->pv, s->count);
    step_first_bounds(s->pv, s->count, s->minpv, s->maxpv);
    step_due_slots_mono(s, t, s->count);
    lemma_slots_all(s, t);
    step_slots_classes(s, t);
    lemma_slots_by_class(s, t);
    lemma_balance(s->pv, s->count, t);
    lemma_fold(s->pv, s->count);
    lemma_start_is_area(s->pv, s->count);
    lemma_rev_top();
    lemma_rev_range();
    lemma_hits();
    lemma_bal_area_nonneg(s->pv, s->count);
    /@ assert counts_small: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
           0 <= class_count(&s->pv[0], s->count, k) <= 65535 && class_area(&s->pv[0], s->count, k) >= 0; @/
    /@ assert hits_closed: \forall integer k; s->minpv <= k <= s->maxpv ==>
           hits(k, class_area(&s->pv[0], s->count, k), class_count(&s->pv[0], s->count, k), rev(k, t % pow2(k))) ==
           below(k, rev(k, t % pow2(k)), class_area(&s->pv[0], s->count, k) + class_count(&s->pv[0], s->count, k)) -
           below(k, rev(k, t % pow2(k)), class_area(&s->pv[0], s->count, k)); @/
    /@ assert classes: \forall integer k; s->minpv <= k <= s->maxpv ==>
         due_slots(s, t, class_first(&s->pv[0], s->count, k + 1)) ==
         due_slots(s, t, class_first(&s->pv[0], s->count, k)) +
         (class_area(&s->pv[0], s->count, k) + class_count(&s->pv[0], s->count, k) -
          rev(k, t % pow2(k)) + pow2(k) - 1) / pow2(k) -
         (class_area(&s->pv[0], s->count, k) - rev(k, t % pow2(k)) + pow2(k) - 1) / pow2(k); @/
    step_classes_at(s, t);
    step_class_due(s, t, s->minpv, s->maxpv);
    step_class_member_due(s, t, s->minpv, s->maxpv);
  }
*/

#endif /* BSCHED_SPEC_STEP_H */
