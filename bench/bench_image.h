/*
 * The body of the two bench images, bench/bench_cpu32.c (the RoboCube's
 * CPU32) and bench/bench_armv7m.c (the Cortex-M4): every case of
 * bench_core.h in five phases, each ended by bench_mark(), which each image
 * defines for its CPU (bench.py finds the phase boundaries by its first
 * instruction): bsched_init, bsched_fig7_start, BENCH_CYCLES minor cycles of
 * bsched_fig7_step (Fig. 7), the same cycles of bsched_step, then the case's
 * report line (not measured). Ends with "bench done". The image brings its
 * console up before bench_run_cases.
 */
#ifndef BSCHED_BENCH_IMAGE_H
#define BSCHED_BENCH_IMAGE_H

#include <stdint.h>

#include "bench_core.h"
#include "kernel/lib/kprintf.h"

#ifndef BENCH_CYCLES
#define BENCH_CYCLES 256u
#endif

/* The phase boundary bench.py looks for (its first instruction). */
void bench_mark(uint32_t phase) __attribute__((noinline));

static struct bsched bench_sched;
static struct bsched_fig7 bench_fig7;
static uint8_t bench_pv[BSCHED_MAX_PROCS];

static void bench_run_cases(void)
{
    uint32_t c;

    kprintf("bench: %u cycles per case, struct bsched %lu bytes (BSCHED_MAX_PROCS %u), "
            "struct bsched_fig7 %lu bytes\n", (unsigned)BENCH_CYCLES,
            (unsigned long)sizeof bench_sched, (unsigned)BSCHED_MAX_PROCS,
            (unsigned long)sizeof bench_fig7);
    for (c = 0u; c < BENCH_CASES; c++) {
        uint32_t n = bench_sizes[c];
        uint32_t sum7 = 0u, sum = 0u, load = 0u, t;
        int32_t rc;

        bench_make_set(bench_pv, n);
        bench_mark(5u * c);
        rc = bsched_init(&bench_sched, bench_pv, n);
        bench_mark(5u * c + 1u);
        rc |= bsched_fig7_start(&bench_fig7, &bench_sched);
        bench_mark(5u * c + 2u);
        for (t = 0u; t < BENCH_CYCLES; t++) {
            int32_t ran = bsched_fig7_step(&bench_fig7, &bench_sched);
            sum7 = bench_sum(sum7, bench_fig7.ran, ran);
            load += (uint32_t)ran;
        }
        bench_mark(5u * c + 3u);
        for (t = 0u; t < BENCH_CYCLES; t++) {
            sum = bench_sum(sum, bench_sched.ran, bsched_step(&bench_sched));
        }
        bench_mark(5u * c + 4u);
        kprintf("bench case %lu: N=%lu maxpv=%u perfect=%u load=%lu %s\n", (unsigned long)c,
                (unsigned long)n, (unsigned)bench_sched.maxpv, (unsigned)bench_sched.perfect,
                (unsigned long)load, rc == 0 && sum7 == sum ? "same" : "DIFFERENT");
    }
    kprintf("bench done\n");
}

#endif /* BSCHED_BENCH_IMAGE_H */
