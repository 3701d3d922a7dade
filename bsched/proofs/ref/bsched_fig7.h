/*
 * bsched_fig7: Fig. 7 of Birk, Kenn and Steels (2002) as its own engine, the
 * paper's reference for bsched_step.
 *
 * It runs a plan made by bsched_init (order, offsets, perfect, pv, count,
 * maxpv), which it only reads, with the paper's per-process waits: every minor
 * cycle it scans every process for a zero wait and counts every wait down, so
 * a cycle costs O(N). bsched_step gives the same results in O(classes + due);
 * CBMC's `agree` harness (bsched/proofs/cbmc/agree/) checks that the two agree
 * cycle by cycle, Frama-C WP proves this engine against the same properties as
 * bsched_step (bsched/spec/bsched_fig7.h). Not for firmware: for proofs, tests
 * and `make bench`.
 */
#ifndef BSCHED_FIG7_H
#define BSCHED_FIG7_H

#include <stdint.h>

#include "bsched.h"

/* Fig. 7's mutable state; the plan lives in a struct bsched. */
struct bsched_fig7 {
    /* current minor cycle, 0..2^maxpv-1 (<= 2^31 - 1). Signed on purpose: in
     * WP's typed memory model a store to it then cannot touch wait[], so the
     * proof does not have to carry every wait across that store. */
    int32_t cycle;
    uint16_t ran_count;                /* processes run in the last minor cycle */
    uint32_t wait[BSCHED_MAX_PROCS];   /* minor cycles until the next run, input order */
    uint16_t ran[BSCHED_MAX_PROCS];    /* input indices run in the last minor cycle, in order */
};

/*
 * Starts Fig. 7 on a plan from bsched_init at minor cycle 0: every wait is the
 * process's Fig. 6 offset. Returns BSCHED_OK, BSCHED_ERR_NULL or
 * BSCHED_ERR_STATE (the plan fails bsched's cheap check); *r is untouched on error.
 */
int32_t bsched_fig7_start(struct bsched_fig7 *r, const struct bsched *plan);

/*
 * One minor cycle of Fig. 7 (lines 5-13): runs the processes whose wait is 0
 * in execution order (plan->order), at most plan->perfect of them, records
 * them in r->ran[0..ran_count-1], restarts their waits at 2^pv, counts every
 * positive wait down and advances r->cycle. Returns the number run or an error
 * code (BSCHED_ERR_NULL, BSCHED_ERR_STATE; *r untouched).
 */
int32_t bsched_fig7_step(struct bsched_fig7 *r, const struct bsched *plan);

#endif /* BSCHED_FIG7_H */
