/*
 * The B-scheduler thread: runs one bsched minor cycle every `period` ticks
 * at the highest application priority (K_PRIO_APP_MAX), released at
 * absolute ticks start + k*period so it never drifts.
 *
 * Overrun: a minor cycle still running when the next release is due. Each
 * missed release is counted; the late cycle's successor starts at the next
 * release still ahead (missed releases are not run back to back, which would
 * only make the lateness worse); the cycle itself is never cut short, and the
 * set's phase advances one minor cycle per cycle run, not per release (a
 * missed release runs nothing). Overruns are reported on the console by a
 * reporter thread just below the B-scheduler thread's priority, so that the
 * report (about a millisecond of output formatting) never delays a cycle;
 * its line names the overrun cycle, how late it ended and the totals.
 * The reporter prints at most one burst of lines every
 * K_BSCHED_REPORT_INTERVAL_TICKS (1 s by default) and sums what happens in
 * between, so under continuous overrun it cannot starve the threads below it.
 * A cycle that is still running when its successor is due is noticed at
 * that tick by the tick hook (k_tick_hook), which only counts it and wakes
 * the reporter, lending it a priority above the cycle's so that a cycle that
 * never ends is not silent either: "bsched: minor cycle C still running at
 * its successor's release (tick T)". No console output from the tick.
 *
 * Timing, when asked for (b->measure set before k_bsched_start), in counts
 * of the kernel's fine time stamp (k_timestamp, at k_timestamp_hz() counts
 * per second: the board's counter, or whole ticks when the board registered
 * none; k_bsched_start starts the board's counter, k_timestamp_start). It
 * costs two counter reads per process and one per cycle (the tick hook's
 * stamp of the release), with their bookkeeping: on the RoboCube, whose
 * counter is read through the TPU, the PDL benchmark (one process a cycle,
 * a cycle every 1024 Hz tick) measured 4.9 % more CPU with it (load 49.2 %
 * -> 54.1 %, about 190 instructions a cycle), above that benchmark's 50 %
 * bound: so it is off unless asked for, and off it costs nothing a tick or
 * a cycle (the stamping tick hook and the timed call are chosen at start).
 * It records
 *  - per process of the planned set, the longest execution of one call of
 *    the process function and how many calls were measured
 *    (k_bsched_wcet). It is the time from the call to its return as the
 *    thread sees it: interrupt handlers and anything more urgent that ran
 *    meanwhile are in it, and so are the call and one counter read (the
 *    floor an empty process function measures).
 *  - release jitter (k_bsched_jitter): for each minor cycle that runs a
 *    process, the time from its release (the stamp the tick hook took at
 *    the end of the release's tick, before the thread ran) to the start of
 *    its first process: the wake-up, the switch, bsched's step and any
 *    lateness. Smallest, largest, mean and the number of cycles measured.
 *    Only the instance the tick watches (the first one started) measures
 *    it; cycles that run no process give no sample. The path from the timer
 *    event to the end of the tick's work (interrupt entry, k_tick) is not
 *    in it.
 */
#ifndef K_BSCHED_H
#define K_BSCHED_H

#include "kernel.h"
#include "bsched.h"

/* One process's measured execution times (k_timestamp counts). */
struct k_bsched_exec {
    uint32_t worst;  /* the longest call of the process function */
    uint32_t runs;   /* calls measured */
};

struct k_bsched {
    struct k_thread thread;
    struct bsched *sched;
    bsched_process_fn run;
    void *context;
    k_ticks_t period;          /* ticks per minor cycle */
    k_ticks_t next_release;    /* absolute tick of the next minor cycle */
    uint32_t cycles_run;       /* minor cycles executed */
    uint32_t overruns;         /* releases missed because a cycle ran late */
    uint32_t overrun_events;   /* cycles that overran (reports printed) */
    uint32_t max_cycle_ticks;  /* longest minor cycle, in ticks */
    uint32_t stop_after;       /* stop after this many cycles (0 = never) */
    int measure;               /* set before k_bsched_start: record the timing (below) */
    volatile int stop;         /* set to end the thread after this cycle */
    /* reporting */
    uint32_t last_overrun_cycle;  /* cycles_run index of the last overrun */
    uint32_t last_overrun_late;   /* ticks its end was past the release */
    uint32_t reported_events;     /* overrun events printed so far */
    int finished;
    volatile int in_cycle;        /* a minor cycle is running */
    volatile k_ticks_t watch;     /* tick at which a running cycle overruns */
    volatile uint32_t stuck_reports; /* cycles found still running at their successor's release */
    volatile uint32_t stuck_cycle;   /* the last such cycle, and the tick it was found at */
    volatile k_ticks_t stuck_tick;
    uint32_t stuck_printed;       /* stuck_reports when the reporter last printed */
    uint32_t report_lines;        /* lines the reporter printed */
    k_ticks_t next_report;        /* the reporter prints nothing before this tick */
    struct k_sem report_sem;      /* binary: something to report */
    struct k_sem finish_sem;      /* binary: the thread ended (cuts the reporter's interval short) */
    /* timing (k_timestamp counts; read with k_bsched_wcet, k_bsched_jitter) */
    struct k_bsched_exec exec[BSCHED_MAX_PROCS]; /* by process index (input order) */
    uint32_t jitter_min, jitter_max; /* release to first process */
    uint32_t jitter_samples;
    uint32_t jitter_sum_lo, jitter_sum_hi; /* 64-bit sum, for the mean */
    bsched_process_fn cycle_run;     /* what each cycle calls: run, or run between stamps */
    void *cycle_context;
    volatile uint32_t release_stamp;      /* the tick hook's stamp at the tick of next_release */
    volatile k_ticks_t release_stamp_tick; /* which tick release_stamp is of */
    volatile int release_stamped;         /* release_stamp holds a stamp no process took yet */
    struct k_thread reporter;
    uint32_t reporter_stack[K_STACK_WORDS(K_BSCHED_REPORTER_STACK_BYTES)] __attribute__((aligned(4)));
};

/* Starts the thread (and its reporter). s must be planned (bsched_init);
 * period >= 1 tick; set b->stop_after before (0 = run for ever) and
 * b->measure (nonzero: record execution times and jitter). The first
 * cycle runs at the next tick. Returns K_OK or K_EINVAL. When the thread
 * stops, it waits until every overrun has been reported. */
int k_bsched_start(struct k_bsched *b, struct bsched *s, bsched_process_fn run, void *context,
                   k_ticks_t period, uint32_t *stack, size_t stack_bytes);

/* The longest execution of process `index` (input order) in counts of
 * k_timestamp_hz(), and how many calls were measured; either pointer may be
 * NULL. Valid from k_bsched_start on, while the thread runs and after
 * (all 0 when b->measure was not set).
 * Returns K_OK, or K_EINVAL (b NULL or not started, index not in the set). */
int k_bsched_wcet(const struct k_bsched *b, uint16_t index, uint32_t *worst, uint32_t *runs);

/* Release jitter so far (see above), in counts of k_timestamp_hz():
 * smallest, largest and mean (rounded down) over `samples` minor cycles;
 * all 0 while samples is 0. Any pointer may be NULL. Returns K_OK, or
 * K_EINVAL for b NULL. */
int k_bsched_jitter(const struct k_bsched *b, uint32_t *min, uint32_t *max, uint32_t *mean,
                    uint32_t *samples);

#endif /* K_BSCHED_H */
