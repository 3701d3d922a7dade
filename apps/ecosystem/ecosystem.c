/*
 * The ecosystem robot's firmware: the behaviour processes of eco_program.c
 * run through the unchanged bsched.c on the nanokernel's B-scheduler thread,
 * one minor cycle every ECO_CYCLE_TICKS kernel ticks (64 Hz). Each cycle
 * reads every sensor before its first process (the quantities' values for
 * the cycle), runs the due processes, and after its last process commits
 * the quantities and writes the motors, as a PDL cycle does.
 *
 * Every ECO_STATUS_CYCLES cycles it prints one status line for the host's
 * live view (emu/world/cosim.py parses it):
 *   eco t=MS ml=L mr=R h=HUNGER ran=MASK ovr=N c=S/T,S/T,...
 * MASK: the processes run in this cycle (bit = process index); c: each
 * process's last contribution to speed/turn (permille).
 */
#include <stdint.h>

#include "bsched.h"
#include "kernel.h"
#include "k_board.h"
#include "k_bsched.h"
#include "drivers/led.h"
#include "eco_io.h"
#include "eco_program.h"

#define ECO_CYCLE_TICKS   2u     /* 128 Hz ticks: 64 Hz minor cycles */
/* A status line every 15 cycles (234 ms): 15 is odd, so the reported cycle
 * walks through every phase of the 16-cycle major cycle. */
#define ECO_STATUS_CYCLES 15u
#define ECO_SEED          0x1D2C3B4Au

static struct bsched sched;
static struct eco_program prog;
static struct k_bsched bsched_thread;
static uint32_t cycles;
static uint32_t io_errors_reported;
K_STACK_DEFINE(bsched_stack, 2048u);

static void print_status(void)
{
    uint32_t mask = 0;
    unsigned i;

    for (i = 0; i < sched.ran_count; i++) {
        mask |= 1ul << sched.ran[i];
    }
    k_printf("eco t=%lu ml=%ld mr=%ld h=%ld ran=%lx ovr=%lu c=", (unsigned long)k_uptime_ms(),
             (long)prog.motor_l, (long)prog.motor_r, (long)prog.hunger.value,
             (unsigned long)mask, (unsigned long)bsched_thread.overruns);
    for (i = 0; i < ECO_PROCS; i++) {
        k_printf("%ld/%ld%s", (long)prog.contrib[i][0], (long)prog.contrib[i][1],
                 i + 1u < ECO_PROCS ? "," : "\n");
    }
}

static void run_process(void *context, uint16_t index)
{
    const struct bsched *s = context;

    if (index == s->ran[0]) {
        struct eco_inputs in = prog.in;
        (void)eco_io_read(&in);
        eco_begin_cycle(&prog, &in);
    }
    eco_run(&prog, index);
    if (index == s->ran[s->ran_count - 1u]) {
        eco_end_cycle(&prog);
        eco_io_motors(prog.motor_l, prog.motor_r);
        cycles++;
        if (cycles % ECO_STATUS_CYCLES == 0u) {
            print_status();
            if (eco_io_errors() != io_errors_reported) {
                io_errors_reported = eco_io_errors();
                k_printf("eco: %lu I2C transfers failed so far\n",
                         (unsigned long)io_errors_reported);
            }
        }
    }
}

int main(void)
{
    int32_t rc;

    k_init();
    led_init();
    if (k_board_init() != 0) {
        static const char msg[] = "k_board_init failed: no PIT rate for K_TICK_HZ\n";
        k_console_write_sync(msg, sizeof msg - 1u);
        return 1;
    }
    k_printf("\nRoboCube firmware: the ecosystem robot (%u behaviour processes, %lu Hz cycles)\n",
             (unsigned)ECO_PROCS, (unsigned long)(K_TICK_HZ / ECO_CYCLE_TICKS));
    eco_io_init();
    eco_init(&prog, ECO_SEED);
    rc = bsched_init(&sched, eco_pv, ECO_PROCS);
    if (rc != BSCHED_OK) {
        k_printf("bsched_init failed: %ld\n", (long)rc);
        return 1;
    }
    if (k_bsched_start(&bsched_thread, &sched, run_process, &sched, ECO_CYCLE_TICKS,
                       bsched_stack, sizeof bsched_stack) != K_OK) {
        k_printf("k_bsched_start failed\n");
        return 1;
    }
    k_start();
    return 0;
}
