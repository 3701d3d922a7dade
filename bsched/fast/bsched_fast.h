/*
 * bsched_fast: a minor cycle in O(classes in use + processes due) instead of
 * Fig. 7's O(N) (issue 14; derivation in shared/notes/due-set-in-closed-form.md).
 *
 * bsched_init (bsched.c) plans the set; bsched_fast_init then builds a small
 * per-class table from that state (O(N) once). bsched_fast_step runs one minor
 * cycle with exactly the results of bsched_step (Fig. 7): the same processes in
 * the same order in s->ran[0 .. ran_count-1], the same return value, the same
 * s->cycle, the same error codes. It finds the due members of class k from the
 * closed form alone: member j of class k runs in cycle t iff
 *     j = rev_k(t mod 2^k) - s_k (mod 2^k),
 * so no per-process wait is read or counted down. rev_k(t mod 2^k) is the
 * top k bits of R = rev_maxpv(t), which is kept from cycle to cycle as a
 * bit-reversed counter (amortised O(1)). In the hand proof's interval picture
 * (every process an interval of 2^-pv, side by side in execution order) the
 * due processes are those whose intervals hold the laps R, R + 2^maxpv, ...
 * (units of 2^-maxpv): the step walks the laps and skips the classes between
 * them with one comparison each, emitting a class's due members with stride 2^k.
 *
 * s->wait[] is Fig. 7's count-down and is NOT maintained by bsched_fast_step:
 * read waits with bsched_wait(s, i) (computed from s->cycle and s->offset[i]),
 * and drive one state with either bsched_step or bsched_fast_step, not both.
 *
 * Status: checked equal to Fig. 7 cycle by cycle by CBMC (harness `fast`) and by
 * the host tests; not yet proven by Frama-C WP, so it is not (yet) the library's
 * bsched_step. See bsched/README section "bsched_fast".
 */
#ifndef BSCHED_FAST_H
#define BSCHED_FAST_H

#include "bsched.h"

/* Room for priority classes in the table: every pv 0..BSCHED_MAX_PV by default.
 * A smaller value (at least 1 + the largest pv in use) saves RAM; the CBMC
 * harness sets it to its bound. bsched_fast_init refuses a set with more classes. */
#ifndef BSCHED_FAST_CLASSES
#define BSCHED_FAST_CLASSES (BSCHED_MAX_PV + 1)
#endif
#if BSCHED_FAST_CLASSES < 1 || BSCHED_FAST_CLASSES > BSCHED_MAX_PV + 1
#error "BSCHED_FAST_CLASSES must be between 1 and BSCHED_MAX_PV + 1"
#endif

/* Returned by bsched_wait for a process index >= s->count. */
#define BSCHED_ERR_INDEX (-6)

/* One priority class k with members, as the dispatch loop reads it (16 bytes,
 * so that indexing the table is a shift). */
struct bsched_class {
    uint32_t lead;  /* 2^k - s_k (s_k of Fig. 6): j0 = (Y_k + lead) mod 2^k */
    uint32_t base;  /* where the class's intervals start, in units of 2^-maxpv */
    uint16_t first; /* first slot of the class in s->order[] */
    uint16_t size;  /* c_k >= 1: members of the class */
    uint8_t  pv;    /* k */
    uint8_t  shift; /* maxpv - k: Y_k = rev_k(t mod 2^k) = rev_maxpv(t) >> shift */
    uint16_t unused;
};

struct bsched_fast {
    uint32_t cycle;     /* the s->cycle that `reversed` belongs to */
    uint32_t reversed;  /* rev_maxpv(cycle): bit-reversed cycle counter */
    uint32_t cycles;    /* 2^maxpv - 1: the cycle mask */
    uint16_t count;     /* s->count when built */
    uint8_t  maxpv;     /* s->maxpv when built */
    uint8_t  used;      /* classes with members, 1 .. BSCHED_FAST_CLASSES */
    uint8_t  laps;      /* 1: the area plus one lap fits in 32 bits (collect_laps) */
    /* base + c_k 2^(maxpv - k) of each class: where its intervals end (its own
     * array: the dispatch loop skips classes by reading only these) */
    uint32_t end[BSCHED_FAST_CLASSES];
    struct bsched_class classes[BSCHED_FAST_CLASSES]; /* those classes, ascending pv */
};

/* Builds the class table of a state set up by bsched_init (any cycle).
 * Returns BSCHED_OK, BSCHED_ERR_NULL or BSCHED_ERR_STATE (*f untouched). */
int32_t bsched_fast_init(struct bsched_fast *f, const struct bsched *s);

/* One minor cycle, the results of bsched_step(s) without its O(N) scan.
 * f must come from bsched_fast_init for this state (as s must come from
 * bsched_init): the class records are checked when built, not every cycle.
 * Returns the number of processes run, or BSCHED_ERR_NULL / BSCHED_ERR_STATE
 * (*s and *f untouched). */
int32_t bsched_fast_step(struct bsched *s, struct bsched_fast *f);

/* bsched_fast_step, then run(context, i) for each process run, in order. */
int32_t bsched_fast_run_cycle(struct bsched *s, struct bsched_fast *f,
                              bsched_process_fn run, void *context);

/* bsched_due(s, ahead, due) in O(maxpv + processes due): the processes due
 * `ahead` minor cycles from s->cycle, in execution order, at most s->perfect. */
int32_t bsched_fast_due(const struct bsched *s, const struct bsched_fast *f,
                        uint32_t ahead, uint16_t *due);

/* Process i's wait at the start of cycle s->cycle, (offset_i - cycle) mod 2^pv_i:
 * Fig. 7's wait[i] computed on demand. Returns it (>= 0), or BSCHED_ERR_NULL,
 * BSCHED_ERR_STATE, BSCHED_ERR_INDEX. */
int32_t bsched_wait(const struct bsched *s, uint16_t i);

#endif /* BSCHED_FAST_H */
