/*
 * The Cortex-M4 side of the two-CPU bench (bench/bench_cpus.py):
 * the phases of bsched/bench/bench_cpu32.c (bsched_init, bsched_fig7_start,
 * BENCH_CYCLES minor cycles of Fig. 7, the same of bsched_step), each ended
 * by bench_mark(), on the stm32f405 board with its polled console. The
 * kernel is initialised only for the console; no thread runs.
 */
#include <stdint.h>

#include "bench_core.h"
#include "kernel.h"
#include "k_board.h"
#include "kernel/lib/kprintf.h"

#ifndef BENCH_CYCLES
#define BENCH_CYCLES 256u
#endif

static struct bsched sched;
static struct bsched_fig7 fig7;
static uint8_t pv[BSCHED_MAX_PROCS];

void bench_mark(uint32_t phase) __attribute__((noinline));
void bench_mark(uint32_t phase)
{
    __asm__ volatile("" : : "r"(phase) : "memory");
}

int main(void)
{
    uint32_t c;

    k_init();
    (void)k_board_init();
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
