/*
 * Host fast mode: the ecosystem program (apps/ecosystem/eco_program.c) and
 * the unchanged bsched.c, built as a shared library for the host and driven
 * from Python (emu/world/hostmode.py, ctypes) against the same world, with
 * no emulator. One call = one B-scheduler minor cycle, as on the board.
 */
#include <stdint.h>
#include <stddef.h>

#include "bsched.h"
#include "eco_program.h"

static struct bsched sched;
static struct eco_program prog;

static void run_process(void *context, uint16_t index)
{
    (void)context;
    eco_run(&prog, index);
}

/* Returns BSCHED_OK (0) or bsched_init's error. */
int32_t eco_host_init(uint32_t seed)
{
    eco_init(&prog, seed);
    return bsched_init(&sched, eco_pv, ECO_PROCS);
}

int32_t eco_host_procs(void)
{
    return ECO_PROCS;
}

const char *eco_host_name(uint32_t index)
{
    return index < ECO_PROCS ? eco_names[index] : NULL;
}

/*
 * One cycle. in: light_l, light_r, ir_l, ir_r, battery, comp_l, comp_r,
 * bump_l, bump_r, charging (flags 1 = active). out: motor_l, motor_r,
 * hunger, then speed and turn contribution of each process (2 * ECO_PROCS).
 * Returns the bit mask of the processes run in this cycle.
 */
uint32_t eco_host_cycle(const int32_t *in, int32_t *out)
{
    struct eco_inputs e = {
        .light_l = in[0], .light_r = in[1], .ir_l = in[2], .ir_r = in[3],
        .battery = in[4], .comp_l = in[5], .comp_r = in[6],
        .bump_l = in[7], .bump_r = in[8], .charging = in[9],
    };
    uint32_t mask = 0;
    unsigned i;

    eco_begin_cycle(&prog, &e);
    bsched_run_cycle(&sched, run_process, NULL);
    eco_end_cycle(&prog);
    for (i = 0; i < sched.ran_count; i++) {
        mask |= 1u << sched.ran[i];
    }
    out[0] = prog.motor_l;
    out[1] = prog.motor_r;
    out[2] = prog.hunger.value;
    for (i = 0; i < ECO_PROCS; i++) {
        out[3 + 2 * i] = prog.contrib[i][0];
        out[4 + 2 * i] = prog.contrib[i][1];
    }
    return mask;
}
