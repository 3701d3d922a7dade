/*
 * bsched: the B-scheduler of Birk, Kenn and Steels, "Programming with
 * behavior-processes" (2002), section 4.
 *
 * Processes carry exponential effect priorities: a process with priority
 * value pv runs once every 2^pv minor cycles. bsched_init computes the
 * initial waits of Fig. 6 (stable counting sort by pv, then bit reversal);
 * bsched_step and bsched_run_cycle execute one minor cycle with the results of
 * Fig. 7 (the same processes in the same order), found from the closed form in
 * O(classes in use + processes due) instead of Fig. 7's count-down of every wait.
 * The resulting major cycle (2^maxpv minor cycles) is periodic and balanced:
 * every minor cycle runs floor(U) or ceil(U) processes, U = sum 2^-pv.
 *
 * Freestanding C99: no allocation, no libc, no global state. All state lives
 * in a caller-owned struct bsched whose capacity is fixed at compile time by
 * BSCHED_MAX_PROCS. Process identity is the caller's index (input order).
 */
#ifndef BSCHED_H
#define BSCHED_H

#include <stddef.h>
#include <stdint.h>

/* Capacity of a struct bsched, in processes. Override with -DBSCHED_MAX_PROCS=N
 * (1 <= N <= 65535) when compiling bsched.c and everything that includes this. */
#ifndef BSCHED_MAX_PROCS
#define BSCHED_MAX_PROCS 256
#endif

/* Largest priority value: periods up to 2^31 minor cycles. */
#define BSCHED_MAX_PV 31

#if BSCHED_MAX_PROCS < 1 || BSCHED_MAX_PROCS > 65535
#error "BSCHED_MAX_PROCS must be between 1 and 65535"
#endif

/* Status codes. Functions returning int32_t return a count >= 0 on success
 * or one of these (negative) codes. */
#define BSCHED_OK            0
#define BSCHED_ERR_NULL     (-1) /* a required pointer is NULL */
#define BSCHED_ERR_NO_PROCS (-2) /* no processes */
#define BSCHED_ERR_TOO_MANY (-3) /* more than BSCHED_MAX_PROCS processes */
#define BSCHED_ERR_PV_RANGE (-4) /* a priority value above BSCHED_MAX_PV */
#define BSCHED_ERR_STATE    (-5) /* the state was not set up by bsched_init */
#define BSCHED_ERR_INDEX    (-6) /* a process index >= count */

/* The scheduler state. Owned by the caller, written only by bsched_init,
 * bsched_step and bsched_run_cycle; every field may be read.
 * Per process: 9 bytes (pv, offset, order, ran); per priority class k = 0..31
 * (indexed by k, empty classes too): 16 bytes. Fig. 7's waits are not stored:
 * bsched_wait computes one on demand. */
struct bsched {
    uint16_t count;   /* number of processes, 1..BSCHED_MAX_PROCS */
    uint8_t  maxpv;   /* largest priority value in the set */
    uint8_t  minpv;   /* smallest priority value in the set */
    uint16_t perfect; /* ceil(sum 2^-pv): the most processes any minor cycle runs */
    uint16_t ran_count;  /* processes run in the last minor cycle */
    uint32_t cycle;      /* current minor cycle within the major cycle, 0..2^maxpv-1 */
    uint32_t reversed;   /* cycle with its low maxpv bits reversed: rev_maxpv(cycle) */
    /* Class k (the processes with pv == k, in execution order) occupies
     * order[class_first[k] .. class_first[k] + class_size[k] - 1]; its member j
     * has offset rev_k((s_k + j) mod 2^k), s_k Fig. 6's start, so member j runs
     * in cycle t iff j = rev_k(t mod 2^k) - s_k (mod 2^k). bsched_step finds that
     * j with an add, a mask and a compare per class, on 31-bit words whose top k
     * bits are the class's residues: class_key[k] = ((2^k - s_k) mod 2^k) * 2^(31-k)
     * and class_limit[k] = min(c_k, 2^k) * 2^(31-k), c_k the class's size. With
     * W = rev_maxpv(cycle) * 2^(31-maxpv), x = (W + class_key[k]) mod 2^31 (no
     * 32-bit wrap) has j in its top k bits, and x >= class_limit[k] means j >= c_k:
     * no member of the class is due. */
    uint32_t class_key[BSCHED_MAX_PV + 1];
    uint32_t class_limit[BSCHED_MAX_PV + 1];
    uint32_t class_first[BSCHED_MAX_PV + 1];
    uint32_t class_size[BSCHED_MAX_PV + 1];
    uint8_t  pv[BSCHED_MAX_PROCS];     /* priority values, input order */
    uint32_t offset[BSCHED_MAX_PROCS]; /* initial waits of Fig. 6, input order: process i
                                          runs in the cycles t with t mod 2^pv_i == offset_i */
    uint16_t order[BSCHED_MAX_PROCS];  /* execution order: input indices, stably sorted by pv */
    uint16_t ran[BSCHED_MAX_PROCS];    /* input indices run in the last minor cycle, in order */
};

/* A process body, called with the caller's context and the process's input index. */
typedef void (*bsched_process_fn)(void *context, uint16_t index);

/*
 * Plans a priority set: pv[0..count-1] are the processes' priority values in
 * the caller's order. Computes order, offsets (= initial waits), perfect, and
 * starts at minor cycle 0. Linear in count.
 * Returns BSCHED_OK, or an error code and leaves *s untouched.
 */
int32_t bsched_init(struct bsched *s, const uint8_t *pv, size_t count);

/*
 * Runs one minor cycle without calling anything: records the processes due in
 * cycle t = s->cycle (those with t mod 2^pv == offset), in execution order, in
 * s->ran[0..ran_count-1] (Fig. 7's selection: never more than `perfect`, the
 * balance theorem), then advances s->cycle (mod 2^maxpv) and s->reversed.
 * O(classes from minpv to maxpv + processes due).
 * Returns the number of processes run, or an error code (*s untouched).
 */
int32_t bsched_step(struct bsched *s);

/*
 * bsched_step, then calls run(context, i) for each process i it selected, in
 * execution order. The process bodies must not modify *s.
 * Returns the number of processes run, or an error code (*s untouched).
 */
int32_t bsched_run_cycle(struct bsched *s, bsched_process_fn run, void *context);

/*
 * Which processes are due `ahead` minor cycles from now (0 = the cycle the
 * next bsched_step runs), without running anything: writes their input
 * indices in execution order to due[] (room for s->perfect entries; never more
 * are due, the balance theorem). Does not modify *s. O(maxpv + processes due).
 * Returns the number written, or an error code.
 */
int32_t bsched_due(const struct bsched *s, uint32_t ahead, uint16_t *due);

/*
 * Fig. 7's wait of process i at the start of the current minor cycle: the
 * cycles until it next runs, (offset_i - cycle) mod 2^pv_i (0: due now).
 * Returns it (>= 0), or BSCHED_ERR_NULL, BSCHED_ERR_STATE, BSCHED_ERR_INDEX.
 */
int32_t bsched_wait(const struct bsched *s, uint16_t i);

#endif /* BSCHED_H */
