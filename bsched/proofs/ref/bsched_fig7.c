/*
 * bsched_fig7.c: Fig. 7 of Birk, Kenn, Steels (2002) over a plan made by
 * bsched_init, the reference engine of bsched_step (see bsched_fig7.h).
 * Proven with Frama-C WP against the properties of bsched_step's contract,
 * restated over (r, plan) in spec/bsched_fig7.h.
 */
#include "bsched_fig7.h"
#include "spec/bsched_logic.h"
#include "spec/bsched_lemmas.h"
#include "spec/bsched_order.h"
#include "spec/bsched_fold.h"
#include "spec/bsched_rev.h"
#include "spec/bsched_balance.h"
#include "spec/bsched_slots.h"
#include "spec/bsched_fig7.h"

/*@ predicate fig7_plausible{L}(struct bsched *s) =
      1 <= s->count <= BSCHED_MAX_PROCS && s->maxpv <= BSCHED_MAX_PV && s->perfect >= 1;
*/

/* bsched's cheap check that the plan came from bsched_init (a zeroed struct
 * does not): 1 <= count <= BSCHED_MAX_PROCS, maxpv <= BSCHED_MAX_PV, perfect >= 1. */
/*@ requires \valid_read(s);
    assigns \nothing;
    ensures plausible_iff: \result != 0 <==> fig7_plausible(s);
*/
static int fig7_plan_plausible(const struct bsched *s)
{
    /* count - 1 < MAX: the upper bound without an always-true comparison at MAX = 65535. */
    return s->count != 0u && (uint32_t)s->count - 1u < (uint32_t)BSCHED_MAX_PROCS &&
           s->maxpv <= BSCHED_MAX_PV && s->perfect >= 1u;
}

/* 2^pv as the period of a class, pv <= BSCHED_MAX_PV. */
/*@ requires pv_range: pv <= BSCHED_MAX_PV;
    assigns \nothing;
    ensures is_pow2: \result == pow2(pv);
*/
static uint32_t fig7_period(uint8_t pv)
{
    /*@ ghost lemma_pow2(BSCHED_MAX_PV); */
    return (uint32_t)1u << pv;
}

/*@ requires valid: r == \null || \valid(r);
    requires valid_plan: plan == \null || \valid_read(plan);
    requires separated: r != \null && plan != \null ==> \separated(r, plan);
    requires from_init: plan != \null && fig7_plausible(plan) ==> fig7_plan(plan);
    assigns r->wait[0 .. BSCHED_MAX_PROCS - 1], r->cycle, r->ran_count;

    behavior null:
      assumes r == \null || plan == \null;
      assigns \nothing;
      ensures \result == BSCHED_ERR_NULL;
    behavior bad_state:
      assumes r != \null && plan != \null && !fig7_plausible(plan);
      assigns \nothing;
      ensures \result == BSCHED_ERR_STATE;
    behavior ok:
      assumes r != \null && plan != \null && fig7_plausible(plan);
      ensures ok_result: \result == BSCHED_OK;
      ensures ok_start: r->cycle == 0 && r->ran_count == 0;
      ensures ok_waits: \forall integer i; 0 <= i < plan->count ==> r->wait[i] == plan->offset[i];
      ensures ok_well_formed: fig7_well_formed(r, plan);
      ensures ok_in_phase: fig7_in_phase(r, plan);
    complete behaviors;
    disjoint behaviors;
*/
int32_t bsched_fig7_start(struct bsched_fig7 *r, const struct bsched *plan)
{
    uint32_t i;
    uint32_t count;

    if (r == NULL || plan == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!fig7_plan_plausible(plan)) {
        return BSCHED_ERR_STATE;
    }
    count = plan->count;
    /*@ loop invariant 0 <= i <= count;
        loop invariant \forall integer j; 0 <= j < i ==> r->wait[j] == plan->offset[j];
        loop assigns i, r->wait[0 .. BSCHED_MAX_PROCS - 1];
        loop variant count - i;
    */
    for (i = 0u; i < count; i++) {
        r->wait[i] = plan->offset[i];
    }
    r->cycle = 0;
    r->ran_count = 0u;
    /*@ ghost lemma_pow2(BSCHED_MAX_PV); */
    /*@ assert waits_in_phase: \forall integer j; 0 <= j < count ==>
            0 <= r->wait[j] < pow2(plan->pv[j]) && (0 + r->wait[j]) % pow2(plan->pv[j]) == plan->offset[j]; */
    return BSCHED_OK;
}

/* Fig. 7, lines 5-12: run the processes whose wait is 0, in the order of
 * plan->order, at most `perfect` of them, and restart their waits. The
 * contract says the cap never bites when at most `perfect` waits are 0
 * (bsched_fig7_step shows that from the balance theorem). */
/*@ requires \valid(r) && \valid_read(plan) && \separated(r, plan);
    requires sizes: 1 <= count <= BSCHED_MAX_PROCS && count == plan->count && perfect <= count;
    requires pv_range: \forall integer q; 0 <= q < count ==> plan->pv[q] <= BSCHED_MAX_PV;
    requires wait_range: \forall integer q; 0 <= q < count ==> r->wait[q] < pow2(plan->pv[q]);
    requires slots: \forall integer d; 0 <= d < count ==> plan->order[d] < count;
    requires distinct: \forall integer d, e; 0 <= d < e < count ==> plan->order[d] != plan->order[e];
    requires onto: \forall integer q; 0 <= q < count ==>
        0 <= sorted_pos(&plan->pv[0], count, q) < count &&
        plan->order[sorted_pos(&plan->pv[0], count, q)] == q;
    requires enough: fig7_zero_slots(r, plan, count) <= perfect;
    assigns r->ran[0 .. BSCHED_MAX_PROCS - 1], r->wait[0 .. BSCHED_MAX_PROCS - 1];
    ensures counted: \result == \old(fig7_zero_slots(r, plan, count));
    ensures ran_were_zero: \forall integer j; 0 <= j < \result ==>
        r->ran[j] < count && \let q = (integer)r->ran[j]; \old(r->wait[q]) == 0;
    ensures zeros_ran: \forall integer q; 0 <= q < count && \old(r->wait[q]) == 0 ==>
        \exists integer j; 0 <= j < \result && r->ran[j] == q;
    ensures restarted: \forall integer q; 0 <= q < count ==>
        r->wait[q] == (\old(r->wait[q]) == 0 ? pow2(plan->pv[q]) : \old(r->wait[q]));
*/
static uint32_t fig7_run_due(struct bsched_fig7 *r, const struct bsched *plan, uint32_t count,
                             uint32_t perfect)
{
    uint32_t done = 0u;
    uint32_t id;

    /*@ ghost lemma_fig7_zero_slots(r, plan, count); */
    /*@ loop invariant 0 <= id <= count;
        loop invariant 0 <= done <= id && done <= perfect;
        loop invariant counted: done == fig7_zero_slots{Pre}(r, plan, id);
        loop invariant ran_were_zero: \forall integer j; 0 <= j < done ==>
            r->ran[j] < count && \let q = (integer)r->ran[j]; \at(r->wait[q], Pre) == 0;
        loop invariant zeros_ran: \forall integer d; 0 <= d < id && \at(r->wait[plan->order[d]], Pre) == 0 ==>
            \exists integer j; 0 <= j < done && r->ran[j] == plan->order[d];
        loop invariant visited: \forall integer d; 0 <= d < id ==>
            r->wait[plan->order[d]] == (\at(r->wait[plan->order[d]], Pre) == 0 ?
                pow2(plan->pv[plan->order[d]]) : \at(r->wait[plan->order[d]], Pre));
        loop invariant not_visited: \forall integer d; id <= d < count ==>
            r->wait[plan->order[d]] == \at(r->wait[plan->order[d]], Pre);
        loop assigns id, done, r->ran[0 .. BSCHED_MAX_PROCS - 1], r->wait[0 .. BSCHED_MAX_PROCS - 1];
        loop variant count - id;
    */
    for (id = 0u; id < count && done < perfect; id++) {
        uint16_t p = plan->order[id];
        if (r->wait[p] == 0u) {
            /*@ assert was_zero: p < count && \let q = (integer)p; \at(r->wait[q], Pre) == 0; */
            r->ran[done] = p;
            done++;
            r->wait[p] = fig7_period(plan->pv[p]);
            /*@ assert ran_kept: \forall integer j; 0 <= j < done - 1 ==>
                    r->ran[j] == \at(r->ran[j], LoopCurrent); */
            /*@ assert ran_new: r->ran[done - 1] == p; */
        }
    }
    /* Stopped early only with `perfect` runs, when no 0 is left. */
    /*@ assert rest_nonzero: \forall integer d; id <= d < count ==>
            \at(r->wait[plan->order[d]], Pre) != 0; */
    /*@ assert every_slot: \forall integer q; 0 <= q < count ==>
            (sorted_pos(&plan->pv[0], count, q) < id &&
             r->wait[q] == (\at(r->wait[q], Pre) == 0 ? pow2(plan->pv[q]) : \at(r->wait[q], Pre)) &&
             (\at(r->wait[q], Pre) == 0 ==> \exists integer j; 0 <= j < done && r->ran[j] == q)) ||
            (sorted_pos(&plan->pv[0], count, q) >= id && \at(r->wait[q], Pre) != 0 &&
             r->wait[q] == \at(r->wait[q], Pre)); */
    return done;
}

/* Fig. 7, line 13: every positive wait counts down one cycle. A function of its
 * own so that its loop is proven with this small contract as the only context. */
/*@ requires \valid(r) && count <= BSCHED_MAX_PROCS;
    requires positive: \forall integer q; 0 <= q < count ==> 1 <= r->wait[q];
    assigns r->wait[0 .. BSCHED_MAX_PROCS - 1];
    ensures counted_down: \forall integer q; 0 <= q < count ==> r->wait[q] == \old(r->wait[q]) - 1;
    ensures others: \forall integer q; count <= q < BSCHED_MAX_PROCS ==> r->wait[q] == \old(r->wait[q]);
*/
static void fig7_count_down(struct bsched_fig7 *r, uint32_t count)
{
    uint32_t i;

    /*@ loop invariant 0 <= i <= count;
        loop invariant counted_down: \forall integer q; 0 <= q < i ==>
            r->wait[q] == \at(r->wait[q], LoopEntry) - 1;
        loop invariant not_yet: \forall integer q; i <= q < BSCHED_MAX_PROCS ==>
            r->wait[q] == \at(r->wait[q], LoopEntry);
        loop assigns i, r->wait[0 .. BSCHED_MAX_PROCS - 1];
        loop variant count - i;
    */
    for (i = 0u; i < count; i++) {
        if (r->wait[i] > 0u) {
            r->wait[i]--;
        }
    }
}

/* The first requires and the null and bad_state behaviors are
 * bsched_fig7_start's again, as bsched.c's contracts repeat theirs: an ACSL
 * contract belongs to one function, ACSL has no behavior two contracts share. */
/*@ requires valid: r == \null || \valid(r);
    requires valid_plan: plan == \null || \valid_read(plan);
    requires separated: r != \null && plan != \null ==> \separated(r, plan);
    requires from_init: r != \null && plan != \null && fig7_plausible(plan) ==>
        fig7_plan(plan) && fig7_well_formed(r, plan) && fig7_in_phase(r, plan);
    assigns r->wait[0 .. BSCHED_MAX_PROCS - 1], r->ran[0 .. BSCHED_MAX_PROCS - 1],
            r->ran_count, r->cycle;

    behavior null:
      assumes r == \null || plan == \null;
      assigns \nothing;
      ensures \result == BSCHED_ERR_NULL;
    behavior bad_state:
      assumes r != \null && plan != \null && !fig7_plausible(plan);
      assigns \nothing;
      ensures \result == BSCHED_ERR_STATE;
    behavior ok:
      assumes r != \null && plan != \null && fig7_plausible(plan);
      ensures ok_count: 0 <= \result <= plan->perfect && \result == r->ran_count;
      ensures ok_well_formed: fig7_well_formed(r, plan);
      ensures ok_in_phase: fig7_in_phase(r, plan);
      ensures ok_cycle: r->cycle == (\old(r->cycle) + 1) % pow2(plan->maxpv);
      ensures ok_ran_range: \forall integer j; 0 <= j < \result ==> r->ran[j] < plan->count;
      ensures ok_periodic: \forall integer i; 0 <= i < plan->count ==>
          (fig7_ran_last(r, i) <==> \old(r->cycle) % pow2(plan->pv[i]) == plan->offset[i]);
      ensures ok_load: \result == load(&plan->pv[0], plan->count, \old(r->cycle));
      ensures ok_no_idle: total_area(&plan->pv[0], plan->count) / pow2(BSCHED_MAX_PV) <= \result;
    complete behaviors;
    disjoint behaviors;
*/
int32_t bsched_fig7_step(struct bsched_fig7 *r, const struct bsched *plan)
{
    uint32_t done;
    uint32_t next;
    uint32_t count;
    uint32_t perfect;

    if (r == NULL || plan == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!fig7_plan_plausible(plan)) {
        return BSCHED_ERR_STATE;
    }
    count = plan->count;
    perfect = plan->perfect;
    /*@ ghost uint32_t t = (uint32_t)r->cycle; */
    /*@ ghost uint32_t g; */
    /* In phase, a wait is 0 exactly when its process is due in cycle t. */
    /*@ ghost
      /@ loop invariant 0 <= g <= count;
         loop invariant due_is_zero: \forall integer q; 0 <= q < g ==>
             (r->wait[q] == 0 <==> t % pow2(plan->pv[q]) == plan->offset[q]);
         loop assigns g;
         loop variant count - g;
      @/
      for (g = 0u; g < count; g++) {
        lemma_due_iff_zero(t, r->wait[g], plan->offset[g], plan->pv[g]);
      }
    */
    /*@ ghost
      /@ loop invariant 0 <= g <= count;
         loop invariant zeros_are_due: fig7_zero_slots(r, plan, g) == due_slots(plan, t, g);
         loop assigns g;
         loop variant count - g;
      @/
      for (g = 0u; g < count; g++) {
      }
    */
    /* The balance theorem for this cycle: at most `perfect` processes are due
     * (spec/bsched_slots.h, bsched_balance.h, bsched_fold.h), so the cap of
     * fig7_run_due never defers one. */
    /*@ ghost lemma_slots_by_class((struct bsched *)plan, t); */
    /*@ ghost lemma_balance(&plan->pv[0], count, t); */
    /*@ ghost lemma_fold(&plan->pv[0], count); */
    /*@ assert load_bound: fig7_zero_slots(r, plan, count) == due_slots(plan, t, count) <= perfect; */
    /*@ assert distinct: \forall integer d, e; 0 <= d < e < count ==> plan->order[d] != plan->order[e]; */
    done = fig7_run_due(r, plan, count, perfect);
    /*@ assert ran_due: \forall integer j; 0 <= j < done ==>
            r->ran[j] < count && \let q = (integer)r->ran[j]; \at(r->wait[q], Pre) == 0; */
    /*@ assert due_ran: \forall integer q; 0 <= q < count && \at(r->wait[q], Pre) == 0 ==>
            \exists integer j; 0 <= j < done && r->ran[j] == q; */
    /*@ assert ran_due_now: \forall integer j; 0 <= j < done ==>
            r->ran[j] < count && t % pow2(plan->pv[r->ran[j]]) == plan->offset[r->ran[j]]; */
    /*@ assert periodic_only: \forall integer q; 0 <= q < count ==>
            (\exists integer j; 0 <= j < done && r->ran[j] == q) ==> t % pow2(plan->pv[q]) == plan->offset[q]; */
    /*@ assert periodic_all: \forall integer q; 0 <= q < count ==>
            t % pow2(plan->pv[q]) == plan->offset[q] ==> \exists integer j; 0 <= j < done && r->ran[j] == q; */
    /*@ assert waits_positive: \forall integer q; 0 <= q < count ==> 1 <= r->wait[q] <= pow2(plan->pv[q]); */
    /* Fig. 7, line 13 (after fig7_run_due every wait is positive). */
    fig7_count_down(r, count);
    /* Stated after the count-down, so that its proof does not carry them. */
    /*@ assert phase_at_t: \forall integer q; 0 <= q < count ==>
            (t + \at(r->wait[q], Pre)) % pow2(plan->pv[q]) == plan->offset[q]; */
    /*@ assert periodic_done: \forall integer q; 0 <= q < count ==>
            ((\exists integer j; 0 <= j < done && r->ran[j] == q) <==> t % pow2(plan->pv[q]) == plan->offset[q]); */
    /*@ assert phase_cases: \forall integer q; 0 <= q < count ==>
            (\at(r->wait[q], Pre) == 0 && t % pow2(plan->pv[q]) == plan->offset[q]) ||
            (\at(r->wait[q], Pre) != 0 && (t + \at(r->wait[q], Pre)) % pow2(plan->pv[q]) == plan->offset[q]); */
    /*@ assert next_waits: \forall integer q; 0 <= q < count ==>
            r->wait[q] == (\at(r->wait[q], Pre) == 0 ? pow2(plan->pv[q]) - 1 : \at(r->wait[q], Pre) - 1); */
    /*@ assert next_phase: \forall integer q; 0 <= q < count ==>
            (r->wait[q] + 1 == pow2(plan->pv[q]) && t % pow2(plan->pv[q]) == plan->offset[q]) ||
            (t + r->wait[q] + 1) % pow2(plan->pv[q]) == plan->offset[q]; */
    next = ((uint32_t)r->cycle + 1u) % fig7_period(plan->maxpv);
    /*@ assert count_same: plan->count == count; */
    /*@ ghost lemma_fig7_next_phase(r, plan, t, next); */
    /*@ ghost Stepped: ; */
    r->ran_count = (uint16_t)done;
    /*@ assert ran_kept: \forall integer j; 0 <= j < done ==> r->ran[j] == \at(r->ran[j], Stepped); */
    /*@ ghost lemma_pow2(BSCHED_MAX_PV); */
    /*@ assert next_fits: next < pow2(plan->maxpv) <= pow2(BSCHED_MAX_PV) == 2147483648; */
    r->cycle = (int32_t)next;
    /*@ assert in_phase_final: \forall integer q; 0 <= q < count ==>
            (r->cycle + r->wait[q]) % pow2(plan->pv[q]) == plan->offset[q]; */
    /*@ assert ran_final: \forall integer j; 0 <= j < done ==> r->ran[j] < plan->count; */
    /*@ assert done_small: done <= count <= BSCHED_MAX_PROCS; */
    return (int32_t)done;
}
