/*
 * Compiler runtime check image: the vectors of rt_vectors.c computed on the
 * CPU32 through the compiler runtime every image links, then dt() and
 * (float)value(q) from inside a running PDL process (the paper's section 5
 * uses both). apps/rtcheck/tests/ compares each line with the host's. An
 * ordinary main (drivers/board_main.c starts the board and runs it as a thread).
 *
 * Console: "RT NAME INDEX BITS" per vector (BITS: 16 hex digits), "RT done N",
 * the C library's lines of rt_libc.c (through newlib's printf) and "RT libc N",
 * then "RT dt CYCLE BITS US" for the first PDL_CHECK_CYCLES cycles (dt()'s
 * bits and dt_us()), "RT value_float CYCLE BITS" ((float)value(q) of an
 * integer quantity that counts down from RT_VALUE_START), and "RT end".
 */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kernel.h"
#include "pdl/pdl.h"
#include "rt_libc.h"
#include "rt_vectors.h"

#define RT_PDL_HZ 100u
#define PDL_CHECK_CYCLES 8u
#define RT_VALUE_START (-16777215)

static struct pdl_quantity counter;
static volatile uint32_t seen;
static uint32_t dt_bits[PDL_CHECK_CYCLES], dt_usecs[PDL_CHECK_CYCLES];
static uint32_t value_bits[PDL_CHECK_CYCLES];

static uint32_t float_bits(float f)
{
    union { float f; uint32_t u; } v;
    v.f = f;
    return v.u;
}

static void rtcheck_emit(const char *name, unsigned index, uint64_t bits)
{
    k_printf("RT %s %u %08lx%08lx\n", name, index, (unsigned long)(bits >> 32),
             (unsigned long)(bits & 0xFFFFFFFFu));
}

/* Runs every cycle: records dt() and the float of the counter's value. */
static void rtcheck_observe(void)
{
    uint32_t i = seen;
    float d = dt(), v = (float)value(counter);
    if (i < PDL_CHECK_CYCLES) {
        dt_bits[i] = float_bits(d);
        dt_usecs[i] = dt_us();
        value_bits[i] = float_bits(v);
        seen = i + 1u;
    }
    add_value(counter, -1);
}

int main(void)
{
    unsigned n;
    uint32_t i;
    int r;
    n = rt_vectors_run(rtcheck_emit);
    k_printf("RT done %u\n", n);
    k_printf("RT libc %d\n", rt_libc_run());
    r = add_quantity(&counter, RT_VALUE_START - 100, 0, RT_VALUE_START);
    if (r >= 0)
        r = add_process(rtcheck_observe);
    if (r >= 0)
        r = pdl_set_frequency(RT_PDL_HZ);
    if (r >= 0)
        r = run_pdl();
    if (r < 0) {
        k_printf("RT failed: %s (%d)\n", pdl_strerror(r), r);
        return 1;
    }
    while (seen < PDL_CHECK_CYCLES)
        (void)k_sleep_ticks(K_TICK_HZ / RT_PDL_HZ);
    for (i = 0; i < PDL_CHECK_CYCLES; i++)
        k_printf("RT dt %lu %08lx %lu\n", (unsigned long)i, (unsigned long)dt_bits[i],
                 (unsigned long)dt_usecs[i]);
    for (i = 0; i < PDL_CHECK_CYCLES; i++)
        k_printf("RT value_float %lu %08lx\n", (unsigned long)i, (unsigned long)value_bits[i]);
    {
        /* malloc in the SRAM between .bss and the stack: a small block, and one
         * larger than the whole SRAM, which must fail with ENOMEM. */
        void *small = malloc(1000u), *huge;
        errno = 0;
        huge = malloc(2u << 20);
        k_printf("RT malloc small=%d huge_refused=%d enomem=%d\n", small != NULL, huge == NULL,
                 errno == ENOMEM);
        free(small);
    }
    k_printf("RT end\n");
    {
        /* stdin: a console line, edited and echoed, through newlib's fgets and read(0). */
        char line[40];
        printf("RT input?\n");
        if (fgets(line, sizeof line, stdin) != NULL) {
            line[strcspn(line, "\n")] = '\0';
            printf("RT input [%s] getchar=%d\n", line, getchar());
        }
    }
    return 0;
}
