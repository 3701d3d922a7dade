/*
 * The Cortex-M4 side of the two-CPU bench (bench/bench_cpus.py): the cases
 * and phases of bench/bench_image.h, as the CPU32's bench image runs them,
 * on the stm32f405 board with its polled console. The kernel is initialised
 * only for the console; no thread runs.
 */
#include <stdint.h>

#include "bench_image.h"
#include "kernel.h"
#include "k_board.h"

void bench_mark(uint32_t phase)
{
    __asm__ volatile("" : : "r"(phase) : "memory");
}

int main(void)
{
    k_init();
    (void)k_board_init();
    bench_run_cases();
    return 0;
}
