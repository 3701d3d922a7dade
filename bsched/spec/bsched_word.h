/*
 * bsched/spec/bsched_word.h: lemma functions for the residue test of
 * bsched_step on 31-bit words (bsched.h, struct bsched: class_key, class_limit).
 *
 * Ghost code only (a comment to a C compiler). Included by bsched.c after
 * bsched_step.h. Per class k (P = 2^k, A = 2^(31-k), so P A = 2^31):
 *   - the reversed counter aligned to bit 31, W = rev_maxpv(t) 2^(31-maxpv),
 *     is Y A + low with Y = rev_k(t mod 2^k) its top k bits and low < A
 *     (word_split);
 *   - x = W + key_k, key_k = ((P - s_k) mod P) A, is below 2^32 (no 32-bit
 *     wrap, which WP could not reason about), and x mod 2^31 is j0 A + low
 *     with j0 = (Y + P - s_k) mod P, the first due member of the class; so
 *     (x mod 2^31) / A == j0 and x mod 2^31 < limit_k = min(c_k, P) A iff
 *     j0 < c_k, that is iff the class has a member due (word_slot);
 *   - key and limit as bsched_init computes them are below 2^31 (word_init).
 */
#ifndef BSCHED_SPEC_WORD_H
#define BSCHED_SPEC_WORD_H

/* P A == 2^31 for every class, and the facts about 2^k the word lemmas use.
 * Each step takes its product from lemma_pow2_split(k + 1, 31): doubling one
 * factor and halving the other in the invariant was not proven (2026-11-27). */
/*@ ghost
  /@ assigns \nothing;
     ensures split_31: \forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
         pow2(k) * pow2(31 - k) == 2147483648 && 1 <= pow2(31 - k) && 1 <= pow2(k);
  @/
  void word_pow2(void)
  {
    int k = 0;
    lemma_pow2(BSCHED_MAX_PV);
    lemma_pow2_split(0, BSCHED_MAX_PV);
    /@ assert p31: pow2(31) == (1 << 31) == 2147483648 && pow2(0) == 1; @/
    /@ loop invariant 0 <= k <= BSCHED_MAX_PV;
       loop invariant \forall integer j; 0 <= j <= k ==>
           pow2(j) * pow2(31 - j) == 2147483648 && 1 <= pow2(31 - j) && 1 <= pow2(j);
       loop assigns k;
       loop variant BSCHED_MAX_PV - k;
    @/
    while (k < BSCHED_MAX_PV) {
      lemma_pow2_split(k + 1, BSCHED_MAX_PV);
      /@ assert next: pow2(k + 1) * pow2(31 - (k + 1)) == 2147483648; @/
      k = k + 1;
    }
  }
*/

/* 2^b as a ghost value: ghost code cannot evaluate pow2, and a shift in a
 * large context leaves the provers to rediscover lemma_pow2 there. */
/*@ ghost
  /@ requires 0 <= b <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures pow2: \result == pow2(b) && 1 <= \result <= 2147483648;
  @/
  uint64_t word_pow2_of(int b)
  {
    lemma_pow2(BSCHED_MAX_PV);
    /@ assert top: pow2(31) == 2147483648 && pow2(b) <= pow2(31); @/
    return (uint64_t)1 << b;
  }
*/

/* Multiplying by c >= 0 keeps an order: a lemma of its own, in a context
 * small enough for the provers (inside word_slot it timed out). */
/*@ ghost
  /@ assigns \nothing;
     ensures mul_le: \forall integer a, b, c; 0 <= a <= b && 0 <= c ==> a * c <= b * c;
     ensures mul_lt: \forall integer a, b, c; 0 <= a < b && 1 <= c ==> a * c < b * c;
  @/
  void word_mul_le(void)
  {
  }
*/

/* A right shift by b is a division by 2^b (j0 = x >> (31 - k) in collect_class). */
/*@ ghost
  /@ assigns \nothing;
     ensures lsr_div: \forall integer x, b; 0 <= x && 0 <= b <= BSCHED_MAX_PV ==> (x >> b) == x / pow2(b);
  @/
  void word_lsr(void)
  {
    int b = 0;
    lemma_pow2(BSCHED_MAX_PV);
    lemma_div_pow2_half();
    /@ assert base: \forall integer x; 0 <= x ==> (x >> 0) == x && pow2(0) == 1; @/
    /@ loop invariant 0 <= b <= BSCHED_MAX_PV;
       loop invariant \forall integer x, c; 0 <= x && 0 <= c <= b ==> (x >> c) == x / pow2(c);
       loop assigns b;
       loop variant BSCHED_MAX_PV - b;
    @/
    while (b < BSCHED_MAX_PV) {
      /@ assert step_add: \forall integer x; 0 <= x ==> (x >> (b + 1)) == ((x >> b) >> 1); @/
      /@ assert step_ih: \forall integer x; 0 <= x ==> (x >> b) == x / pow2(b); @/
      /@ assert step_pos: \forall integer x; 0 <= x ==> x / pow2(b) >= 0; @/
      /@ assert step_half: \forall integer x; 0 <= x ==> ((x >> b) >> 1) == (x >> b) / 2; @/
      /@ assert step_div: \forall integer x; 0 <= x ==> (x / pow2(b)) / 2 == x / pow2(b + 1); @/
      b = b + 1;
    }
  }
*/

/* The aligned counter W = R F (F = 2^(31-maxpv)) splits at bit 31-k into
 * its top k bits, R / E (E = 2^(maxpv-k)), and the rest, (R mod E) F. */
/*@ ghost
  /@ requires 1 <= e && 1 <= f && a == e * f && 0 <= r;
     assigns \nothing;
     ensures split: r * f == (r / e) * a + (r % e) * f;
     ensures low_range: 0 <= (r % e) * f < a;
  @/
  void word_split(uint64_t r, uint64_t e, uint64_t f, uint64_t a)
  {
    /@ assert div: r == e * (r / e) + r % e && 0 <= r % e < e && r / e >= 0; @/
    /@ assert times: r * f == (e * (r / e)) * f + (r % e) * f; @/
    /@ assert regroup: (e * (r / e)) * f == (r / e) * a; @/
    /@ assert below: (r % e) * f <= (e - 1) * f; @/
    /@ assert below2: (e - 1) * f == a - f; @/
  }
*/

/* collect_due's word: R < 2^m times f = 2^(31-m) is below 2^31, and splits at
 * bit 31-k (e = 2^(m-k)) into R / e times 2^(31-k) and (R mod e) f < 2^(31-k). */
/*@ ghost
  /@ requires 0 <= k <= m <= BSCHED_MAX_PV && 0 <= r < pow2(m);
     requires e == pow2(m - k) && f == pow2(31 - m);
     assigns \nothing;
     ensures ef: e * f == pow2(31 - k);
     ensures small: r * f < 2147483648;
     ensures split: r * f == (r / e) * pow2(31 - k) + (r % e) * f && 0 <= (r % e) * f < pow2(31 - k);
  @/
  void word_top(int m, int k, uint64_t r, uint64_t e, uint64_t f)
  {
    word_pow2();
    word_mul_le();
    lemma_pow2_split(31 - m, 31 - k);
    /@ assert ef: e * f == pow2(31 - k); @/
    /@ assert pm: pow2(m) * f == 2147483648 && f >= 1; @/
    /@ assert lt: r * f < pow2(m) * f; @/
    word_split(r, e, f, e * f);
  }
*/

/* word_slot's products, each in a context of its own (together they timed out):
 * the sum of two residues times a stays below 2^32, a residue times a plus
 * low stays below 2^31, and the limit test on j0 a + low is the test j0 < m. */
/*@ ghost
  /@ requires 1 <= pk && 1 <= a && pk * a == 2147483648;
     requires 0 <= y < pk && 0 <= lead < pk && 0 <= low < a;
     assigns \nothing;
     ensures sum_bound: (y + lead) * a + low < 4294967296;
  @/
  void word_sum_bound(uint64_t pk, uint64_t a, uint64_t y, uint64_t lead, uint64_t low)
  {
    word_mul_le();
    /@ assert le: (y + lead) * a <= (2 * pk - 2) * a; @/
    /@ assert eq: (2 * pk - 2) * a == 2 * 2147483648 - 2 * a; @/
  }
*/

/*@ ghost
  /@ requires 1 <= pk && 1 <= a && pk * a == 2147483648;
     requires 0 <= j0 < pk && 0 <= low < a;
     assigns \nothing;
     ensures j0_range: 0 <= j0 * a + low < 2147483648;
  @/
  void word_j0_range(uint64_t pk, uint64_t a, uint64_t j0, uint64_t low)
  {
    word_mul_le();
    /@ assert le: j0 * a <= (pk - 1) * a; @/
    /@ assert eq: (pk - 1) * a == 2147483648 - a; @/
  }
*/

/*@ ghost
  /@ requires 1 <= a && 0 <= j0 && 0 <= low < a && 0 <= m;
     assigns \nothing;
     ensures hit: j0 * a + low < m * a <==> j0 < m;
  @/
  void word_hit(uint64_t a, uint64_t j0, uint64_t low, uint64_t m)
  {
    word_mul_le();
    if (j0 < m) {
      /@ assert lt: j0 * a + low < (j0 + 1) * a <= m * a; @/
    } else {
      /@ assert ge: m * a <= j0 * a <= j0 * a + low; @/
    }
  }
*/

/* The residue test: from W = Y A + low (low < A) and the class's key and
 * limit, x = W + key is below 2^32, and x mod 2^31 carries the first due
 * member j0 in its top k bits and is below the limit iff j0 < size. The
 * powers come in as parameters pk = 2^k and a = 2^(31-k): ghost code cannot
 * compute pow2. The terms of the division by 2^31 are ghost values x, q, r of
 * their own, each shown not to wrap: passed as expressions, their uint64_t
 * conversions stayed in the call's precondition, which under -machdep x86_16
 * no prover closed. */
/*@ ghost
  /@ requires k_range: 0 <= k <= BSCHED_MAX_PV && pk == pow2(k) && a == pow2(31 - k);
     requires word: w == y * a + low && 0 <= low < a && 0 <= y < pk;
     requires start: 0 <= start < pk && 0 <= size;
     requires key: key == class_key_of(start, k);
     requires limit: limit == class_limit_of(size, k);
     assigns \nothing;
     ensures no_wrap: w + key < 4294967296;
     ensures slot: ((w + key) % 2147483648) / pow2(31 - k) == (y + pow2(k) - start) % pow2(k);
     ensures hit: (w + key) % 2147483648 < limit <==> (y + pow2(k) - start) % pow2(k) < size;
  @/
  void word_slot(int k, uint64_t pk, uint64_t a, uint64_t w, uint64_t y, uint64_t low,
                 uint64_t start, uint64_t size, uint64_t key, uint64_t limit)
  {
    uint64_t lead = (pk - start) % pk;
    uint64_t j0 = (y + pk - start) % pk;
    word_pow2();
    /@ assert pa: pk * a == 2147483648 && 1 <= a && 1 <= pk; @/
    if (start == 0) {
      /@ assert key_zero: key == 0 && lead == 0 && key == lead * a; @/
    } else {
      /@ assert key_pos: 0 < 2147483648 - start * a == (pk - start) * a < 2147483648 &&
             key == (pk - start) * a && lead == pk - start; @/
      /@ assert key_pos_is: key == lead * a; @/
    }
    /@ assert key_is: key == lead * a; @/
    /@ assert lead_range: 0 <= lead < pk && (y + lead) % pk == j0 && 0 <= j0 < pk; @/
    /@ assert sum_is: w + key == (y + lead) * a + low; @/
    word_sum_bound(pk, a, y, lead, low);
    /@ assert j0_split: y + lead == pk * ((y + lead) / pk) + j0 && 0 <= (y + lead) / pk <= 1; @/
    /@ assert x_dist: (y + lead) * a == (pk * ((y + lead) / pk)) * a + j0 * a; @/
    /@ assert x_assoc: (pk * ((y + lead) / pk)) * a == (pk * a) * ((y + lead) / pk); @/
    /@ assert x_split: w + key == 2147483648 * ((y + lead) / pk) + (j0 * a + low); @/
    word_j0_range(pk, a, j0, low);
    uint64_t x = w + key;
    /@ assert x_is: x == w + key; @/
    uint64_t q = (y + lead) / pk;
    /@ assert q_is: q == (y + lead) / pk; @/
    uint64_t r = j0 * a + low;
    /@ assert r_is: r == j0 * a + low && 0 <= r < 2147483648; @/
    /@ assert x_qr: x == 2147483648 * q + r; @/
    lemma_div_unique(x, 2147483648, q, r);
    /@ assert y_is: (w + key) % 2147483648 == j0 * a + low; @/
    lemma_div_unique(j0 * a + low, a, j0, low);
    /@ assert limit_is: limit == (size < pk ? size : pk) * a; @/
    word_hit(a, j0, low, size < pk ? size : pk);
    /@ assert hit_min: j0 < size <==> j0 < (size < pk ? size : pk); @/
    /@ assert hit_word: (w + key) % 2147483648 < limit <==> j0 * a + low < (size < pk ? size : pk) * a; @/
    /@ assert hit_chain: (w + key) % 2147483648 < limit <==> j0 < size; @/
    /@ assert j0_is: j0 == (y + pow2(k) - start) % pow2(k); @/
  }
*/

/* bsched_init's key and limit: m times u = 2^(31-k) for m <= 2^k (the class
 * size capped at 2^k, or its start) is at most 2^31, and below it by u at
 * least when m < 2^k: 32-bit arithmetic without a wrap. */
/*@ ghost
  /@ requires 0 <= k <= BSCHED_MAX_PV && pk == pow2(k) && u == pow2(31 - k) && 0 <= m <= pk;
     assigns \nothing;
     ensures times: m * u <= 2147483648 && pk * u == 2147483648;
     ensures below: m < pk ==> m * u <= 2147483648 - u;
  @/
  void word_init(int k, uint64_t pk, uint64_t u, uint64_t m)
  {
    word_pow2();
    /@ assert pa: pk * u == 2147483648 && u >= 1; @/
    word_mul_le();
    /@ assert last: (pk - 1) * u == 2147483648 - u; @/
    /@ assert up: m * u <= pk * u; @/
    /@ assert down: m < pk ==> m * u <= (pk - 1) * u; @/
  }
*/

/* The top and the rest of collect_due's word as ghost values: computed here,
 * where their casts are dropped in a small context (in collect_due they timed out). */
/*@ ghost
  /@ requires 0 <= k <= m <= BSCHED_MAX_PV && 0 <= r < pow2(m);
     assigns \nothing;
     ensures top: \result == r / pow2(m - k) && 0 <= \result < pow2(k);
  @/
  uint32_t word_top_of(int m, int k, uint64_t r)
  {
    uint64_t e = word_pow2_of(m - k);
    lemma_pow2_split(k, m);
    /@ assert bound: r < pow2(k) * e; @/
    lemma_bal_div_bounds();
    lemma_bal_mul_mono();
    /@ assert lt: r / e < pow2(k); @/
    return (uint32_t)(r / e);
  }
*/

/*@ ghost
  /@ requires 0 <= k <= m <= BSCHED_MAX_PV && 0 <= r < pow2(m);
     assigns \nothing;
     ensures low: \result == (r % pow2(m - k)) * pow2(31 - m) && 0 <= \result < pow2(31 - k);
     ensures word: r * pow2(31 - m) == (r / pow2(m - k)) * pow2(31 - k) + \result;
  @/
  uint32_t word_low_of(int m, int k, uint64_t r)
  {
    uint64_t e = word_pow2_of(m - k);
    uint64_t f = word_pow2_of(BSCHED_MAX_PV - m);
    word_top(m, k, r, e, f);
    return (uint32_t)(r % e * f);
  }
*/

#endif /* BSCHED_SPEC_WORD_H */
