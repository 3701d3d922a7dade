/*
 * CBMC harness `major_cycle`: full simulation, the cross-check of `init` + `step`.
 * For every priority set within the bounds (any input order), bsched_init then
 * one complete major cycle (2^maxpv minor cycles) through bsched_run_cycle with
 * a recording callback.
 *
 * Checks:
 *   - periodicity: process i runs in cycle t only if t = w_i (mod 2^pv_i), at most
 *     once per cycle, and 2^(maxpv - pv_i) times in the major cycle -- so exactly
 *     in the cycles t = w_i (mod 2^pv_i) and nowhere else;
 *   - the callback sees the processes of a cycle in execution order (ascending
 *     pv, ties by index), and as many as bsched_run_cycle returns;
 *   - load: every minor cycle runs floor(U) or ceil(U) processes;
 *   - the state after the major cycle equals the state after bsched_init
 *     (count, maxpv, perfect, cycle, reversed, pv, offset, order, the class
 *     table): the schedule really repeats. ran[] and ran_count describe only the last minor cycle.
 */
#include "proof_model.h"

struct recorder {
    const struct proof_set *set;
    const struct bsched *s;
    uint32_t t;                          /* the minor cycle being run */
    uint32_t calls;                      /* callbacks in this minor cycle */
    uint32_t last_key;                   /* order key of the previous call in this cycle */
    uint32_t runs[BSCHED_MAX_PROCS];     /* runs of each process in the major cycle */
    uint32_t last_run[BSCHED_MAX_PROCS]; /* 1 + the last cycle each process ran in, 0 = never */
};

static void record_run(void *context, uint16_t index)
{
    struct recorder *r = context;
    uint32_t pv;
    uint32_t key;

    __CPROVER_assert(index < r->set->n, "major_cycle: the callback gets a process index");
    if (index >= r->set->n) {
        return;
    }
    pv = r->set->pv[index];
    key = proof_order_key(r->set, index);
    __CPROVER_assert(proof_due_at(r->s->offset[index], pv, r->t),
                     "periodicity: a process runs only in cycles t = w (mod 2^pv)");
    __CPROVER_assert(r->last_run[index] != r->t + 1u, "periodicity: at most one run per cycle");
    __CPROVER_assert(r->calls == 0u || key > r->last_key, "major_cycle: runs in execution order");
    r->last_run[index] = r->t + 1u;
    r->runs[index]++;
    r->calls++;
    r->last_key = key;
}

void harness(void)
{
    static struct bsched s;
    static struct bsched before;
    static struct recorder r;
    struct proof_set set;
    uint32_t cycles;
    uint32_t t;
    uint32_t i;
    int32_t rc;

    proof_nondet_set(&set);
    rc = bsched_init(&s, set.pv, (size_t)set.n);
    __CPROVER_assert(rc == BSCHED_OK, "major_cycle: a valid set is accepted");
    before = s;

    r.set = &set;
    r.s = &s;
    for (i = 0u; i < PROOF_N; i++) {
        r.runs[i] = 0u;
        r.last_run[i] = 0u;
    }

    cycles = (uint32_t)1u << set.maxpv;
    for (t = 0u; t < cycles; t++) {
        r.t = t;
        r.calls = 0u;
        rc = bsched_run_cycle(&s, record_run, &r);
        __CPROVER_assert(rc >= 0 && (uint32_t)rc == r.calls, "major_cycle: returns the number of processes it ran");
        __CPROVER_assert(r.calls >= set.load_lo, "load: at least floor(U) processes in every cycle");
        __CPROVER_assert(r.calls <= set.load_hi, "load: at most ceil(U) processes in every cycle");
    }

    for (i = 0u; i < PROOF_N; i++) {
        if (i < set.n) {
            __CPROVER_assert(r.runs[i] == cycles >> set.pv[i],
                             "periodicity: 2^(maxpv - pv) runs per major cycle");
            __CPROVER_assert(bsched_wait(&s, (uint16_t)i) == (int32_t)before.offset[i] && s.offset[i] == before.offset[i] &&
                             s.pv[i] == before.pv[i] && s.order[i] == before.order[i],
                             "repeat: per-process state after the major cycle equals the initial state");
        }
    }
    __CPROVER_assert(s.count == before.count && s.maxpv == before.maxpv && s.perfect == before.perfect &&
                     s.cycle == before.cycle && s.reversed == before.reversed,
                     "repeat: count, maxpv, perfect, cycle and reversed back to the initial state");
}
