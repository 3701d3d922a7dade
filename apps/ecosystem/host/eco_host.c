/*
 * Host fast mode: the ecosystem PDL program (apps/ecosystem/eco_program.c)
 * on the PDL host runtime (pdl/host/, the same pdl_core.c and bsched.c as on
 * the board), built as a shared library and driven from Python
 * (emu/world/hostmode.py, ctypes) against the same world, with no emulator.
 * One call = one PDL cycle.
 */
#include <stdint.h>
#include <stddef.h>

#include "eco_program.h"
#include "pdl/host/pdl_host.h"

#define ECO_HZ 64u

/* PDL_OK (0) or the runtime's error. */
int32_t eco_host_init(uint32_t seed)
{
    int r = pdl_reset();
    if (r == PDL_OK) {
        r = eco_setup(seed, 1);
    }
    if (r == PDL_OK) {
        r = pdl_set_frequency(ECO_HZ);
    }
    if (r == PDL_OK) {
        r = run_pdl();
    }
    return r;
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
 * One cycle. in: light_l, light_r, ir_l, ir_r, battery, comp_l, comp_r
 * (analog inputs 0..6), bump_l, bump_r, charging (flags 1 = active: the
 * binary inputs read 0). out: motor_l, motor_r (what the motor ports were
 * given), hunger, then speed and turn contribution of each process.
 * Returns the bit mask of the processes run in this cycle, or 0xFFFFFFFF
 * if the runtime refused to run it.
 */
uint32_t eco_host_cycle(const int32_t *in, int32_t *out)
{
    struct pdl_stats st;
    unsigned i;

    for (i = 0; i < 7u; i++) {
        pdl_host_set_input(PDL_ANALOG_IN, i, in[i]);
    }
    for (i = 0; i < 3u; i++) {
        pdl_host_set_input(PDL_BINARY_IN, 1u + i, in[7u + i] ? 0 : 1);
    }
    if (pdl_run_cycles(1) != 1) {
        return 0xFFFFFFFFu;
    }
    pdl_get_stats(&st);
    out[0] = pdl_host_output(PDL_MOTOR, 0);
    out[1] = pdl_host_output(PDL_MOTOR, 1);
    out[2] = value(hunger);
    for (i = 0; i < ECO_PROCS; i++) {
        out[3 + 2 * i] = eco_contrib[i][0];
        out[4 + 2 * i] = eco_contrib[i][1];
    }
    return eco_ran_mask(st.cycles - 1u);
}
