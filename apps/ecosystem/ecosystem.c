/*
 * The ecosystem robot's firmware: the PDL program of eco_program.c on the
 * PDL runtime (pdl/): its cycle thread runs the processes through the
 * unchanged bsched.c at 64 Hz (two ticks of the 128 Hz kernel clock),
 * sensors from the drivers' sampler snapshot, motors through the motor
 * driver (open loop).
 *
 * A report thread prints one status line every ECO_STATUS_MS for the host's
 * live view (emu/world/cosim.py parses it):
 *   eco t=MS ml=L mr=R h=HUNGER ran=MASK ovr=N c=S/T,S/T,...
 * MASK: the processes run in the last completed cycle (bit = process id);
 * c: each process's last contribution to speed/turn (permille).
 */
#include <stdint.h>

#include "kernel.h"
#include "boards/include/board.h"
#include "eco_program.h"
#include "pdl/pdl.h"

#define ECO_HZ        64u
#define ECO_STATUS_MS 250u
#define ECO_SEED      0x1D2C3B4Au

static struct k_thread eco_thread;
K_STACK_DEFINE(eco_stack, 2048u);

static void print_status(void)
{
    struct pdl_stats st;
    unsigned i;

    pdl_get_stats(&st);
    k_printf("eco t=%lu ml=%ld mr=%ld h=%ld ran=%lx ovr=%lu c=", (unsigned long)k_uptime_ms(),
             (long)value(motor_l), (long)value(motor_r), (long)value(hunger),
             (unsigned long)eco_ran_mask(st.cycles ? st.cycles - 1u : 0u),
             (unsigned long)st.overruns);
    for (i = 0; i < ECO_PROCS; i++) {
        k_printf("%ld/%ld%s", (long)eco_contrib[i][0], (long)eco_contrib[i][1],
                 i + 1u < ECO_PROCS ? "," : "\n");
    }
}

static void *eco_main(void *arg)
{
    k_ticks_t next;
    int r;
    (void)arg;

    r = eco_setup(ECO_SEED, 1);
    if (r == PDL_OK) {
        r = pdl_set_frequency(ECO_HZ);
    }
    if (r == PDL_OK) {
        r = run_pdl();
    }
    if (r != PDL_OK) {
        k_printf("eco: PDL refused the program: %s (%d)\n", pdl_strerror(r), r);
        return NULL;
    }
    k_printf("eco: %u behaviour processes at %lu mHz\n", (unsigned)ECO_PROCS,
             (unsigned long)pdl_frequency_mhz());
    next = k_ticks();
    for (;;) {
        next += k_ms_to_ticks(ECO_STATUS_MS);
        (void)k_sleep_until(next);
        print_status();
    }
    return NULL;
}

int main(void)
{
    board_start("ecosystem");
    k_printf("\nRoboCube firmware: the ecosystem robot (PDL, %u processes)\n",
             (unsigned)ECO_PROCS);
    (void)board_spawn(&eco_thread, "eco", eco_main, NULL, eco_stack, sizeof eco_stack,
                      K_PRIO_APP_MIN + 1u);
    k_start();
    return 0;
}
