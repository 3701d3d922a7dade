/*
 * The arena robot's wiring: which port of the board each sensor and wheel of
 * the robot in the ecosystem arena is connected to (emu/world/README.md
 * "Sensors"; the "wiring" of emu/world/arenas/default.json, checked against
 * this file by the eco suite). The ecosystem robot (apps/ecosystem) and the
 * example behaviours (pdl/examples) use it; a program binds to a name:
 *
 *     pdl_bind_sensor(&light, ROBOT_LIGHT_LEFT);
 *     pdl_bind_actuator(&left_wheel, ROBOT_MOTOR_LEFT);
 *
 * Each name is a port and an index (two arguments of pdl_bind_sensor or
 * pdl_bind_actuator, or the last two fields of a struct pdl_binding).
 */
#ifndef PDL_ROBOT_H
#define PDL_ROBOT_H

#include "pdl/pdl.h"

/* Sensors (bind with pdl_bind_sensor). */
#define ROBOT_LIGHT_LEFT   PDL_ANALOG_IN, 0  /* station light, 40 deg left: 8 (dark) .. ~208 */
#define ROBOT_LIGHT_RIGHT  PDL_ANALOG_IN, 1  /* station light, 40 deg right */
#define ROBOT_IR_LEFT      PDL_ANALOG_IN, 2  /* infrared distance, 30 deg left: 12 (nothing within 0.8 m) .. 255 (touching) */
#define ROBOT_IR_RIGHT     PDL_ANALOG_IN, 3  /* infrared distance, 30 deg right */
#define ROBOT_BATTERY      PDL_ANALOG_IN, 4  /* battery voltage, 10 V full scale: 153 (empty, 6.0 V) .. 214 (full, 8.4 V) */
#define ROBOT_COMP_LEFT    PDL_ANALOG_IN, 5  /* competitor lamps, 40 deg left */
#define ROBOT_COMP_RIGHT   PDL_ANALOG_IN, 6  /* competitor lamps, 40 deg right */
#define ROBOT_BUMPER_LEFT  PDL_BINARY_IN, 1  /* 0 = pressed */
#define ROBOT_BUMPER_RIGHT PDL_BINARY_IN, 2  /* 0 = pressed */
#define ROBOT_CHARGING     PDL_BINARY_IN, 3  /* 0 = on the charging pad */

/* Actuators (bind with pdl_bind_actuator): wheel set-points, permille
 * -1000..1000, + = forward; 1000 is 0.31 m/s. */
#define ROBOT_MOTOR_LEFT   PDL_MOTOR, 0
#define ROBOT_MOTOR_RIGHT  PDL_MOTOR, 1

#endif /* PDL_ROBOT_H */
