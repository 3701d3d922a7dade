/*
 * The ecosystem robot's behaviour program, written in the style of PDL
 * (paper section 5): quantities with a current value (read by every process
 * of a cycle) and a next value (the sum of what the processes add), and
 * argumentless processes that only read values and add to quantities. The
 * behaviours combine by superposition, with no arbiter.
 *
 * Host-portable C99 (no kernel, no drivers): the firmware (ecosystem.c) runs
 * the processes from the kernel's B-scheduler thread, and the host fast mode
 * (emu/world/host/eco_host.c) runs the very same file through the same
 * bsched.c on the host. Interim: when the pdl runtime lands, these become
 * PDL processes (add_process_pv, value, add_value) unchanged in substance.
 */
#ifndef ECO_PROGRAM_H
#define ECO_PROGRAM_H

#include <stdint.h>

enum eco_process {
    ECO_BUMP,      /* bumper reflex: back off and turn away */
    ECO_AVOID,     /* infrared obstacle avoidance */
    ECO_CRUISE,    /* relax speed toward cruising speed, turn toward straight */
    ECO_PHOTO,     /* phototaxis toward the charging station's light, when hungry */
    ECO_DOCK,      /* stop in the station while charging, when hungry */
    ECO_WANDER,    /* random turns */
    ECO_COMPETE,   /* seek competitor lamps when fed (the ecosystem's work) */
    ECO_BATTERY,   /* battery monitor: sets the hunger motivation */
    ECO_PROCS
};

/* Sensor values of one cycle (analog codes 0..255; flags 1 = active). */
struct eco_inputs {
    int32_t light_l, light_r;   /* station light */
    int32_t ir_l, ir_r;         /* infrared distance: larger = nearer */
    int32_t battery;            /* battery voltage code (10 V full scale) */
    int32_t comp_l, comp_r;     /* competitor lamp light */
    int32_t bump_l, bump_r, charging;
};

/* A PDL-style quantity: value (this cycle) and the sum of contributions. */
struct eco_quantity {
    int32_t value, next, min, max;
};

struct eco_program {
    struct eco_inputs in;
    struct eco_quantity speed;   /* forward, permille of full duty */
    struct eco_quantity turn;    /* counter-clockwise, permille */
    struct eco_quantity hunger;  /* 0 fed .. 1000 hungry */
    int32_t motor_l, motor_r;    /* committed motor set-points, permille */
    /* What each process added in its last run: speed, turn. */
    int32_t contrib[ECO_PROCS][2];
    uint32_t runs[ECO_PROCS];
    /* Process-private state. */
    int32_t escape_cycles, escape_turn;
    int32_t avoid_dir;           /* -1 right, +1 left, 0 nothing in view */
    int32_t battery_avg;         /* x16 */
    uint32_t rng;
};

extern const uint8_t eco_pv[ECO_PROCS];
extern const char *const eco_names[ECO_PROCS];

void eco_init(struct eco_program *p, uint32_t seed);
/* Start of a cycle: the sensor quantities take their new values. */
void eco_begin_cycle(struct eco_program *p, const struct eco_inputs *in);
/* Runs process `index` (an enum eco_process). */
void eco_run(struct eco_program *p, unsigned index);
/* End of a cycle: every quantity takes value + sum of contributions,
 * clipped to its bounds; motor set-points from speed and turn. */
void eco_end_cycle(struct eco_program *p);

#endif
