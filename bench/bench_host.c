/*
 * bsched-bench: one case of `make bench` on the host, to be run under
 * callgrind (bench/bench.py reads the inclusive instruction counts of
 * bsched_init, bsched_fig7_start, bsched_fig7_step and bsched_step).
 *   bsched-bench N CYCLES
 * Prints "N maxpv perfect cycles loads sizeof(struct bsched)
 * sizeof(struct bsched_fig7)"; exit 1 if Fig. 7 and bsched_step disagree.
 */
#include <stdio.h>
#include <stdlib.h>

#include "bench_core.h"

static struct bsched sched;
static struct bsched_fig7 fig7;
static uint8_t pv[BSCHED_MAX_PROCS];

int main(int argc, char **argv)
{
    unsigned long n, cycles, t, load = 0;
    uint32_t sum7 = 0u, sum = 0u;

    if (argc != 3 || (n = strtoul(argv[1], NULL, 10)) == 0 || n > BSCHED_MAX_PROCS ||
        (cycles = strtoul(argv[2], NULL, 10)) == 0) {
        fprintf(stderr, "usage: bsched-bench N CYCLES (1 <= N <= %d)\n", BSCHED_MAX_PROCS);
        return 2;
    }
    bench_make_set(pv, (uint32_t)n);
    if (bsched_init(&sched, pv, n) != BSCHED_OK || bsched_fig7_start(&fig7, &sched) != BSCHED_OK) {
        fprintf(stderr, "bsched-bench: bsched_init or bsched_fig7_start failed\n");
        return 1;
    }
    for (t = 0; t < cycles; t++) {
        int32_t ran = bsched_fig7_step(&fig7, &sched);
        sum7 = bench_sum(sum7, fig7.ran, ran);
        load += (unsigned long)ran;
    }
    for (t = 0; t < cycles; t++) {
        int32_t ran = bsched_step(&sched);
        sum = bench_sum(sum, sched.ran, ran);
    }
    if (sum7 != sum) {
        fprintf(stderr, "bsched-bench: Fig. 7 and bsched_step disagree\n");
        return 1;
    }
    printf("%lu %u %u %lu %lu %zu %zu\n", n, (unsigned)sched.maxpv, (unsigned)sched.perfect, cycles,
           load, sizeof(struct bsched), sizeof(struct bsched_fig7));
    return 0;
}
