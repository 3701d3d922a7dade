/*
 * Board platform of the PDL runtime: run_pdl() starts the cycle thread on
 * the nanokernel (the kernel's B-scheduler thread, kernel/k_bsched.c, with
 * PDL's work before and after each minor cycle). The ports are the board's,
 * reached as the board's make file says: through the drivers
 * (pdl/ports/drivers.c) or through the board's own port access
 * (pdl/ports/board.c).
 *
 * The kernel thread runs a one-process B-schedule (pv 0: every minor cycle)
 * whose process is the whole PDL cycle; the PDL processes' own schedule is
 * pdl_core's (bsched.c's plan of the PDL set).
 *
 * A cycle: read the sensors (pdl_platform_read_inputs), run the due
 * processes, commit, write the changed actuators. The cycle period is a
 * whole number of kernel ticks (f0 = K_TICK_HZ / period; 1 tick = 1024 Hz at
 * the default tick). Overruns are
 * counted by the kernel thread and reported on the console by its reporter
 * thread; pdl_get_stats() returns them.
 *
 * run_pdl() brings up the ports the bindings use (pdl_platform_start_ports).
 */
#include "pdl/pdl_internal.h"

#include "bsched.h"
#include "kernel.h"
#include "k_bsched.h"
#include "pdl/pdl_board.h"

#ifndef PDL_STACK_BYTES
#define PDL_STACK_BYTES 2048u
#endif

static struct k_bsched pdl_thread;
K_STACK_DEFINE(pdl_stack, PDL_STACK_BYTES);
static k_ticks_t pdl_period_ticks = (K_TICK_HZ + PDL_DEFAULT_HZ / 2u) / PDL_DEFAULT_HZ;
static int pdl_thread_started;

void pdl_platform_report(int code, const char *what)
{
    if (code == PDL_ERR_DRIVER)
        k_printf("pdl: %s: %s (driver code %d)\n", what, pdl_strerror(code),
                 pdl_stats.last_driver_code);
    else
        k_printf("pdl: %s: %s (%d)\n", what, pdl_strerror(code), code);
}

int pdl_running(void) { return pdl_core_started(); }

static uint32_t pdl_ticks_to_us(k_ticks_t t)
{
    return (t / K_TICK_HZ) * 1000000u + (t % K_TICK_HZ) * 1000000u / K_TICK_HZ;
}

/* ---- the cycle thread ---- */
static struct bsched pdl_outer;
static const uint8_t pdl_outer_pv[1] = {0};

/* The one process of the kernel thread's schedule: a whole PDL cycle. */
static void pdl_board_cycle(void *context, uint16_t index)
{
    (void)context;
    (void)index;
    pdl_cycle_begin(pdl_ticks_to_us(k_ticks()));
    (void)pdl_cycle_run();
    pdl_cycle_end();
}

int pdl_set_frequency(uint32_t hz)
{
    uint32_t ticks;
    if (pdl_core_started())
        return pdl_refuse(PDL_ERR_RUNNING, "pdl_set_frequency");
    if (hz == 0u || hz > K_TICK_HZ)
        return pdl_refuse(PDL_ERR_FREQUENCY, "pdl_set_frequency (1 .. kernel tick rate)");
    ticks = (K_TICK_HZ + hz / 2u) / hz;
    pdl_period_ticks = ticks;
    pdl_core_period_us = pdl_ticks_to_us(ticks);
    return PDL_OK;
}

uint32_t pdl_frequency_mhz(void)
{
    return K_TICK_HZ * 1000u / pdl_period_ticks;
}

int run_pdl(void)
{
    int r;
    if (pdl_thread_started)
        return pdl_refuse(PDL_ERR_RUNNING, "run_pdl");
    pdl_core_period_us = pdl_ticks_to_us(pdl_period_ticks);
    r = pdl_core_start();
    if (r != PDL_OK)
        return r;
    pdl_thread.stop_after = 0;
    /* Start at the beginning of a tick: creating the thread fills its stack
     * (a few thousand instructions), and k_bsched_start releases the first
     * cycle at the next tick, which must not already be past. */
    if (!k_in_isr())
        (void)k_sleep_ticks(1);
    r = (int)bsched_init(&pdl_outer, pdl_outer_pv, 1);
    if (r == BSCHED_OK)
        r = k_bsched_start(&pdl_thread, &pdl_outer, pdl_board_cycle, NULL,
                           pdl_period_ticks, pdl_stack, sizeof pdl_stack);
    if (r != K_OK) {
        pdl_core_set_started(0);
        return pdl_refuse(PDL_ERR_KERNEL, "run_pdl (k_bsched_start)");
    }
    pdl_thread_started = 1;
    return PDL_OK;
}

int pdl_stop(uint32_t timeout_ms)
{
    int r;
    if (!pdl_thread_started)
        return pdl_refuse(PDL_ERR_NOT_RUNNING, "pdl_stop");
    pdl_thread.stop = 1;
    r = k_thread_join(&pdl_thread.thread, NULL, k_ms_to_ticks(timeout_ms));
    if (r != K_OK)
        return pdl_refuse(PDL_ERR_KERNEL, "pdl_stop (the cycle thread did not end in time)");
    pdl_thread_started = 0;
    pdl_core_set_started(0);
    return PDL_OK;
}

int pdl_reset(void)
{
    if (pdl_thread_started)
        return pdl_refuse(PDL_ERR_RUNNING, "pdl_reset");
    pdl_core_reset();
    pdl_period_ticks = (K_TICK_HZ + PDL_DEFAULT_HZ / 2u) / PDL_DEFAULT_HZ;
    return PDL_OK;
}

void pdl_platform_stats(struct pdl_stats *out)
{
    out->overruns = pdl_thread.overruns;
    out->overrun_events = pdl_thread.overrun_events;
    out->max_cycle_ticks = pdl_thread.max_cycle_ticks;
}

uint32_t pdl_stack_used(void)
{
    unsigned i, n = sizeof pdl_stack / sizeof pdl_stack[0];
    /* k_thread_create fills the whole stack with K_STACK_GUARD: the first
     * word that differs is the deepest the thread has been */
    for (i = K_STACK_GUARD_WORDS; i < n && pdl_stack[i] == K_STACK_GUARD; i++)
        ;
    return (n - i) * 4u;
}

uint32_t pdl_stack_size(void) { return sizeof pdl_stack; }

struct k_thread *pdl_cycle_thread(void) { return &pdl_thread.thread; }

int pdl_sleep_ms(uint32_t ms)
{
    return k_sleep_ticks(k_ms_to_ticks(ms)) == K_OK ? PDL_OK : PDL_ERR_KERNEL;
}

uint32_t pdl_uptime_ms(void) { return k_uptime_ms(); }
