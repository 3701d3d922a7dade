/*
 * bsched/spec/bsched_logic.h: the ACSL specification of the B-scheduler.
 *
 * Only comments for a C compiler; Frama-C reads the annotations. Included by
 * bsched.c after bsched.h. Every definition here is arithmetic (no bitwise
 * operators), so the provers see integers, +, *, / and %, never bit-vectors.
 * There is no `axiomatic` block and no axiom: only logic definitions (WP
 * turns each recursive definition into its defining equations) and lemmas
 * that WP proves like any other goal.
 *
 * Names follow the hand proof (bsched/proofs/README.md, the balance theorem):
 *   pow2(k)                 2^k
 *   rev(k, x)               rev_k(x): the low k bits of x in reverse order
 *   class_count(pv, n, k)   #{ i < n : pv[i] == k }   (c_k over a prefix)
 *   class_first(pv, n, k)   sum_{k' < k} c_k'          (first slot of class k)
 *   class_start(pv, n, k)   s_k of Fig. 6 (the value of `start` for class k)
 *   init_wait(pv, n, i)     rev_k((s_k + j) mod 2^k), k = pv[i], j = rank of i in its class
 *   carry_from(pv, n, k)    the perfect-fold of bsched_init over classes k..31
 */
#ifndef BSCHED_SPEC_LOGIC_H
#define BSCHED_SPEC_LOGIC_H

/*@
  // 2^k for k >= 0.
  logic integer pow2(integer k) = k <= 0 ? 1 : 2 * pow2(k - 1);

  // Bit b of x (x >= 0), stated arithmetically.
  logic integer bit_of(integer x, integer b) = (x / pow2(b)) % 2;

  // Bit reversal, stated arithmetically: rev(k, x) = rev_k(x), the low k bits
  // of x in reverse order (bit b of x becomes bit k-1-b of the result). Built
  // from the top: rev_(k+1)(x) = 2 * rev_k(x) + bit k of x, which is also how
  // reverse_bits computes it, one bit per iteration.
  logic integer rev(integer k, integer x) = k <= 0 ? 0 : 2 * rev(k - 1, x) + bit_of(x, k - 1);

  // c_k over the prefix pv[0 .. n-1]: how many of them have priority value k.
  logic integer class_count{L}(uint8_t *pv, integer n, integer k) =
      n <= 0 ? 0 : class_count{L}(pv, n - 1, k) + (pv[n - 1] == k ? 1 : 0);

  // First slot of class k in the sorted order: the size of the classes below k.
  logic integer class_first{L}(uint8_t *pv, integer n, integer k) =
      k <= 0 ? 0 : class_first{L}(pv, n, k - 1) + class_count{L}(pv, n, k - 1);

  // Where the stable sort puts process i: after the lower classes and after the
  // earlier members of its own class.
  logic integer sorted_pos{L}(uint8_t *pv, integer n, integer i) =
      class_first{L}(pv, n, pv[i]) + class_count{L}(pv, i, pv[i]);

  // s_k of Fig. 6: s_0 = 0, s_(k+1) = 2 * ((s_k + c_k) mod 2^k); s_1 = 2 * (c_0 mod 1) = 0.
  logic integer class_start{L}(uint8_t *pv, integer n, integer k) =
      k <= 0 ? 0
             : 2 * ((class_start{L}(pv, n, k - 1) + class_count{L}(pv, n, k - 1)) % pow2(k - 1));

  // Fig. 6 maps the position x of a class-k member to its initial wait by bit
  // reversal. The negative check builds a deliberately wrong variant
  // (-DBSCHED_MUTANT_NO_REVERSE: the identity, in the code and here); then
  // everything up to bsched_init still proves, and the balance proof fails.
#ifdef BSCHED_MUTANT_NO_REVERSE
  logic integer fig6_map(integer k, integer x) = x;
#else
  logic integer fig6_map(integer k, integer x) = rev(k, x);
#endif

  // The initial wait of process i among pv[0 .. n-1] (Fig. 6 in closed form):
  // member j = class_count(pv, i, k) of class k = pv[i] gets rev_k((s_k + j) mod 2^k).
  // For class 0 this is rev_0(..) = 0.
  logic integer init_wait{L}(uint8_t *pv, integer n, integer i) =
      fig6_map(pv[i], (class_start{L}(pv, n, pv[i]) + class_count{L}(pv, i, pv[i])) % pow2(pv[i]));

  // The perfect fold of bsched_init: carry_k = ceil((c_k + carry_(k+1)) / 2)
  // for k = 31 down to 1, carry_32 = 0; perfect = c_0 + carry_1.
  logic integer carry_from{L}(uint8_t *pv, integer n, integer k) =
      k > BSCHED_MAX_PV || k < 1 ? 0
          : (class_count{L}(pv, n, k) + carry_from{L}(pv, n, k + 1) + 1) / 2;
  logic integer perfect_of{L}(uint8_t *pv, integer n) =
      class_count{L}(pv, n, 0) + carry_from{L}(pv, n, 1);

  // The area of the set in units of 2^-31 of a minor cycle: sum_i 2^(31 - pv_i),
  // i.e. U * 2^31 with U = sum_i 2^-pv_i.
  logic integer area{L}(uint8_t *pv, integer n) =
      n <= 0 ? 0 : area{L}(pv, n - 1) + pow2(BSCHED_MAX_PV - pv[n - 1]);

  // The largest priority value among pv[0 .. n-1] (0 for an empty prefix).
  logic integer max_pv{L}(uint8_t *pv, integer n) =
      n <= 0 ? 0 : (pv[n - 1] > max_pv{L}(pv, n - 1) ? pv[n - 1] : max_pv{L}(pv, n - 1));

  // ---- Balance (bsched/proofs/README.md: how it is proven) ----
  // The hand proof's interval picture, per class. Class k's c_k processes sit
  // side by side after the lower classes, each 2^-k of a minor cycle wide.

  // B_k: the area of the classes below k, in units of 2^-k of a minor cycle:
  // B_0 = 0, B_(k+1) = 2 * (B_k + c_k). Member j of class k starts at B_k + j.
  logic integer class_area{L}(uint8_t *pv, integer n, integer k) =
      k <= 0 ? 0 : 2 * (class_area{L}(pv, n, k - 1) + class_count{L}(pv, n, k - 1));

  // The area of all classes, in units of 2^-31: U * 2^31 with U = sum_i 2^-pv_i.
  logic integer total_area{L}(uint8_t *pv, integer n) =
      class_area{L}(pv, n, BSCHED_MAX_PV) + class_count{L}(pv, n, BSCHED_MAX_PV);

  // below(k, r, x) = #{ m >= 0 : r + m * 2^k < x }, for 0 <= r < 2^k and x >= 0:
  // how many of the positions 0 .. x-1 are r modulo 2^k, i.e. ceil((x - r) / 2^k)
  // (0 when x <= r).
  logic integer below(integer k, integer r, integer x) = (x - r + pow2(k) - 1) / pow2(k);

  // hits(k, b, c, r) = #{ j < c : (b + j) mod 2^k == r }: the members of a class
  // of c processes of priority k, starting at position b, that sit at residue r.
  logic integer hits(integer k, integer b, integer c, integer r) =
      c <= 0 ? 0 : hits(k, b, c - 1, r) + ((b + c - 1) % pow2(k) == r ? 1 : 0);

  // The processes due in minor cycle t (t >= 0), counted class by class: member
  // j of class k is due iff rev_k(t mod 2^k) == (B_k + j) mod 2^k. load_upto
  // counts classes 0 .. k-1; load counts them all.
  logic integer load_upto{L}(uint8_t *pv, integer n, integer t, integer k) =
      k <= 0 ? 0
             : load_upto{L}(pv, n, t, k - 1) +
               hits(k - 1, class_area{L}(pv, n, k - 1), class_count{L}(pv, n, k - 1),
                    rev(k - 1, t % pow2(k - 1)));
  logic integer load{L}(uint8_t *pv, integer n, integer t) =
      load_upto{L}(pv, n, t, BSCHED_MAX_PV + 1);

  // ---- The scheduler state ----

  // What bsched_init establishes and bsched_step keeps: sizes and ranges that
  // make every access of bsched_step, bsched_due and bsched_wait safe, offsets
  // below their period, and order[] a map into the processes.
  predicate well_formed{L}(struct bsched *s) =
      1 <= s->count <= BSCHED_MAX_PROCS && s->maxpv <= BSCHED_MAX_PV &&
      1 <= s->perfect && s->perfect <= s->count &&
      s->cycle < pow2(s->maxpv) &&
      (\forall integer i; 0 <= i < s->count ==>
           s->pv[i] <= s->maxpv && s->offset[i] < pow2(s->pv[i])) &&
      (\forall integer id; 0 <= id < s->count ==> s->order[id] < s->count);

  // order[] is the stable sort by priority value: slot d holds the process
  // whose sorted position is d, and every process sits at its sorted position.
  predicate sorted_order{L}(struct bsched *s) =
      (\forall integer d; 0 <= d < s->count ==>
           s->order[d] < s->count && sorted_pos{L}(&s->pv[0], s->count, s->order[d]) == d) &&
      (\forall integer i; 0 <= i < s->count ==>
           0 <= sorted_pos{L}(&s->pv[0], s->count, i) < s->count &&
           s->order[sorted_pos{L}(&s->pv[0], s->count, i)] == i);

  // The offsets are Fig. 6's initial waits of the set in s->pv.
  predicate closed_form{L}(struct bsched *s) =
      \forall integer i; 0 <= i < s->count ==>
          s->offset[i] == init_wait{L}(&s->pv[0], s->count, i);

  // Class k's residue test on 31-bit words (bsched.h): its key is
  // (2^31 - s_k 2^(31-k)) mod 2^31 = ((2^k - s_k) mod 2^k) 2^(31-k) and its limit min(c_k, 2^k) 2^(31-k)
  // (s_k Fig. 6's start, c_k the class's size); both at most 2^31.
  logic integer class_key_of(integer start, integer k) =
      (2147483648 - start * pow2(31 - k)) % 2147483648;
  logic integer class_limit_of(integer size, integer k) =
      (size < pow2(k) ? size : pow2(k)) * pow2(31 - k);

  // How many of the slots order[0 .. d-1] hold a process due in cycle t
  // (t = offset mod 2^pv): the processes bsched_step finds due, in its order.
  logic integer due_slots{L}(struct bsched *s, integer t, integer d) =
      d <= 0 ? 0
             : due_slots{L}(s, t, d - 1) +
               (t % pow2(s->pv[s->order[d - 1]]) == s->offset[s->order[d - 1]] ? 1 : 0);

  // The class table of bsched_step: class k occupies the slots class_first[k] ..
  // class_first[k] + class_size[k] - 1 of order[]; class_key[k] and
  // class_limit[k] are its residue test on 31-bit words (class_key_of,
  // class_limit_of); every class in use lies between minpv and maxpv.
  predicate class_table{L}(struct bsched *s) =
      s->minpv <= s->maxpv &&
      (\forall integer i; 0 <= i < s->count ==> s->minpv <= s->pv[i]) &&
      (\forall integer k; 0 <= k <= BSCHED_MAX_PV ==>
           s->class_first[k] == class_first{L}(&s->pv[0], s->count, k) &&
           s->class_size[k] == class_count{L}(&s->pv[0], s->count, k) &&
           s->class_key[k] == class_key_of(class_start{L}(&s->pv[0], s->count, k), k) &&
           s->class_limit[k] == class_limit_of(class_count{L}(&s->pv[0], s->count, k), k));

  // Everything bsched_init establishes and bsched_step keeps: the state is well
  // formed, sorted and in closed form, perfect is the fold, the class table
  // describes order[], and `reversed` is the bit-reversed cycle counter.
  predicate scheduled{L}(struct bsched *s) =
      well_formed(s) && sorted_order(s) && closed_form(s) &&
      s->perfect == perfect_of{L}(&s->pv[0], s->count) &&
      class_table(s) && s->reversed == rev(s->maxpv, s->cycle);

  // Process i ran in the last step.
  predicate ran_last{L}(struct bsched *s, integer i) =
      \exists integer j; 0 <= j < s->ran_count && s->ran[j] == i;
*/

#endif /* BSCHED_SPEC_LOGIC_H */
