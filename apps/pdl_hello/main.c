/*
 * A PDL program as the paper writes one (Birk, Kenn, Steels 2002, section 5):
 * main declares the quantities, adds the behaviour processes and calls
 * run_pdl(), which starts the B-scheduler's cycle thread; the board, kernel
 * and console were started before main. `make new-app NAME=x` copies this
 * folder to apps/x as the start of a program of your own.
 *
 * Two behaviours superpose on one quantity: wander pushes the heading up every
 * cycle, settle pulls it back towards 0 every fourth cycle (pv 2); the heading
 * settles where the two balance. main reports once a second for three seconds.
 */
#include <stdio.h>

#include "kernel.h"
#include "pdl/pdl.h"

static struct pdl_quantity heading;

static void wander(void)
{
    add_value(heading, 40);
}

static void settle(void)
{
    add_value(heading, -value(heading) / 2);
}

int main(void)
{
    struct pdl_stats st;
    int r, second;

    r = add_quantity(&heading, -1000, 1000, 0);
    if (r >= 0)
        r = add_process(wander);
    if (r >= 0)
        r = add_process_pv(settle, 2);
    if (r >= 0)
        r = run_pdl();
    if (r < 0) {
        printf("run_pdl: %s (%d)\n", pdl_strerror(r), r);
        return 1;
    }
    for (second = 1; second <= 3; second++) {
        (void)k_sleep_ticks(K_TICK_HZ);
        pdl_get_stats(&st);
        printf("t=%d s heading=%ld cycles=%lu runs=%lu overruns=%lu\n", second,
               (long)value(heading), (unsigned long)st.cycles, (unsigned long)st.process_runs,
               (unsigned long)st.overruns);
    }
    return 0;
}
