/*
 * PDL demo image: the ecosystem robot's behaviours (pdl/examples/) run by
 * the PDL runtime at f0 = 100 Hz, as an ordinary main (the board was started
 * before it). `make run APP=pdl_demo` puts the robot in the ecosystem arena
 * (its sensors fed and its wheels taken by the world, pdl/robot.h); with
 * WORLD=none the board runs alone and the host sets the inputs over QMP
 * (pdl/tests/target/). The same file runs on the host (HOST=1).
 *
 * Console: "PDL-DEMO running f0_mhz=..." once, then every half second
 * "PDL-DEMO t_ms=... light=L,R ir=L,R battery=B bumpers=L,R motors=L,R
 *  hunger=H led=X cycles=C overruns=O misuse=M driver_errors=D stack=S"
 * (S: bytes of the cycle thread's stack used so far; on the board only).
 */
#include <stdint.h>
#include <stdio.h>

#include "pdl/examples/behaviours.h"
#include "pdl/pdl.h"
#ifndef PDL_HOST
#include "pdl/pdl_board.h"
#endif

#define DEMO_HZ 100u
#define DEMO_REPORT_MS 500u

int main(void)
{
    struct pdl_stats st;
    int r;

    printf("\nPDL demo: phototaxis, avoidance, wandering, battery motivation\n");
    r = behaviours_setup(BEH_ALL, 1);
    if (r == PDL_OK)
        r = pdl_set_frequency(DEMO_HZ);
    if (r == PDL_OK)
        r = run_pdl();
    if (r != PDL_OK) {
        printf("PDL-DEMO failed: %s (%d)\n", pdl_strerror(r), r);
        return 1;
    }
    printf("PDL-DEMO running f0_mhz=%lu period_us=%lu\n", (unsigned long)pdl_frequency_mhz(),
           (unsigned long)pdl_period_us());
    for (;;) {
        (void)pdl_sleep_ms(DEMO_REPORT_MS);
        pdl_get_stats(&st);
        printf("PDL-DEMO t_ms=%lu light=%ld,%ld ir=%ld,%ld battery=%ld bumpers=%ld,%ld "
               "motors=%ld,%ld hunger=%ld led=%ld cycles=%lu overruns=%lu misuse=%lu "
               "driver_errors=%lu",
               (unsigned long)pdl_uptime_ms(), (long)value(light_left), (long)value(light_right),
               (long)value(ir_left), (long)value(ir_right), (long)value(battery),
               (long)value(bumper_left), (long)value(bumper_right), (long)value(motor_left),
               (long)value(motor_right), (long)value(hunger), (long)value(seeking_led),
               (unsigned long)st.cycles, (unsigned long)st.overruns,
               (unsigned long)st.misuse, (unsigned long)st.driver_errors);
#ifndef PDL_HOST
        printf(" stack=%lu", (unsigned long)pdl_stack_used());
#endif
        printf("\n");
    }
}
