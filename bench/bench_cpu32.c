/*
 * The CPU32 side of `make bench`: a bare test image (startup and console of
 * the firmware base, no kernel) that runs every case of bench_core.h on the
 * emulated RoboCube. bench.py runs it under QEMU's instruction log restricted
 * to the library's and the reference engine's functions (-dfilter) and counts
 * the instructions between two calls of bench_mark(), five per case:
 * bsched_init, bsched_fig7_start, BENCH_CYCLES minor cycles of
 * bsched_fig7_step (Fig. 7), the same cycles of bsched_step, (the report, not
 * measured). The image prints one line per case, and "bench done".
 */
#include <stdint.h>

#include "bench_core.h"
#include "boards/robocube/duart_console.h"
#include "kernel/lib/kprintf.h"

#ifndef BENCH_CYCLES
#define BENCH_CYCLES 256u
#endif

static struct bsched sched;
static struct bsched_fig7 fig7;
static uint8_t pv[BSCHED_MAX_PROCS];

/* The phase boundary bench.py looks for (its first instruction). */
void bench_mark(uint32_t phase) __attribute__((noinline));
void bench_mark(uint32_t phase)
{
    __asm__ volatile("" : : "d"(phase) : "memory");
}

int main(void)
{
    uint32_t c;

    console_init();
    kprintf("bench: %u cycles per case, struct bsched %lu bytes (BSCHED_MAX_PROCS %u), "
            "struct bsched_fig7 %lu bytes\n", (unsigned)BENCH_CYCLES,
            (unsigned long)sizeof sched, (unsigned)BSCHED_MAX_PROCS, (unsigned long)sizeof fig7);
    for (c = 0u; c < BENCH_CASES; c++) {
        uint32_t n = bench_sizes[c];
        uint32_t sum7 = 0u, sum = 0u, load = 0u, t;
        int32_t rc;

        bench_make_set(pv, n);
        bench_mark(5u * c);
        rc = bsched_init(&sched, pv, n);
        bench_mark(5u * c + 1u);
        rc |= bsched_fig7_start(&fig7, &sched);
        bench_mark(5u * c + 2u);
        for (t = 0u; t < BENCH_CYCLES; t++) {
            int32_t ran = bsched_fig7_step(&fig7, &sched);
            sum7 = bench_sum(sum7, fig7.ran, ran);
            load += (uint32_t)ran;
        }
        bench_mark(5u * c + 3u);
        for (t = 0u; t < BENCH_CYCLES; t++) {
            sum = bench_sum(sum, sched.ran, bsched_step(&sched));
        }
        bench_mark(5u * c + 4u);
        kprintf("bench case %lu: N=%lu maxpv=%u perfect=%u load=%lu %s\n", (unsigned long)c,
                (unsigned long)n, (unsigned)sched.maxpv, (unsigned)sched.perfect, (unsigned long)load,
                rc == 0 && sum7 == sum ? "same" : "DIFFERENT");
    }
    kprintf("bench done\n");
    return 0;
}
