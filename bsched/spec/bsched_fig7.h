/*
 * bsched/spec/bsched_fig7.h: the ACSL specification of the reference engine
 * bsched/proofs/ref/bsched_fig7.c (Fig. 7 with per-process waits over a plan made by
 * bsched_init).
 *
 * The plan is a struct bsched; the engine's mutable state (cycle, waits, ran)
 * is a struct bsched_fig7. The predicates here are the ones bsched_step's
 * proof states over a single struct, restated over the pair (r, plan): the
 * balance and periodicity facts about the plan itself (sorted_order,
 * closed_form, due_slots, load, lemma_slots_by_class, lemma_balance,
 * lemma_fold) come unchanged from the shared spec. Included after
 * bsched_logic.h, bsched_lemmas.h and the other shared spec headers, and after
 * bsched_fig7.h. No axiom: logic definitions and lemma functions only.
 */
#ifndef BSCHED_SPEC_FIG7_H
#define BSCHED_SPEC_FIG7_H

/*@
  // A plan as bsched_init leaves it: its sizes and ranges, order[] the stable
  // sort by pv, the offsets Fig. 6's closed form, perfect = ceil(U).
  predicate fig7_plan{L}(struct bsched *s) =
      well_formed{L}(s) && sorted_order{L}(s) && closed_form{L}(s) &&
      s->perfect == perfect_of{L}(&s->pv[0], s->count);

  // The engine's ranges: the cycle within the major cycle, waits below their period.
  predicate fig7_well_formed{L}(struct bsched_fig7 *r, struct bsched *s) =
      0 <= r->cycle < pow2(s->maxpv) &&
      \forall integer i; 0 <= i < s->count ==> r->wait[i] < pow2(s->pv[i]);

  // The periodicity invariant at the start of minor cycle t = r->cycle:
  // wait_i = (offset_i - t) mod 2^pv_i, i.e. process i is due (wait 0) exactly
  // when t = offset_i (mod 2^pv_i).
  predicate fig7_in_phase{L}(struct bsched_fig7 *r, struct bsched *s) =
      \forall integer i; 0 <= i < s->count ==>
          (r->cycle + r->wait[i]) % pow2(s->pv[i]) == s->offset[i];

  // How many of the slots order[0 .. d-1] hold a process whose wait is 0.
  logic integer fig7_zero_slots{L}(struct bsched_fig7 *r, struct bsched *s, integer d) =
      d <= 0 ? 0 : fig7_zero_slots{L}(r, s, d - 1) + (r->wait[s->order[d - 1]] == 0 ? 1 : 0);

  // Process i ran in the last step.
  predicate fig7_ran_last{L}(struct bsched_fig7 *r, integer i) =
      \exists integer j; 0 <= j < r->ran_count && r->ran[j] == i;
*/

/*@ ghost
  /@ requires \valid_read(r) && \valid_read(s) && 0 <= n <= BSCHED_MAX_PROCS;
     assigns \nothing;
     ensures zero_monotone: \forall integer a, b; 0 <= a <= b <= n ==>
         fig7_zero_slots(r, s, a) <= fig7_zero_slots(r, s, b);
     ensures zero_strict: \forall integer a, d; 0 <= a <= d < n && r->wait[s->order[d]] == 0 ==>
         fig7_zero_slots(r, s, a) < fig7_zero_slots(r, s, n);
  @/
  void lemma_fig7_zero_slots(struct bsched_fig7 *r, const struct bsched *s, uint32_t n)
  {
    uint32_t x = 0;
    /@ loop invariant 0 <= x <= n;
       loop invariant \forall integer a, b; 0 <= a <= b <= x ==>
           fig7_zero_slots(r, s, a) <= fig7_zero_slots(r, s, b);
       loop invariant \forall integer a, d; 0 <= a <= d < x && r->wait[s->order[d]] == 0 ==>
           fig7_zero_slots(r, s, a) < fig7_zero_slots(r, s, x);
       loop assigns x;
       loop variant n - x;
    @/
    while (x < n) {
      x = x + 1;
    }
  }
*/

/* Back in phase for cycle c = t + 1 (mod 2^maxpv) after a step: a process that
 * ran restarts a full period (t + 2^pv == t mod 2^pv), the others counted down
 * by one; the cycle counter wraps at 2^maxpv, a multiple of every period.
 * Stated for the next cycle c before it is stored in r->cycle, so that the
 * waits need not be carried across that store. */
/*@ ghost
  /@ requires \valid_read(r) && \valid_read(s);
     requires 1 <= s->count <= BSCHED_MAX_PROCS && s->maxpv <= BSCHED_MAX_PV;
     requires \forall integer q; 0 <= q < s->count ==> s->pv[q] <= s->maxpv;
     requires \forall integer q; 0 <= q < s->count ==> r->wait[q] < pow2(s->pv[q]);
     requires t + 1 <= pow2(s->maxpv) && c == (t + 1) % pow2(s->maxpv);
     requires \forall integer q; 0 <= q < s->count ==>
         (r->wait[q] + 1 == pow2(s->pv[q]) && t % pow2(s->pv[q]) == s->offset[q]) ||
         (t + r->wait[q] + 1) % pow2(s->pv[q]) == s->offset[q];
     assigns \nothing;
     ensures in_phase: \forall integer q; 0 <= q < s->count ==>
         (c + r->wait[q]) % pow2(s->pv[q]) == s->offset[q];
  @/
  void lemma_fig7_next_phase(struct bsched_fig7 *r, const struct bsched *s, uint32_t t, uint32_t c)
  {
    uint32_t g;
    /@ loop invariant 0 <= g <= s->count;
       loop invariant \forall integer q; 0 <= q < g ==>
           (c + r->wait[q]) % pow2(s->pv[q]) == s->offset[q];
       loop assigns g;
       loop variant s->count - g;
    @/
    for (g = 0u; g < s->count; g++) {
      lemma_full_period(t, s->pv[g]);
      lemma_wrap_pow2(c, r->wait[g], t, s->pv[g], s->maxpv);
    }
  }
*/

#endif /* BSCHED_SPEC_FIG7_H */
