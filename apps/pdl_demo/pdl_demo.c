/*
 * PDL demo image: the ecosystem robot's behaviours (pdl/examples/) run by
 * the PDL runtime at f0 = 100 Hz on the nanokernel. The sensors come from
 * the I/O board through the sampler, the motors are driven open loop; the
 * host sets the inputs and reads the motors over QMP (pdl/tests/target/).
 *
 * Console: "PDL-DEMO running f0_mhz=..." once, then every half second
 * "PDL-DEMO t_ms=... light=L,R ir=L,R battery=B bumpers=L,R motors=L,R
 *  hunger=H led=X cycles=C overruns=O misuse=M driver_errors=D stack=S"
 * (S: bytes of the cycle thread's stack used so far).
 */
#include <stdint.h>

#include "kernel.h"
#include "drivers/board.h"
#include "pdl/examples/behaviours.h"
#include "pdl/pdl.h"
#include "pdl/pdl_board.h"

#define DEMO_HZ 100u
#define DEMO_REPORT_TICKS (K_TICK_HZ / 2u)

static struct k_thread demo_thread;
K_STACK_DEFINE(demo_stack, 2048u);

static void *demo_main(void *arg)
{
    struct pdl_stats st;
    k_ticks_t next;
    int r;
    (void)arg;
    r = behaviours_setup(BEH_ALL, 1);
    if (r == PDL_OK)
        r = pdl_set_frequency(DEMO_HZ);
    if (r == PDL_OK)
        r = run_pdl();
    if (r != PDL_OK) {
        k_printf("PDL-DEMO failed: %s (%d)\n", pdl_strerror(r), r);
        return NULL;
    }
    k_printf("PDL-DEMO running f0_mhz=%lu period_us=%lu\n", (unsigned long)pdl_frequency_mhz(),
             (unsigned long)pdl_period_us());
    next = k_ticks();
    for (;;) {
        next += DEMO_REPORT_TICKS;
        (void)k_sleep_until(next);
        pdl_get_stats(&st);
        k_printf("PDL-DEMO t_ms=%lu light=%ld,%ld ir=%ld,%ld battery=%ld bumpers=%ld,%ld "
                 "motors=%ld,%ld hunger=%ld led=%ld cycles=%lu overruns=%lu misuse=%lu "
                 "driver_errors=%lu stack=%lu\n",
                 (unsigned long)k_uptime_ms(), (long)value(light_left), (long)value(light_right),
                 (long)value(ir_left), (long)value(ir_right), (long)value(battery),
                 (long)value(bumper_left), (long)value(bumper_right), (long)value(motor_left),
                 (long)value(motor_right), (long)value(hunger), (long)value(seeking_led),
                 (unsigned long)st.cycles, (unsigned long)st.overruns,
                 (unsigned long)st.misuse, (unsigned long)st.driver_errors,
                 (unsigned long)pdl_stack_used());
    }
    return NULL;
}

int main(void)
{
    board_start("pdl_demo");
    k_printf("\nPDL demo: phototaxis, avoidance, wandering, battery motivation\n");
    if (board_spawn(&demo_thread, "pdl-demo", demo_main, NULL, demo_stack, sizeof demo_stack,
                    K_PRIO_APP_MIN + 1u) != K_OK)
        k_printf("PDL-DEMO failed: thread\n");
    k_start();
    return 0;
}
