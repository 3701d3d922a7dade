/* The B-scheduler thread (see k_bsched.h). */
#include "k_bsched.h"

/* The instance the tick watches (the first one started). */
static struct k_bsched *k_bsched_watched;

/* Tick hook: a cycle still running at its successor's release is announced
 * at once; the in-thread accounting counts it when it ends. */
static void k_bsched_watchdog(k_ticks_t now)
{
    struct k_bsched *b = k_bsched_watched;
    if (b == NULL || !b->in_cycle || now != b->watch)
        return;
    b->stuck_reports++;
    k_printf("bsched: minor cycle %lu still running at its successor's release (tick %lu)\n",
             (unsigned long)b->cycles_run, (unsigned long)now);
}

/* Prints what happened since the last report; one line per wake-up, so
 * overruns that come faster than the console are summed, never lost. */
static void *k_bsched_reporter(void *arg)
{
    struct k_bsched *b = arg;
    for (;;) {
        uint32_t irq, events, cycle, late, overruns;
        (void)k_sem_wait(&b->report_sem);
        irq = k_arch_irq_save();
        events = b->overrun_events;
        cycle = b->last_overrun_cycle;
        late = b->last_overrun_late;
        overruns = b->overruns;
        k_arch_irq_restore(irq);
        if (events != b->reported_events) {
            k_printf("bsched: overrun in minor cycle %lu: %lu ticks late, %lu overruns in %lu cycles so far\n",
                     (unsigned long)cycle, (unsigned long)late, (unsigned long)overruns,
                     (unsigned long)events);
            b->reported_events = events;
        }
        if (b->finished)
            return NULL;
    }
}

static void *k_bsched_main(void *arg)
{
    struct k_bsched *b = arg;
    for (;;) {
        k_ticks_t start, end, late;
        int32_t ran;
        (void)k_sleep_until(b->next_release);
        start = k_ticks();
        b->watch = b->next_release + b->period;
        b->in_cycle = 1;
        ran = bsched_run_cycle(b->sched, b->run, b->context);
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
    r = k_sem_init(&b->report_sem, 0, 0xFFFFFFFFu);
    if (r == K_OK)
        r = k_thread_create(&b->reporter, "bsched-report", k_bsched_reporter, b,
                            b->reporter_stack, sizeof b->reporter_stack, K_PRIO_APP_MAX - 1u);
    if (r == K_OK)
        r = k_thread_create(&b->thread, "bsched", k_bsched_main, b, stack, stack_bytes,
                            K_PRIO_APP_MAX);
    if (r == K_OK && k_tick_hook == NULL) {
        k_bsched_watched = b;
        k_tick_hook = k_bsched_watchdog;
    }
    return r;
}
