/*
 * The CPU32 side of `make bench`: a bare test image (startup and console of
 * the firmware base, no kernel) that runs every case of bench_core.h on the
 * emulated RoboCube (bench_image.h). bench.py runs it under QEMU's
 * instruction log restricted to the library's and the reference engine's
 * functions (-dfilter) and counts the instructions between two calls of
 * bench_mark(), five per case. The image prints one line per case, and
 * "bench done".
 */
#include <stdint.h>

#include "bench_image.h"
#include "boards/robocube/duart_console.h"

void bench_mark(uint32_t phase)
{
    __asm__ volatile("" : : "d"(phase) : "memory");
}

int main(void)
{
    console_init();
    bench_run_cases();
    return 0;
}
