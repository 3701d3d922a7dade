/* The B-scheduler thread (see k_bsched.h). */
#include "k_bsched.h"

/* The reporter's own priority, and the one it is lent to announce a cycle
 * that still runs (the cycle runs at K_PRIO_APP_MAX). */
#define K_BSCHED_REPORTER_PRIO (K_PRIO_APP_MAX - 1u)
#define K_BSCHED_ANNOUNCE_PRIO (K_PRIO_APP_MAX + 1u)

/* The instance the tick watches (the first one started). */
static struct k_bsched *k_bsched_watched;

/* Tick hook, in the tick interrupt: a cycle still running at its
 * successor's release is counted at once; the reporter says so. */
static void k_bsched_watchdog(k_ticks_t now)
{
    struct k_bsched *b = k_bsched_watched;
    if (b == NULL || !b->in_cycle || now != b->watch)
        return;
    b->stuck_cycle = b->cycles_run;
    b->stuck_tick = now;
    b->stuck_reports++;
    (void)k_thread_setprio(&b->reporter, K_BSCHED_ANNOUNCE_PRIO);
    (void)k_sem_post(&b->report_sem);
}

/* The tick hook of an instance that measures: the release of the cycle
 * the thread sleeps for is stamped at the end of its tick (the tick's own
 * work, a few dozen instructions, is not in the jitter), then the watchdog.
 * A hook of its own, so that an instance that measures nothing runs no
 * more instructions a tick than the watchdog's. */
static void k_bsched_watchdog_stamping(k_ticks_t now)
{
    struct k_bsched *b = k_bsched_watched;
    if (b != NULL && !b->in_cycle && now == b->next_release) {
        b->release_stamp = k_timestamp();
        b->release_stamp_tick = now;
        b->release_stamped = 1;
        return;
    }
    k_bsched_watchdog(now);
}

/* Prints what happened since the last burst: the last "still running"
 * announcement and the overrun totals, each at most once. */
static void k_bsched_report(struct k_bsched *b)
{
    uint32_t irq, events, cycle, late, overruns, stuck, stuck_cycle;
    k_ticks_t stuck_tick;
    irq = k_arch_irq_save();
    events = b->overrun_events;
    cycle = b->last_overrun_cycle;
    late = b->last_overrun_late;
    overruns = b->overruns;
    stuck = b->stuck_reports;
    stuck_cycle = b->stuck_cycle;
    stuck_tick = b->stuck_tick;
    k_arch_irq_restore(irq);
    if (stuck != b->stuck_printed) {
        k_printf("bsched: minor cycle %lu still running at its successor's release (tick %lu)\n",
                 (unsigned long)stuck_cycle, (unsigned long)stuck_tick);
        b->stuck_printed = stuck;
        b->report_lines++;
    }
    if (events != b->reported_events) {
        k_printf("bsched: overrun in minor cycle %lu: %lu ticks late, %lu overruns in %lu cycles so far\n",
                 (unsigned long)cycle, (unsigned long)late, (unsigned long)overruns,
                 (unsigned long)events);
        b->reported_events = events;
        b->report_lines++;
    }
}

/* One burst per wake-up, at most one per K_BSCHED_REPORT_INTERVAL_TICKS
 * (the end of the B-scheduler thread does not wait for the interval). */
static void *k_bsched_reporter(void *arg)
{
    struct k_bsched *b = arg;
    for (;;) {
        uint32_t irq;
        (void)k_sem_wait(&b->report_sem);
        /* Events meanwhile only post report_sem: they cost no wake-up here. */
        while (!b->finished && k_tick_before(k_ticks(), b->next_report))
            (void)k_sem_wait_ticks(&b->finish_sem, b->next_report - k_ticks());
        k_bsched_report(b);
        b->next_report = k_ticks() + (k_ticks_t)K_BSCHED_REPORT_INTERVAL_TICKS;
        /* Back below the cycle, unless a new announcement came meanwhile. */
        irq = k_arch_irq_save();
        if (b->stuck_reports == b->stuck_printed)
            (void)k_thread_setprio(&b->reporter, K_BSCHED_REPORTER_PRIO);
        k_arch_irq_restore(irq);
        if (b->finished) {
            k_bsched_report(b);
            return NULL;
        }
    }
}

/* One jitter sample: smallest, largest and the 64-bit sum in two words. */
static void k_bsched_jitter_sample(struct k_bsched *b, uint32_t jitter)
{
    if (b->jitter_samples == 0u || jitter < b->jitter_min)
        b->jitter_min = jitter;
    if (jitter > b->jitter_max)
        b->jitter_max = jitter;
    b->jitter_sum_lo += jitter;
    if (b->jitter_sum_lo < jitter)
        b->jitter_sum_hi++;
    b->jitter_samples++;
}

/* What bsched_run_cycle calls for each process: the caller's process
 * function between two time stamps; the first of a cycle also closes its
 * release jitter. */
static void k_bsched_invoke(void *context, uint16_t index)
{
    struct k_bsched *b = context;
    uint32_t begin = k_timestamp();
    uint32_t took;
    if (b->release_stamped) {
        /* The first process of the cycle: the thread's cycle runs for
         * next_release (it moves on after the cycle). */
        b->release_stamped = 0;
        /* Only a stamp of this cycle's own release tick counts (the hook
         * stamps the watched instance only). */
        if (b->release_stamp_tick == b->next_release)
            k_bsched_jitter_sample(b, begin - b->release_stamp);
    }
    b->run(b->context, index);
    took = k_timestamp() - begin;
    if (index < BSCHED_MAX_PROCS) {
        struct k_bsched_exec *e = &b->exec[index];
        if (took > e->worst)
            e->worst = took;
        e->runs++;
    }
}

static void *k_bsched_main(void *arg)
{
    struct k_bsched *b = arg;
    /* The first release counts from when the thread runs, not from the
     * call of k_bsched_start: filling the two stacks (for their high-water
     * marks) may take most of a tick, and a release already due would make
     * the first cycle late. */
    b->next_release = k_ticks() + 1u;
    for (;;) {
        k_ticks_t start, end, late;
        int32_t ran;
        (void)k_sleep_until(b->next_release);
        start = k_ticks();
        b->watch = b->next_release + b->period;
        b->in_cycle = 1;
        ran = bsched_run_cycle(b->sched, b->cycle_run, b->cycle_context);
        b->in_cycle = 0;
        end = k_ticks();
        if (ran < 0) {
            k_printf("bsched: cycle failed with error %ld, thread stops\n", (long)ran);
            break;
        }
        b->cycles_run++;
        if (end - start > b->max_cycle_ticks)
            b->max_cycle_ticks = end - start;
        b->next_release += b->period;
        if (!k_tick_before(end, b->next_release)) {
            /* The next release came while this cycle ran: overrun. */
            late = end - b->next_release;
            b->overruns += late / b->period + 1u;
            b->overrun_events++;
            b->last_overrun_cycle = b->cycles_run - 1u;
            b->last_overrun_late = late;
            b->next_release += (late / b->period + 1u) * b->period;
            (void)k_sem_post(&b->report_sem);
        }
        if (b->stop || (b->stop_after != 0u && b->cycles_run >= b->stop_after))
            break;
    }
    if (k_bsched_watched == b) {
        k_tick_hook = NULL;
        k_bsched_watched = NULL;
    }
    b->finished = 1;
    (void)k_sem_post(&b->finish_sem);
    (void)k_sem_post(&b->report_sem);
    (void)k_thread_join(&b->reporter, NULL, K_FOREVER);
    return NULL;
}

int k_bsched_start(struct k_bsched *b, struct bsched *s, bsched_process_fn run, void *context,
                   k_ticks_t period, uint32_t *stack, size_t stack_bytes)
{
    int r;
    if (b == NULL || s == NULL || run == NULL || period == 0u || period > 0x40000000u)
        return K_EINVAL;
    b->sched = s;
    b->run = run;
    b->context = context;
    b->period = period;
    b->next_release = k_ticks() + 1u;
    b->cycles_run = 0;
    b->overruns = 0;
    b->overrun_events = 0;
    b->max_cycle_ticks = 0;
    b->stop = 0;
    b->last_overrun_cycle = 0;
    b->last_overrun_late = 0;
    b->reported_events = 0;
    b->finished = 0;
    b->in_cycle = 0;
    b->stuck_reports = 0;
    b->stuck_cycle = 0;
    b->stuck_tick = 0;
    b->stuck_printed = 0;
    b->report_lines = 0;
    b->next_report = k_ticks();
    k_memset(b->exec, 0, sizeof b->exec);
    b->jitter_min = 0;
    b->jitter_max = 0;
    b->jitter_samples = 0;
    b->jitter_sum_lo = 0;
    b->jitter_sum_hi = 0;
    b->cycle_run = b->measure ? k_bsched_invoke : run;
    b->cycle_context = b->measure ? (void *)b : context;
    b->release_stamp = 0;
    b->release_stamp_tick = 0;
    b->release_stamped = 0;
    if (b->measure)
        (void)k_timestamp_start(); /* whole ticks if the board's counter cannot start */
    r = k_sem_init(&b->report_sem, 0, 1);
    if (r == K_OK)
        r = k_sem_init(&b->finish_sem, 0, 1);
    if (r == K_OK)
        r = k_thread_create(&b->reporter, "bsched-report", k_bsched_reporter, b,
                            b->reporter_stack, sizeof b->reporter_stack, K_BSCHED_REPORTER_PRIO);
    if (r == K_OK)
        r = k_thread_create(&b->thread, "bsched", k_bsched_main, b, stack, stack_bytes,
                            K_PRIO_APP_MAX);
    if (r == K_OK && k_tick_hook == NULL) {
        k_bsched_watched = b;
        k_tick_hook = b->measure ? k_bsched_watchdog_stamping : k_bsched_watchdog;
    }
    return r;
}

int k_bsched_wcet(const struct k_bsched *b, uint16_t index, uint32_t *worst, uint32_t *runs)
{
    uint32_t irq, w, n;
    if (b == NULL || b->sched == NULL || index >= b->sched->count || index >= BSCHED_MAX_PROCS)
        return K_EINVAL;
    /* The pair as one: the thread is more urgent than most callers. */
    irq = k_arch_irq_save();
    w = b->exec[index].worst;
    n = b->exec[index].runs;
    k_arch_irq_restore(irq);
    if (worst != NULL)
        *worst = w;
    if (runs != NULL)
        *runs = n;
    return K_OK;
}

/* (hi:lo) / d for d > 0, saturated to 32 bits, in 32-bit operations: the
 * kernel calls no compiler routine (64-bit division is one on both CPUs). */
static uint32_t k_bsched_div64(uint32_t hi, uint32_t low, uint32_t d)
{
    uint32_t q = 0, r = hi, lo = low, i;
    if (hi >= d)
        return 0xFFFFFFFFu;
    for (i = 0; i < 32u; i++) {
        uint32_t carry = r >> 31;
        r = (r << 1) | (lo >> 31);
        lo <<= 1;
        q <<= 1;
        if (carry != 0u || r >= d) {
            r -= d;
            q |= 1u;
        }
    }
    return q;
}

int k_bsched_jitter(const struct k_bsched *b, uint32_t *min, uint32_t *max, uint32_t *mean,
                    uint32_t *samples)
{
    uint32_t irq, lo, hi, n, jmin, jmax;
    if (b == NULL)
        return K_EINVAL;
    irq = k_arch_irq_save();
    n = b->jitter_samples;
    jmin = b->jitter_min;
    jmax = b->jitter_max;
    lo = b->jitter_sum_lo;
    hi = b->jitter_sum_hi;
    k_arch_irq_restore(irq);
    if (min != NULL)
        *min = jmin;
    if (max != NULL)
        *max = jmax;
    if (mean != NULL)
        *mean = n != 0u ? k_bsched_div64(hi, lo, n) : 0u;
    if (samples != NULL)
        *samples = n;
    return K_OK;
}
