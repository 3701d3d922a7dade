/*
 * The ecosystem robot's behaviour program, a PDL program (pdl/pdl.h, paper
 * section 5): quantities with a value (the previous cycle's, the same for
 * every process) and the sum of what processes add (committed and clipped
 * at the end of the cycle); argumentless processes that only read values
 * and add. The behaviours combine by superposition, with no arbiter.
 *
 * The same file runs on the emulated board (apps/ecosystem/ecosystem.c: the
 * PDL runtime's cycle thread, the drivers' sampler and motor driver) and on
 * the host (apps/ecosystem/host/eco_host.c: the PDL host runtime), against the
 * same world.
 *
 * Wiring (the arena robot's, pdl/robot.h):
 *   light_l/r  analog in 0/1   station light, left/right (+-40 deg)
 *   ir_l/r     analog in 2/3   infrared distance, larger = nearer
 *   battery    analog in 4     battery voltage, 10 V full scale
 *   comp_l/r   analog in 5/6   competitor lamps
 *   bump_l/r   binary in 1/2   bumpers, 0 = pressed
 *   charger    binary in 3     charger contact, 0 = charging
 *   motor_l/r  motor 0/1       wheel set-points, permille, + = forward
 */
#ifndef ECO_PROGRAM_H
#define ECO_PROGRAM_H

#include <stdint.h>

#include "pdl/pdl.h"

enum eco_process {
    ECO_BUMP,      /* bumper reflex: back off and turn away */
    ECO_AVOID,     /* infrared obstacle avoidance */
    ECO_CRUISE,    /* relax speed toward cruising speed, turn toward straight */
    ECO_PHOTO,     /* phototaxis toward the charging station's light, when hungry */
    ECO_DOCK,      /* stop in the station while charging, when hungry */
    ECO_WANDER,    /* random turns */
    ECO_COMPETE,   /* seek competitor lamps when fed (the ecosystem's work) */
    ECO_BATTERY,   /* battery monitor: sets the hunger motivation */
    ECO_MOTORS,    /* speed and turn to the two wheel set-points */
    ECO_PROCS
};

extern struct pdl_sensor light_l, light_r, ir_l, ir_r, battery, comp_l, comp_r;
extern struct pdl_sensor bump_l, bump_r, charger;
extern struct pdl_quantity speed, turn, hunger, motor_l, motor_r;

extern const uint8_t eco_pv[ECO_PROCS];
extern const char *const eco_names[ECO_PROCS];

/* What the live view shows: each process's last contribution to speed and
 * turn, and the PDL cycle in which it last ran. */
extern int32_t eco_contrib[ECO_PROCS][2];
extern uint32_t eco_last_cycle[ECO_PROCS];

/* Declares the quantities, binds them to the ports above (bind != 0) and
 * adds the processes, in enum order (process id = enum value). Before
 * run_pdl(). PDL_OK or the first error. */
int eco_setup(uint32_t seed, int bind);

/* Bit mask of the processes that ran in PDL cycle `cycle` (0-based). */
uint32_t eco_ran_mask(uint32_t cycle);

#endif
