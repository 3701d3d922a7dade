/*
 * PDL benchmark image. Phases (the host reads the console, and for the
 * instruction counts a QEMU exec trace; pdl/tests/target/):
 *
 *  1. sweep: for N = 5, 10, 20, 30 processes (pv = k mod 5, each adding to
 *     two quantities of its own: Q = 2N), BENCH_SWEEP_CYCLES cycles at one
 *     cycle per tick. bench_config_start(N) marks each in the trace.
 *  2. load: a spinner thread at the lowest priority counts loops for
 *     BENCH_LOAD_TICKS ticks without PDL, then as long with N = 20, Q = 40
 *     at f0 = 1024 Hz: load = 1 - spins_with / spins_without (everything the
 *     PDL costs: tick wake-up, switches, the cycle).
 *  3. overload: one process of ~20 ticks at f0 = 64 Hz (16 ticks): the
 *     kernel counts and reports the overruns; the image prints them.
 *
 * Output: "PDL-BENCH key=value ..." lines, "PDL-BENCH RESULT PASS|FAIL".
 */
#include <stdint.h>

#include "kernel.h"
#include "boards/include/board.h"
#include "pdl/pdl.h"
#include "pdl/pdl_board.h"

#define BENCH_MAX_N 30
#define BENCH_SWEEP_CYCLES 40u
#define BENCH_LOAD_TICKS 256u
#define BENCH_OVERLOAD_CYCLES 12u

static struct pdl_quantity bq[2 * BENCH_MAX_N];

static inline void bench_body(unsigned k)
{
    add_value(bq[2 * k], (value(bq[2 * k + 1]) - value(bq[2 * k])) / 4);
    add_value(bq[2 * k + 1], 1);
}

#define P(k) static void bench_p##k(void) { bench_body(k); }
P(0) P(1) P(2) P(3) P(4) P(5) P(6) P(7) P(8) P(9) P(10) P(11) P(12) P(13) P(14)
P(15) P(16) P(17) P(18) P(19) P(20) P(21) P(22) P(23) P(24) P(25) P(26) P(27) P(28) P(29)
static pdl_process_fn const bench_procs[BENCH_MAX_N] = {
    bench_p0, bench_p1, bench_p2, bench_p3, bench_p4, bench_p5, bench_p6, bench_p7,
    bench_p8, bench_p9, bench_p10, bench_p11, bench_p12, bench_p13, bench_p14, bench_p15,
    bench_p16, bench_p17, bench_p18, bench_p19, bench_p20, bench_p21, bench_p22, bench_p23,
    bench_p24, bench_p25, bench_p26, bench_p27, bench_p28, bench_p29,
};

static int failed;

static void check(int ok, const char *what)
{
    if (!ok) {
        failed = 1;
        k_printf("PDL-BENCH FAILED %s\n", what);
    }
}

/* The trace finds each configuration by this function's entry. */
__attribute__((noinline)) void bench_config_start(unsigned n)
{
    __asm__ volatile("" : : "r"(n) : "memory");
}

static int bench_setup(unsigned n)
{
    unsigned k;
    int r = pdl_reset();
    if (r == PDL_OK)
        r = pdl_set_frequency(1000u);        /* one tick: 1024 Hz */
    for (k = 0; r >= 0 && k < 2u * n; k++)
        r = add_quantity(&bq[k], -100000, 100000, 0);
    for (k = 0; r >= 0 && k < n; k++)
        r = add_process_pv(bench_procs[k], (int)(k % 5u));
    return r < 0 ? r : PDL_OK;
}

/* Runs the set for `cycles` cycles (stops the thread after them). */
static int bench_run(uint32_t cycles)
{
    struct pdl_stats st;
    int r = run_pdl();
    if (r != PDL_OK)
        return r;
    do {
        (void)k_sleep_ticks(4);
        pdl_get_stats(&st);
    } while (st.cycles < cycles);
    return pdl_stop(1000u);
}

static volatile uint32_t spins;
static volatile int spinning;

static void *spinner_main(void *arg)
{
    (void)arg;
    for (;;) {
        if (spinning)
            spins++;
    }
    return NULL;
}

static uint32_t spin_for(k_ticks_t ticks)
{
    uint32_t before;
    k_ticks_t start;
    (void)k_sleep_ticks(1);
    start = k_ticks();
    before = spins;
    spinning = 1;
    (void)k_sleep_until(start + ticks);
    spinning = 0;
    return spins - before;
}

/* The overloaded program: at f0 = 64 Hz (16 ticks), a process that computes
 * for 20 ticks of kernel time (so on any CPU, whatever its speed: a count of
 * turns made for the CPU32 ran in under a tick on a Cortex-M4). Every cycle overruns;
 * the kernel's reporter prints at most one burst of lines a second and sums
 * the rest, so lower threads run whatever the overrun rate. */
#define OVERLOAD_HZ 64u
static volatile uint32_t overload_sink;
#define OVERLOAD_TICKS 20u
static void overloaded(void)
{
    k_ticks_t start = k_ticks();
    while (k_ticks() - start < OVERLOAD_TICKS)
        overload_sink++;
}

static struct k_thread bench_thread, spinner_thread;
K_STACK_DEFINE(bench_stack, 2048u);
K_STACK_DEFINE(spinner_stack, 512u);

static void *bench_main(void *arg)
{
    static const unsigned sweep[] = {5u, 10u, 20u, 30u};
    uint32_t idle, busy, load_permille;
    struct pdl_stats st;
    unsigned i;
    int r;
    (void)arg;

    for (i = 0; i < sizeof sweep / sizeof sweep[0]; i++) {
        r = bench_setup(sweep[i]);
        check(r == PDL_OK, "sweep setup");
        bench_config_start(sweep[i]);
        r = bench_run(BENCH_SWEEP_CYCLES);
        check(r == PDL_OK, "sweep run");
        pdl_get_stats(&st);
        k_printf("PDL-BENCH sweep n=%u q=%u cycles=%lu runs=%lu commits=%lu overruns=%lu\n",
                 sweep[i], 2u * sweep[i], (unsigned long)st.cycles,
                 (unsigned long)st.process_runs, (unsigned long)st.commits,
                 (unsigned long)st.overruns);
        check(st.overruns == 0u, "no overrun in the sweep");
    }
    k_printf("PDL-BENCH SWEEP DONE\n");

    idle = spin_for(BENCH_LOAD_TICKS);
    r = bench_setup(20u);
    check(r == PDL_OK, "load setup");
    r = run_pdl();
    check(r == PDL_OK, "load run_pdl");
    busy = spin_for(BENCH_LOAD_TICKS);
    r = pdl_stop(1000u);
    check(r == PDL_OK, "load stop");
    pdl_get_stats(&st);
    load_permille = idle == 0u ? 1000u : 1000u - (uint32_t)((uint64_t)busy * 1000u / idle);
    k_printf("PDL-BENCH load n=20 q=40 f0_mhz=%lu spins_idle=%lu spins_pdl=%lu load_permille=%lu "
             "cycles=%lu overruns=%lu max_cycle_ticks=%lu stack_used=%lu stack_size=%lu\n",
             (unsigned long)pdl_frequency_mhz(), (unsigned long)idle, (unsigned long)busy,
             (unsigned long)load_permille, (unsigned long)st.cycles,
             (unsigned long)st.overruns, (unsigned long)st.max_cycle_ticks,
             (unsigned long)pdl_stack_used(), (unsigned long)pdl_stack_size());
    check(st.overruns == 0u, "no overrun at 1 kHz");
    check(load_permille <= 500u, "load at most 50 %");

    r = pdl_reset();
    if (r == PDL_OK)
        r = pdl_set_frequency(OVERLOAD_HZ);
    if (r == PDL_OK)
        r = add_process(overloaded) < 0 ? -1 : PDL_OK;
    check(r == PDL_OK, "overload setup");
    r = bench_run(BENCH_OVERLOAD_CYCLES);
    check(r == PDL_OK, "overload run");
    pdl_get_stats(&st);
    k_printf("PDL-BENCH overload cycles=%lu overruns=%lu overrun_events=%lu max_cycle_ticks=%lu\n",
             (unsigned long)st.cycles, (unsigned long)st.overruns,
             (unsigned long)st.overrun_events, (unsigned long)st.max_cycle_ticks);
    check(st.overruns > 0u && st.overrun_events > 0u, "overload overruns counted");
    (void)k_sleep_ticks(64);    /* let the reporter's lines out first */
    k_printf("PDL-BENCH RESULT %s\n", failed ? "FAIL" : "PASS");
    return NULL;
}

int main(void)
{
    board_start("pdl_bench");
    k_printf("\nPDL benchmark: tick %lu Hz\n", (unsigned long)K_TICK_HZ);
    if (board_spawn(&spinner_thread, "spinner", spinner_main, NULL, spinner_stack,
                    sizeof spinner_stack, K_PRIO_APP_MIN) != K_OK ||
        board_spawn(&bench_thread, "bench", bench_main, NULL, bench_stack, sizeof bench_stack,
                    K_PRIO_APP_MIN + 10u) != K_OK)
        k_printf("PDL-BENCH RESULT FAIL (threads)\n");
    k_start();
    return 0;
}
