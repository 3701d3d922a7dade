/*
 * Default firmware image: the nanokernel runs the paper's Table 1 process
 * set in its B-scheduler thread (kernel/k_bsched.c), one bsched minor cycle
 * per kernel tick, at the highest application priority.
 *
 * Threads (priority: larger is more urgent):
 *   bsched         27  one minor cycle per tick, TABLE1_MAJOR_CYCLES major cycles
 *   bsched-report  26  the kernel's overrun reporter (silent when none occur)
 *   table1          2  starts the B-scheduler thread, waits for it, prints the summary
 *   led             1  toggles the LED every 0.5 s once the run is over
 *
 * Output: one line per minor cycle, "cycle T: p1.1 p1.3 p3.1", T being the
 * minor cycle within the major cycle (Table 2's numbering), printed by the
 * process bodies themselves (the first process of a cycle opens the line,
 * the last one ends it; bsched's s->ran lists the cycle's processes). Then,
 * per process, the period measured from the kernel tick count (k_ticks())
 * at each of its actual runs, and the B-scheduler thread's overrun count.
 *
 * Tick rate: this image builds the kernel with K_TICK_HZ = 128 (PIT PITM =
 * 64, 7.8125 ms; boards/robocube/board.mk FW_TICK_HZ) instead of the kernel's
 * default 1024 Hz, because every minor cycle prints its line: up to 26
 * characters, 6.8 ms at 38400 baud on real hardware, about 2.8 KB/s on
 * average at 128 Hz, within the console's 3.84 KB/s. At 1024 Hz the console
 * ring would fill and the B-scheduler thread would wait for it and overrun.
 */
#include <stdint.h>

#include "bsched.h"
#include "kernel.h"
#include "boards/include/board.h"
#include "k_board.h"
#include "k_bsched.h"
#include "boards/include/board_led.h"

#ifndef TABLE1_MAJOR_CYCLES
#define TABLE1_MAJOR_CYCLES 4u
#endif

#define TABLE1_PROCS 9u
/* One bsched minor cycle per kernel tick. */
#define TABLE1_CYCLE_TICKS 1u
/* The LED changes state every half second. */
#define LED_TOGGLE_TICKS (K_TICK_HZ / 2u)

static const uint8_t table1_pv[TABLE1_PROCS] = {1, 1, 1, 2, 2, 3, 4, 4, 4};
static const char *const table1_names[TABLE1_PROCS] = {
    "p1.1", "p1.2", "p1.3", "p2.1", "p2.2", "p3.1", "p4.1", "p4.2", "p4.3",
};

/* What each process observed of its own runs, in kernel ticks. */
struct run_record {
    uint32_t runs;
    k_ticks_t last_tick;
    uint32_t min_period;
    uint32_t max_period;
};

/* Shared by the process bodies (all run in the B-scheduler thread). */
struct table1_run {
    const struct bsched *sched;
    uint32_t cycles_seen;      /* minor cycles whose line was opened */
    k_ticks_t first_cycle_tick;
    k_ticks_t last_cycle_tick;
    struct run_record records[TABLE1_PROCS];
};

static struct bsched sched;
static struct table1_run run;
static struct k_bsched bsched_thread;
static struct k_thread table1_thread, led_thread;
K_STACK_DEFINE(bsched_stack, 2048u);
K_STACK_DEFINE(table1_stack, 2048u);
K_STACK_DEFINE(led_stack, 1024u);

/* The process body: every Table 1 process records the tick it runs at and
 * names itself on its minor cycle's line. bsched_run_cycle has already
 * stepped: s->ran[0..ran_count-1] are this cycle's processes in execution
 * order (each once) and s->cycle is the number of the next cycle. */
static void run_process(void *context, uint16_t index)
{
    struct table1_run *ctx = context;
    const struct bsched *s = ctx->sched;
    struct run_record *r = &ctx->records[index];
    k_ticks_t now = k_ticks();

    if (index == s->ran[0]) {
        uint32_t major = 1ul << s->maxpv;
        if (ctx->cycles_seen == 0u) {
            ctx->first_cycle_tick = now;
        }
        ctx->cycles_seen++;
        ctx->last_cycle_tick = now;
        k_printf("cycle %lu:", (unsigned long)((s->cycle + major - 1u) & (major - 1u)));
    }
    if (r->runs > 0u) {
        uint32_t period = now - r->last_tick;
        if (r->runs == 1u || period < r->min_period) {
            r->min_period = period;
        }
        if (r->runs == 1u || period > r->max_period) {
            r->max_period = period;
        }
    }
    r->runs++;
    r->last_tick = now;
    k_printf(" %s", table1_names[index]);
    if (index == s->ran[s->ran_count - 1u]) {
        k_printf("\n");
    }
}

static void print_periods(void)
{
    unsigned i;

    k_printf("measured periods (kernel ticks between consecutive runs):\n");
    for (i = 0; i < TABLE1_PROCS; i++) {
        const struct run_record *r = &run.records[i];
        if (r->runs < 2u) {
            k_printf("period %s: not measured (%lu run)\n", table1_names[i],
                     (unsigned long)r->runs);
        } else if (r->min_period == r->max_period) {
            k_printf("period %s: %lu ticks (%lu runs)\n", table1_names[i],
                     (unsigned long)r->min_period, (unsigned long)r->runs);
        } else {
            k_printf("period %s: %lu..%lu ticks, NOT periodic (%lu runs)\n", table1_names[i],
                     (unsigned long)r->min_period, (unsigned long)r->max_period,
                     (unsigned long)r->runs);
        }
    }
}

/* Toggles the LED at absolute tick multiples of LED_TOGGLE_TICKS: no drift. */
static void *led_main(void *arg)
{
    k_ticks_t next = k_ticks();
    (void)arg;
    for (;;) {
        int r;
        next += LED_TOGGLE_TICKS;
        r = k_sleep_until(next);
        if (r != K_OK) {
            k_printf("led: k_sleep_until failed: %d\n", r);
            return NULL;
        }
        led_toggle();
    }
}

static void *table1_main(void *arg)
{
    uint32_t minor_cycles, ticks_spanned;
    int32_t rc;
    int r;
    (void)arg;

    rc = bsched_init(&sched, table1_pv, TABLE1_PROCS);
    if (rc != BSCHED_OK) {
        k_printf("bsched_init failed: %ld\n", (long)rc);
        return NULL;
    }
    minor_cycles = (1ul << sched.maxpv) * TABLE1_MAJOR_CYCLES;
    k_printf("major cycle %lu minor cycles, at most %u processes per minor cycle\n",
             (unsigned long)(1ul << sched.maxpv), (unsigned)sched.perfect);

    run.sched = &sched;
    bsched_thread.stop_after = minor_cycles;
    r = k_bsched_start(&bsched_thread, &sched, run_process, &run, TABLE1_CYCLE_TICKS,
                       bsched_stack, sizeof bsched_stack);
    if (r != K_OK) {
        k_printf("k_bsched_start failed: %d\n", r);
        return NULL;
    }
    r = k_thread_join(&bsched_thread.thread, NULL, K_FOREVER);
    if (r != K_OK) {
        k_printf("joining the B-scheduler thread failed: %d\n", r);
        return NULL;
    }

    ticks_spanned = run.cycles_seen == 0u ? 0u : run.last_cycle_tick - run.first_cycle_tick + 1u;
    k_printf("ran %lu minor cycles in %lu ticks, %lu ticks missed\n",
             (unsigned long)run.cycles_seen, (unsigned long)ticks_spanned,
             (unsigned long)(ticks_spanned - run.cycles_seen));
    print_periods();
    k_printf("bsched thread: %lu minor cycles from tick %lu, overruns: %lu, "
             "longest cycle %lu ticks, console bytes dropped: %lu\n",
             (unsigned long)bsched_thread.cycles_run, (unsigned long)run.first_cycle_tick,
             (unsigned long)bsched_thread.overruns, (unsigned long)bsched_thread.max_cycle_ticks,
             (unsigned long)k_board_console_dropped());

    if (board_spawn(&led_thread, "led", led_main, NULL, led_stack, sizeof led_stack,
                    K_PRIO_APP_MIN) != K_OK)
        return NULL;
    k_printf("table1 done at tick %lu (%lu ms); LED thread blinks at 1 Hz\n",
             (unsigned long)k_ticks(), (unsigned long)k_uptime_ms());
    return NULL;
}

int main(void)
{
    board_start("table1");
    /* Queued in the console ring; goes out once k_start enables interrupts. */
    k_printf("\n%s firmware: B-scheduler, Table 1 process set\n", board_name);
    k_printf("nanokernel: tick %lu Hz, B-scheduler thread at priority %u, %lu tick per minor cycle\n",
             (unsigned long)K_TICK_HZ, (unsigned)K_PRIO_APP_MAX,
             (unsigned long)TABLE1_CYCLE_TICKS);
    k_printf("cpu %s %lu Hz, tick %lu Hz, console %lu baud (interrupt-driven), "
             "bsched capacity %u\n",
             board_cpu_name, (unsigned long)board_cpu_hz, (unsigned long)K_TICK_HZ,
             (unsigned long)board_console_baud,
             (unsigned)BSCHED_MAX_PROCS);
    (void)board_spawn(&table1_thread, "table1", table1_main, NULL, table1_stack,
                      sizeof table1_stack, K_PRIO_APP_MIN + 1u);
    k_start();
    return 0;
}
