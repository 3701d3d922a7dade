/*
 * bsched-bench: one case of `make bench` on the host, to be run under
 * callgrind (bsched/bench/bench.py reads the inclusive instruction counts of
 * bsched_init, bsched_fast_init, bsched_step and bsched_fast_step).
 *   bsched-bench N CYCLES
 * Prints "N maxpv perfect cycles loads sizeof(struct bsched) sizeof(struct
 * bsched_fast)"; exit 1 if Fig. 7 and bsched_fast_step disagree.
 */
#include <stdio.h>
#include <stdlib.h>

#include "bench_core.h"

static struct bsched fig7, fast;
static struct bsched_fast table;
static uint8_t pv[BSCHED_MAX_PROCS];

int main(int argc, char **argv)
{
    unsigned long n, cycles, t, load = 0;
    uint32_t sum7 = 0u, sumf = 0u;

    if (argc != 3 || (n = strtoul(argv[1], NULL, 10)) == 0 || n > BSCHED_MAX_PROCS ||
        (cycles = strtoul(argv[2], NULL, 10)) == 0) {
        fprintf(stderr, "usage: bsched-bench N CYCLES (1 <= N <= %d)\n", BSCHED_MAX_PROCS);
        return 2;
    }
    bench_make_set(pv, (uint32_t)n);
    if (bsched_init(&fig7, pv, n) != BSCHED_OK) {
        fprintf(stderr, "bsched-bench: bsched_init failed\n");
        return 1;
    }
    fast = fig7;
    if (bsched_fast_init(&table, &fast) != BSCHED_OK) {
        fprintf(stderr, "bsched-bench: bsched_fast_init failed\n");
        return 1;
    }
    for (t = 0; t < cycles; t++) {
        int32_t ran = bsched_step(&fig7);
        sum7 = bench_sum(sum7, &fig7, ran);
        load += (unsigned long)ran;
    }
    for (t = 0; t < cycles; t++) {
        int32_t ran = bsched_fast_step(&fast, &table);
        sumf = bench_sum(sumf, &fast, ran);
    }
    if (sum7 != sumf) {
        fprintf(stderr, "bsched-bench: Fig. 7 and bsched_fast_step disagree\n");
        return 1;
    }
    printf("%lu %u %u %lu %lu %zu %zu\n", n, (unsigned)fig7.maxpv, (unsigned)fig7.perfect, cycles,
           load, sizeof(struct bsched), sizeof(struct bsched_fast));
    return 0;
}
