/*
 * The benchmark of `make bench`, shared by the host program (run under
 * callgrind) and the CPU32 image (run under QEMU's instruction log).
 *
 * Cases: N = 9 is the paper's Table 1 set (pv 1 1 1 2 2 3 4 4 4); every other N
 * draws pv uniformly from 3..12 with a fixed linear congruential generator
 * (the distribution of the speed goals' figures: about U = 0.25 N / 10 processes due
 * per cycle, 6.4 at N = 256, 102 at N = 4096). Each case plans the set with
 * bsched_init, starts Fig. 7's reference engine (bsched/proofs/ref/bsched_fig7.c) on
 * the plan and runs the same `cycles` minor cycles with Fig. 7
 * (bsched_fig7_step) and with the library's bsched_step. The two are checked
 * equal cycle by cycle (a checksum of every ran[] list), outside the measured
 * functions.
 */
#ifndef BSCHED_BENCH_CORE_H
#define BSCHED_BENCH_CORE_H

#include "bsched.h"
#include "bsched_fig7.h"

#define BENCH_CASES 5u
static const uint16_t bench_sizes[BENCH_CASES] = {9u, 64u, 256u, 1024u, 4096u};
#define BENCH_PV_LO 3u
#define BENCH_PV_HI 12u

static void bench_make_set(uint8_t *pv, uint32_t n)
{
    static const uint8_t table1[9] = {1u, 1u, 1u, 2u, 2u, 3u, 4u, 4u, 4u};
    uint32_t x = 2026u;
    uint32_t i;

    for (i = 0u; i < n; i++) {
        x = x * 1103515245u + 12345u;
        pv[i] = n == 9u ? table1[i]
                        : (uint8_t)(BENCH_PV_LO + (x >> 16) % (BENCH_PV_HI - BENCH_PV_LO + 1u));
    }
}

/* Order-sensitive checksum of one cycle's ran[] list. */
static uint32_t bench_sum(uint32_t sum, const uint16_t *ran_list, int32_t ran)
{
    int32_t k;
    sum = sum * 31u + (uint32_t)ran;
    for (k = 0; k < ran; k++) {
        sum = sum * 31u + ran_list[k];
    }
    return sum;
}

#endif /* BSCHED_BENCH_CORE_H */
