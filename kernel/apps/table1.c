/*
 * Default firmware image: the paper's Table 1 process set run by the
 * B-scheduler (bsched.c), one minor cycle per PIT tick.
 *
 * Prints one line per minor cycle, "cycle T: p1.1 p1.3 p3.1", T being the
 * minor cycle within the major cycle (Table 2's numbering), for
 * TABLE1_MAJOR_CYCLES major cycles; then, per process, the period measured
 * from the PIT tick count at each of its actual runs: a process body records
 * the tick number of the PIT interrupt that started the minor cycle it runs
 * in (the main loop reads it once per cycle, so every process of one cycle
 * sees the same tick even if the next interrupt arrives while the cycle is
 * still printing). If the loop falls behind and a tick passes without a
 * minor cycle, that shows up both as "ticks missed" and in the periods.
 * Then the firmware idles and blinks the LED at 1 Hz.
 *
 * Tick rate: TABLE1_TICK_HZ = 128 Hz (PITM = 64, 7.8125 ms). The original
 * CubeOS tick was 1024 Hz, but a minor cycle here also prints its line on
 * the polled console (at most 26 characters: 6.8 ms at 38400 baud, 4.5 ms
 * at 57600), which must fit in one tick or minor cycles would fall behind.
 */
#include <stdint.h>

#include "bsched.h"
#include "cpu.h"
#include "drivers/duart_console.h"
#include "drivers/led.h"
#include "drivers/pit.h"
#include "kernel/lib/kprintf.h"
#include "mc68332.h"

#ifndef TABLE1_TICK_HZ
#define TABLE1_TICK_HZ 128u
#endif
#ifndef TABLE1_MAJOR_CYCLES
#define TABLE1_MAJOR_CYCLES 4u
#endif

#define TABLE1_PROCS 9u

static const uint8_t table1_pv[TABLE1_PROCS] = {1, 1, 1, 2, 2, 3, 4, 4, 4};
static const char *const table1_names[TABLE1_PROCS] = {
    "p1.1", "p1.2", "p1.3", "p2.1", "p2.2", "p3.1", "p4.1", "p4.2", "p4.3",
};

/* What each process observed of its own runs, in PIT ticks. */
struct run_record {
    uint32_t runs;
    uint32_t last_tick;
    uint32_t min_period;
    uint32_t max_period;
};

/* Shared by the process bodies: the tick that started the current minor cycle. */
struct table1_run {
    uint32_t cycle_tick;
    struct run_record records[TABLE1_PROCS];
};

static struct bsched sched;
static struct table1_run run;

/* The process body: every Table 1 process records the tick it runs in and
 * names itself on the cycle's line. */
static void run_process(void *context, uint16_t index)
{
    struct table1_run *ctx = context;
    struct run_record *r = &ctx->records[index];
    uint32_t now = ctx->cycle_tick;

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
    kprintf(" %s", table1_names[index]);
}

static void print_periods(void)
{
    unsigned i;

    kprintf("measured periods (PIT ticks between consecutive runs):\n");
    for (i = 0; i < TABLE1_PROCS; i++) {
        const struct run_record *r = &run.records[i];
        if (r->runs < 2u) {
            kprintf("period %s: not measured (%lu run)\n", table1_names[i],
                    (unsigned long)r->runs);
        } else if (r->min_period == r->max_period) {
            kprintf("period %s: %lu ticks (%lu runs)\n", table1_names[i],
                    (unsigned long)r->min_period, (unsigned long)r->runs);
        } else {
            kprintf("period %s: %lu..%lu ticks, NOT periodic (%lu runs)\n", table1_names[i],
                    (unsigned long)r->min_period, (unsigned long)r->max_period,
                    (unsigned long)r->runs);
        }
    }
}

int main(void)
{
    uint32_t minor_cycles, n, tick, start_tick, missed = 0;
    int32_t rc;

    console_init();
    led_init();
    kprintf("\nRoboCube firmware: B-scheduler, Table 1 process set\n");
    kprintf("cpu MC68332 %lu Hz, tick %lu Hz, console %lu baud, bsched capacity %u\n",
            (unsigned long)CPU_CLOCK_HZ, (unsigned long)TABLE1_TICK_HZ,
            (unsigned long)CONSOLE_BAUD, (unsigned)BSCHED_MAX_PROCS);

    rc = bsched_init(&sched, table1_pv, TABLE1_PROCS);
    if (rc != BSCHED_OK) {
        kprintf("bsched_init failed: %ld\n", (long)rc);
        return 1;
    }
    minor_cycles = (1ul << sched.maxpv) * TABLE1_MAJOR_CYCLES;
    kprintf("major cycle %lu minor cycles, at most %u processes per minor cycle\n",
            (unsigned long)(1ul << sched.maxpv), (unsigned)sched.perfect);

    if (pit_start(TABLE1_TICK_HZ, NULL) != 0) {
        kprintf("PIT cannot run at %lu Hz\n", (unsigned long)TABLE1_TICK_HZ);
        return 1;
    }
    cpu32_irq_enable();

    start_tick = tick = pit_wait_tick_after(0);
    for (n = 0; n < minor_cycles; n++) {
        if (n > 0u) {
            uint32_t next = pit_wait_tick_after(tick);
            missed += next - tick - 1u;
            tick = next;
        }
        if (sched.cycle == 0u) {
            led_toggle(); /* the LED changes state every major cycle */
        }
        kprintf("cycle %lu:", (unsigned long)sched.cycle);
        run.cycle_tick = tick;
        rc = bsched_run_cycle(&sched, run_process, &run);
        kprintf("\n");
        if (rc < 0) {
            kprintf("bsched_run_cycle failed: %ld\n", (long)rc);
            return 1;
        }
    }
    kprintf("ran %lu minor cycles in %lu ticks, %lu ticks missed\n",
            (unsigned long)minor_cycles, (unsigned long)(tick - start_tick + 1u),
            (unsigned long)missed);
    print_periods();
    kprintf("table1 done; LED blinks at 1 Hz\n");

    for (;;) {
        tick = pit_wait_tick_after(tick);
        if (tick % (TABLE1_TICK_HZ / 2u) == 0u) {
            led_toggle();
        }
    }
}
