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
 * Names follow ../../shared/notes/why-b-schedules-are-balanced.md:
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

  // Bit reversal, stated arithmetically: take the lowest bit of `rest` n
  // times and shift it into `acc` from the right. rev(k, x) = rev_k(x).
  logic integer rev_acc(integer n, integer rest, integer acc) =
      n <= 0 ? acc : rev_acc(n - 1, rest / 2, acc * 2 + rest % 2);
  logic integer rev(integer k, integer x) = rev_acc(k, x, 0);

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

  // The initial wait of process i among pv[0 .. n-1] (Fig. 6 in closed form):
  // member j = class_count(pv, i, k) of class k = pv[i] gets rev_k((s_k + j) mod 2^k).
  // For class 0 this is rev_0(..) = 0.
  logic integer init_wait{L}(uint8_t *pv, integer n, integer i) =
      rev(pv[i], (class_start{L}(pv, n, pv[i]) + class_count{L}(pv, i, pv[i])) % pow2(pv[i]));

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

  // Residues are unchanged by adding whole periods (used for the wrap of the
  // cycle counter at the end of a major cycle). Proven by WP like any goal.
  lemma mod_add_period: \forall integer x, p; p > 0 && x >= 0 ==> (x + p) % p == x % p;
  lemma mod_add_periods: \forall integer x, p, q; p > 0 && q >= 0 && x >= 0 ==>
      (x + p * q) % p == x % p;

  // ---- The scheduler state ----

  // What bsched_init establishes and bsched_step keeps: sizes and ranges that
  // make every access of bsched_step and bsched_due safe, waits below their
  // period, offsets below their period, and order[] a map into the processes
  // into the processes.
  predicate well_formed{L}(struct bsched *s) =
      1 <= s->count <= BSCHED_MAX_PROCS && s->maxpv <= BSCHED_MAX_PV &&
      1 <= s->perfect && s->perfect <= s->count &&
      s->cycle < pow2(s->maxpv) &&
      (\forall integer i; 0 <= i < s->count ==>
           s->pv[i] <= s->maxpv && s->wait[i] < pow2(s->pv[i]) &&
           s->offset[i] < pow2(s->pv[i])) &&
      (\forall integer id; 0 <= id < s->count ==> s->order[id] < s->count);

  // The periodicity invariant of the hand proof, at the start of minor cycle
  // t = s->cycle: wait_i = (offset_i - t) mod 2^pv_i, i.e. process i is due
  // (wait 0) exactly when t = offset_i (mod 2^pv_i).
  predicate in_phase{L}(struct bsched *s) =
      \forall integer i; 0 <= i < s->count ==>
          (s->cycle + s->wait[i]) % pow2(s->pv[i]) == s->offset[i];

  // Process i ran in the last step.
  predicate ran_last{L}(struct bsched *s, integer i) =
      \exists integer j; 0 <= j < s->ran_count && s->ran[j] == i;
*/

#endif /* BSCHED_SPEC_LOGIC_H */
