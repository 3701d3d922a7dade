/*
 * bsched/spec/bsched_slots.h: bsched_step's slot-by-slot count of the due
 * processes equals the class-by-class count `load` of the balance theorem.
 *
 * bsched_step scans order[] slot by slot and finds process order[d] due in
 * minor cycle t iff t mod 2^pv == offset (due_slots). Slot d of class k
 * (class_first(k) <= d < class_first(k + 1)) holds member j = d -
 * class_first(k) of class k (sorted_order), whose offset is rev_k((s_k + j)
 * mod 2^k) (closed_form); it is due iff rev_k(t mod 2^k) == (B_k + j) mod 2^k
 * (rev is an involution, s_k == B_k mod 2^k), which is the term `hits` counts
 * in `load`. ACSL and ghost code only. Included by bsched.c after
 * bsched_rev.h (lemma_rev_involution, lemma_start_is_area) and
 * bsched_balance.h.
 *
 * Contents (prefix slots_): the predicate slots_slot_ok (the fact about one
 * slot); lemma_slots_disjoint (slot ranges of classes are disjoint);
 * slots_area (a ghost function computing B_k = class_area, so that the
 * modular step below is stated on concrete values, with lemma_div_unique);
 * lemma_slots_mod_sum ((a mod p + j) mod p == (a + j) mod p);
 * lemma_slots_due (member j of class q is due iff it sits at residue
 * rev_q(t mod 2^q)); lemma_slots_init_wait (init_wait unfolded);
 * lemma_slots_slot / lemma_slots_all (the fact for one / every slot);
 * lemma_slots_step / lemma_slots_class (one slot / one class of the count);
 * lemma_slots_by_class (the result: due_slots == load).
 */
#ifndef BSCHED_SPEC_SLOTS_H
#define BSCHED_SPEC_SLOTS_H

/*@
  // The fact about one slot d: if d lies in class k's slot range, it holds a
  // process of class k that is due in cycle t exactly when member
  // d - class_first(k) of class k sits at residue rev_k(t mod 2^k).
  predicate slots_slot_ok{L}(struct bsched *s, integer t, integer d) =
      (\forall integer k; 0 <= k <= BSCHED_MAX_PV &&
          class_first{L}(&s->pv[0], s->count, k) <= d < class_first{L}(&s->pv[0], s->count, k + 1) ==>
          s->pv[s->order[d]] == k) &&
      (t % pow2(s->pv[s->order[d]]) == s->offset[s->order[d]] <==>
       (class_area{L}(&s->pv[0], s->count, s->pv[s->order[d]]) +
        (d - class_first{L}(&s->pv[0], s->count, s->pv[s->order[d]]))) % pow2(s->pv[s->order[d]]) ==
           rev(s->pv[s->order[d]], t % pow2(s->pv[s->order[d]])));
*/

/*@ ghost
  /@ requires n <= 65535;
     requires \forall integer i; 0 <= i < n ==> pv[i] <= BSCHED_MAX_PV;
     requires 0 <= q <= BSCHED_MAX_PV;
     requires class_first(pv, n, q) <= d < class_first(pv, n, q + 1);
     assigns \nothing;
     ensures disjoint: \forall integer k; 0 <= k <= BSCHED_MAX_PV &&
         class_first(pv, n, k) <= d < class_first(pv, n, k + 1) ==> k == q;
  @/
  void lemma_slots_disjoint(const uint8_t *pv, size_t n, int q, uint32_t d)
  {
    lemma_first(pv, n);
    /@ assert below_q: \forall integer k; 0 <= k < q ==>
           class_first(pv, n, k + 1) <= class_first(pv, n, q); @/
    /@ assert above_q: \forall integer k; q < k <= BSCHED_MAX_PV ==>
           class_first(pv, n, q + 1) <= class_first(pv, n, k); @/
  }
*/

/*@ ghost
  /@ requires n <= 65535 && \valid_read(pv + (0 .. n - 1));
     requires 0 <= q <= BSCHED_MAX_PV;
     assigns \nothing;
     ensures area: \result == class_area(pv, n, q);
     ensures area_range: 0 <= \result <= 131072 * pow2(q);
  @/
  int64_t slots_area(const uint8_t *pv, size_t n, int q)
  {
    int64_t a = 0;
    int k = 0;
    lemma_pow2(BSCHED_MAX_PV);
    /@ loop invariant k_range: 0 <= k <= q;
       loop invariant area_so_far: a == class_area(pv, n, k);
       loop invariant area_bound: 0 <= a && a + 131072 <= 131072 * pow2(k);
       loop assigns k, a;
       loop variant q - k;
    @/
    while (k < q) {
      int64_t c = 0;
      size_t i = 0;
      /@ loop invariant i_range: 0 <= i <= n;
         loop invariant count_so_far: c == class_count(pv, i, k) && 0 <= c <= i;
         loop assigns i, c;
         loop variant n - i;
      @/
      while (i < n) {
        if (pv[i] == k)
          c = c + 1;
        i = i + 1;
      }
      /@ assert period: pow2(k + 1) == 2 * pow2(k) && pow2(k) <= 2147483648; @/
      a = 2 * (a + c);
      k = k + 1;
    }
    return a;
  }
*/

/*@ ghost
  /@ requires 0 < p <= 2147483648 && a <= 281474976710656 && j <= 65536;
     assigns \nothing;
     ensures mod_sum: (a % p + j) % p == (a + j) % p;
  @/
  void lemma_slots_mod_sum(uint64_t a, uint64_t j, uint64_t p)
  {
    /@ assert split: a == p * (a / p) + a % p && 0 <= a % p < p && a / p >= 0 && a / p <= a; @/
    /@ assert split_x: a % p + j == p * ((a % p + j) / p) + (a % p + j) % p &&
           0 <= (a % p + j) % p < p && 0 <= (a % p + j) / p <= a % p + j; @/
    /@ assert regroup: a + j == p * (a / p + (a % p + j) / p) + (a % p + j) % p; @/
    lemma_div_unique(a + j, p, a / p + (a % p + j) / p, (a % p + j) % p);
  }
*/

/*@ ghost
  /@ requires n <= 65535;
     requires 0 <= q <= BSCHED_MAX_PV;
     requires a == class_area(pv, n, q) && 0 <= a <= 131072 * pow2(q);
     requires 0 <= j <= 65535;
     assigns \nothing;
     ensures due: t % pow2(q) == rev(q, (class_start(pv, n, q) + j) % pow2(q)) <==>
         (class_area(pv, n, q) + j) % pow2(q) == rev(q, t % pow2(q));
  @/
  void lemma_slots_due(const uint8_t *pv, size_t n, uint32_t t, int q, int64_t a, int j)
  {
    lemma_pow2(BSCHED_MAX_PV);
    lemma_rev_involution();
    lemma_start_is_area(pv, n);
    uint64_t p = (uint64_t)1 << q;
    /@ assert top: pow2(BSCHED_MAX_PV) == 2147483648; @/
    /@ assert bound: 1 <= pow2(q) <= pow2(BSCHED_MAX_PV); @/
    /@ assert shift: (1 << q) == pow2(q); @/
    /@ assert period: p == pow2(q); @/
    /@ assert area_small: a <= 281474976710656; @/
    lemma_slots_mod_sum((uint64_t)a, (uint64_t)j, p);
    /@ assert wrap: (a % pow2(q) + j) % pow2(q) == (a + j) % pow2(q); @/
    /@ assert start: class_start(pv, n, q) == a % pow2(q) && pow2(q) >= 1; @/
    /@ assert residue: (class_start(pv, n, q) + j) % pow2(q) == (a + j) % pow2(q); @/
    /@ assert residue_range: 0 <= (a + j) % pow2(q) < pow2(q); @/
    /@ assert flip: t % pow2(q) == rev(q, (a + j) % pow2(q)) <==>
           rev(q, t % pow2(q)) == (a + j) % pow2(q); @/
  }
*/

/*@ ghost
  /@ assigns \nothing;
     ensures init_wait_def: \forall integer i; 0 <= i ==> init_wait(pv, n, i) ==
         rev(pv[i], (class_start(pv, n, pv[i]) + class_count(pv, i, pv[i])) % pow2(pv[i]));
  @/
  void lemma_slots_init_wait(const uint8_t *pv, size_t n)
  {
  }
*/

/*@ ghost
  /@ requires \valid_read(s);
     requires 1 <= s->count <= BSCHED_MAX_PROCS;
     requires \forall integer i; 0 <= i < s->count ==> s->pv[i] <= BSCHED_MAX_PV;
     requires sorted_order(s) && closed_form(s);
     requires 0 <= d < s->count;
     assigns \nothing;
     ensures slot_ok: slots_slot_ok(s, t, d);
  @/
  void lemma_slots_slot(struct bsched *s, uint32_t t, uint32_t d)
  {
    uint16_t p = s->order[d];
    uint8_t q = s->pv[p];
    int j = 0;
    int i = 0;
    int64_t a = 0;
    lemma_count(s->pv, s->count);
    lemma_first(s->pv, s->count);
    lemma_slots_init_wait(s->pv, s->count);
    /@ assert p_slot: p < s->count && sorted_pos(&s->pv[0], s->count, p) == d; @/
    /@ loop invariant i_range: 0 <= i <= p;
       loop invariant rank_so_far: j == class_count(&s->pv[0], i, q) && 0 <= j <= i;
       loop assigns i, j;
       loop variant p - i;
    @/
    while (i < p) {
      if (s->pv[i] == q)
        j = j + 1;
      i = i + 1;
    }
    a = slots_area(s->pv, s->count, q);
    lemma_slots_due(s->pv, s->count, t, q, a, j);
    /@ assert q_range: 0 <= q <= BSCHED_MAX_PV; @/
    /@ assert pos_split: sorted_pos(&s->pv[0], s->count, p) ==
           class_first(&s->pv[0], s->count, q) + class_count(&s->pv[0], p, q); @/
    /@ assert rank_range: 0 <= class_count(&s->pv[0], p, q) < class_count(&s->pv[0], s->count, q); @/
    /@ assert next_q: class_first(&s->pv[0], s->count, q + 1) ==
           class_first(&s->pv[0], s->count, q) + class_count(&s->pv[0], s->count, q); @/
    /@ assert in_q: class_first(&s->pv[0], s->count, q) <= d < class_first(&s->pv[0], s->count, q + 1); @/
    /@ assert rank: j == class_count(&s->pv[0], p, q); @/
    /@ assert closed: s->offset[p] == init_wait(&s->pv[0], s->count, p); @/
    /@ assert wait: s->offset[p] == rev(q, (class_start(&s->pv[0], s->count, q) +
           class_count(&s->pv[0], p, q)) % pow2(q)); @/
    /@ assert rank_is_slot: class_count(&s->pv[0], p, q) == d - class_first(&s->pv[0], s->count, q); @/
    /@ assert due: t % pow2(q) == s->offset[p] <==>
           (class_area(&s->pv[0], s->count, q) + (d - class_first(&s->pv[0], s->count, q))) % pow2(q) ==
               rev(q, t % pow2(q)); @/
    /@ assert at_q: s->pv[s->order[d]] == q &&
           (t % pow2(q) == s->offset[s->order[d]] <==>
            (class_area(&s->pv[0], s->count, q) + (d - class_first(&s->pv[0], s->count, q))) % pow2(q) ==
                rev(q, t % pow2(q))); @/
    lemma_slots_disjoint(s->pv, s->count, q, d);
    /@ assert only_q: \forall integer k; 0 <= k <= BSCHED_MAX_PV &&
           class_first(&s->pv[0], s->count, k) <= d < class_first(&s->pv[0], s->count, k + 1) ==> k == q; @/
  }
*/

/*@ ghost
  /@ requires \valid_read(s);
     requires 1 <= s->count <= BSCHED_MAX_PROCS;
     requires \forall integer i; 0 <= i < s->count ==> s->pv[i] <= BSCHED_MAX_PV;
     requires sorted_order(s) && closed_form(s);
     assigns \nothing;
     ensures slots_ok: \forall integer d; 0 <= d < s->count ==> slots_slot_ok(s, t, d);
  @/
  void lemma_slots_all(struct bsched *s, uint32_t t)
  {
    uint32_t d = 0;
    /@ loop invariant d_range: 0 <= d <= s->count;
       loop invariant slots_so_far: \forall integer e; 0 <= e < d ==> slots_slot_ok(s, t, e);
       loop assigns d;
       loop variant s->count - d;
    @/
    while (d < s->count) {
      lemma_slots_slot(s, t, d);
      d = d + 1;
    }
  }
*/

/*@ ghost
  /@ requires \valid_read(s);
     requires 1 <= s->count <= BSCHED_MAX_PROCS;
     requires ranges: 0 <= k <= BSCHED_MAX_PV && 0 <= j;
     requires first_nonneg: 0 <= class_first(&s->pv[0], s->count, k);
     requires in_class: class_first(&s->pv[0], s->count, k) + j < class_first(&s->pv[0], s->count, k + 1);
     requires slot_class: s->pv[s->order[class_first(&s->pv[0], s->count, k) + j]] == k;
     requires slot_due: \let d = class_first(&s->pv[0], s->count, k) + j; \let m = s->pv[s->order[d]];
         t % pow2(m) == s->offset[s->order[d]] <==>
         (class_area(&s->pv[0], s->count, m) + (d - class_first(&s->pv[0], s->count, m))) % pow2(m) ==
             rev(m, t % pow2(m));
     assigns \nothing;
     ensures step: due_slots(s, t, class_first(&s->pv[0], s->count, k) + j + 1) ==
         due_slots(s, t, class_first(&s->pv[0], s->count, k) + j) +
         ((class_area(&s->pv[0], s->count, k) + j) % pow2(k) == rev(k, t % pow2(k)) ? 1 : 0);
  @/
  void lemma_slots_step(struct bsched *s, uint32_t t, int k, int j)
  {
    /@ assert slot_due: t % pow2(k) == s->offset[s->order[class_first(&s->pv[0], s->count, k) + j]] <==>
           (class_area(&s->pv[0], s->count, k) + j) % pow2(k) == rev(k, t % pow2(k)); @/
    /@ assert due_step: due_slots(s, t, class_first(&s->pv[0], s->count, k) + j + 1) ==
           due_slots(s, t, class_first(&s->pv[0], s->count, k) + j) +
           (t % pow2(s->pv[s->order[class_first(&s->pv[0], s->count, k) + j]]) ==
                s->offset[s->order[class_first(&s->pv[0], s->count, k) + j]] ? 1 : 0); @/
  }
*/

/*@ ghost
  /@ requires \valid_read(s);
     requires 1 <= s->count <= BSCHED_MAX_PROCS;
     requires \forall integer i; 0 <= i < s->count ==> s->pv[i] <= BSCHED_MAX_PV;
     requires 0 <= k <= BSCHED_MAX_PV;
     requires slots_ok: \forall integer d; 0 <= d < s->count ==> slots_slot_ok(s, t, d);
     assigns \nothing;
     ensures class_step: due_slots(s, t, class_first(&s->pv[0], s->count, k + 1)) ==
         due_slots(s, t, class_first(&s->pv[0], s->count, k)) +
         hits(k, class_area(&s->pv[0], s->count, k), class_count(&s->pv[0], s->count, k),
              rev(k, t % pow2(k)));
  @/
  void lemma_slots_class(struct bsched *s, uint32_t t, int k)
  {
    int i = 0;
    int c = 0;
    int j = 0;
    lemma_pow2(BSCHED_MAX_PV);
    lemma_count(s->pv, s->count);
    lemma_first(s->pv, s->count);
    /@ loop invariant i_range: 0 <= i <= s->count;
       loop invariant count_so_far: c == class_count(&s->pv[0], i, k) && c <= i;
       loop assigns i, c;
       loop variant s->count - i;
    @/
    while (i < s->count) {
      if (s->pv[i] == k)
        c = c + 1;
      i = i + 1;
    }
    /@ assert class_end: class_first(&s->pv[0], s->count, k + 1) ==
           class_first(&s->pv[0], s->count, k) + c; @/
    /@ assert class_in: class_first(&s->pv[0], s->count, k + 1) <= s->count; @/
    /@ assert first_nonneg: class_first(&s->pv[0], s->count, 0) == 0 &&
           0 <= class_first(&s->pv[0], s->count, k); @/
    /@ loop invariant j_range: 0 <= j <= c;
       loop invariant first_nonneg: 0 <= class_first(&s->pv[0], s->count, k);
       loop invariant class_end: class_first(&s->pv[0], s->count, k + 1) ==
           class_first(&s->pv[0], s->count, k) + c <= s->count;
       loop invariant slots_so_far: due_slots(s, t, class_first(&s->pv[0], s->count, k) + j) ==
           due_slots(s, t, class_first(&s->pv[0], s->count, k)) +
           hits(k, class_area(&s->pv[0], s->count, k), j, rev(k, t % pow2(k)));
       loop assigns j;
       loop variant c - j;
    @/
    while (j < c) {
      /@ assert slot_range: 0 <= class_first(&s->pv[0], s->count, k) + j < s->count; @/
      /@ assert slot: slots_slot_ok(s, t, class_first(&s->pv[0], s->count, k) + j); @/
      lemma_slots_step(s, t, k, j);
      /@ assert hits_step: hits(k, class_area(&s->pv[0], s->count, k), j + 1, rev(k, t % pow2(k))) ==
             hits(k, class_area(&s->pv[0], s->count, k), j, rev(k, t % pow2(k))) +
             ((class_area(&s->pv[0], s->count, k) + j) % pow2(k) == rev(k, t % pow2(k)) ? 1 : 0); @/
      /@ assert next: due_slots(s, t, class_first(&s->pv[0], s->count, k) + (j + 1)) ==
             due_slots(s, t, class_first(&s->pv[0], s->count, k)) +
             hits(k, class_area(&s->pv[0], s->count, k), j + 1, rev(k, t % pow2(k))); @/
      j = j + 1;
    }
  }
*/

/*@ ghost
  /@ requires \valid_read(s);
     requires 1 <= s->count <= BSCHED_MAX_PROCS;
     requires \forall integer i; 0 <= i < s->count ==> s->pv[i] <= BSCHED_MAX_PV;
     requires sorted_order(s) && closed_form(s);
     assigns \nothing;
     ensures slots_are_load: due_slots(s, t, s->count) == load(&s->pv[0], s->count, t);
  @/
  void lemma_slots_by_class(struct bsched *s, uint32_t t)
  {
    int k = 0;
    lemma_first(s->pv, s->count);
    lemma_slots_all(s, t);
    /@ loop invariant k_range: 0 <= k <= BSCHED_MAX_PV + 1;
       loop invariant classes_so_far: due_slots(s, t, class_first(&s->pv[0], s->count, k)) ==
           load_upto(&s->pv[0], s->count, t, k);
       loop assigns k;
       loop variant BSCHED_MAX_PV + 1 - k;
    @/
    while (k < BSCHED_MAX_PV + 1) {
      lemma_slots_class(s, t, k);
      k = k + 1;
    }
  }
*/

#endif /* BSCHED_SPEC_SLOTS_H */
