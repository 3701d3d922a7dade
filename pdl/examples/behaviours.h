/*
 * Example PDL behaviours for a two-wheeled robot (the ecosystem robot):
 * phototaxis, obstacle avoidance, wandering and a slow battery monitor that
 * makes the robot seek its (lit) charging station. They combine by
 * superposition: each process adds its influence to the same two motor
 * quantities with add_value; there is no arbiter.
 *
 * Wiring (the binding table behaviours_bindings[]; the eco arena and the
 * board use the same ports):
 *
 *   quantity        port            range      meaning
 *   light_left      analog in 0     0..255     light to the front left, 255 = brightest
 *   light_right     analog in 1     0..255     light to the front right
 *   ir_left         analog in 2     0..255     infrared reflection front left, 255 = touching
 *   ir_right        analog in 3     0..255     infrared reflection front right
 *   battery         analog in 4     0..255     battery level, 255 = full (BATTERY_LOW = 100)
 *   bumper_left     binary in 1     0/1        DUART IP1, 0 = pressed (a switch to
 *   bumper_right    binary in 2     0/1        DUART IP2   ground; the input is pulled up)
 *   motor_left      motor 0         -1000..1000 permille set-point, + = forward
 *   motor_right     motor 1         -1000..1000
 *   seeking_led     LED             0/1        on while the robot seeks the charger
 *
 * Own quantities: hunger (0..1000, the motivation to seek the charger),
 * wander_turn (-200..200, the current random turn bias).
 *
 * Processes (pv: runs every 2^pv cycles; at f0 = 100 Hz):
 *   cruise       pv 0   pulls both motors toward CRUISE_SPEED (a leak: the
 *                       motors settle where all influences balance)
 *   phototaxis   pv 0   turns toward the brighter side; gain grows with hunger
 *   avoid        pv 0   turns away from the nearer IR side, brakes when both
 *                       see an obstacle, backs up on a bumper
 *   wander       pv 3   every 8 cycles a new pseudo-random turn bias
 *   battery      pv 8   every 256 cycles (2.56 s): hunger up while the
 *                       battery is low, down while it is not; LED = hungry
 */
#ifndef PDL_BEHAVIOURS_H
#define PDL_BEHAVIOURS_H

#include "pdl/pdl.h"

#define CRUISE_SPEED 400        /* permille */
#define BATTERY_LOW 100         /* analog code below which the robot gets hungry */
#define HUNGER_STEP 100         /* per battery-monitor run */
#define HUNGRY 500              /* hunger above which the LED shows it seeks */

extern struct pdl_sensor light_left, light_right, ir_left, ir_right, battery;
extern struct pdl_sensor bumper_left, bumper_right;
extern struct pdl_quantity motor_left, motor_right, seeking_led, hunger, wander_turn;

/* Which behaviours behaviours_setup installs. */
#define BEH_CRUISE     0x01u
#define BEH_PHOTOTAXIS 0x02u
#define BEH_AVOID      0x04u
#define BEH_WANDER     0x08u
#define BEH_BATTERY    0x10u
#define BEH_ALL        0x1Fu

/* Declares every quantity above, binds them to their ports (the wiring
 * table) when bind is non-zero, and adds the chosen processes. Call before
 * run_pdl(). PDL_OK or the first error. */
int behaviours_setup(unsigned which, int bind);

#endif /* PDL_BEHAVIOURS_H */
