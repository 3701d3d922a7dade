/*
 * A PDL program as the paper writes one (Birk, Kenn, Steels 2002, section 5):
 * main declares the quantities, binds them to the robot's ports, adds the
 * behaviour processes and calls run_pdl(), which starts the B-scheduler's
 * cycle thread; the board, kernel and console were started before main.
 * `make new-app NAME=x` copies this file to apps/x as the start of your own.
 *
 *   make run APP=x                   on the emulated board
 *   make run APP=x WORLD=default     on the board, driving the arena's robot
 *   make run APP=x HOST=1            on the host runtime, in the same arena
 *
 * Two behaviours superpose on the two wheels: cruise pulls both toward a
 * cruising speed, avoid (every second cycle) turns away from the nearer
 * obstacle the infrared sensors see. Every refused call is reported on the
 * console. main reports once a second: the wheels and each process's runs.
 */
#include <stdio.h>

#include "pdl/pdl.h"
#include "pdl/robot.h"

static struct pdl_sensor ir_left, ir_right;
static struct pdl_quantity left, right;

static void cruise(void)
{
    add_value(left, (400 - value(left)) / 8);
    add_value(right, (400 - value(right)) / 8);
}

static void avoid(void)
{
    int32_t nearer_left = value(ir_left) - value(ir_right);
    add_value(left, 4 * nearer_left);
    add_value(right, -4 * nearer_left);
}

int main(void)
{
    int r, second, i;

    add_sensor(&ir_left, 0, 255);
    add_sensor(&ir_right, 0, 255);
    add_quantity(&left, -1000, 1000, 0);
    add_quantity(&right, -1000, 1000, 0);
    pdl_bind_sensor(&ir_left, ROBOT_IR_LEFT);
    pdl_bind_sensor(&ir_right, ROBOT_IR_RIGHT);
    pdl_bind_actuator(&left, ROBOT_MOTOR_LEFT);
    pdl_bind_actuator(&right, ROBOT_MOTOR_RIGHT);
    add_process(cruise);
    add_process_pv(avoid, 1);
    r = run_pdl();
    if (r < 0) {
        printf("run_pdl: %s (%d)\n", pdl_strerror(r), r);
        return 1;
    }
    for (second = 1;; second++) {
        pdl_sleep_ms(1000);
        printf("t=%d s wheels=%ld,%ld runs:", second, (long)value(left), (long)value(right));
        for (i = 0; i < pdl_process_count(); i++)
            printf(" %s=%lu", pdl_process_name(i), (unsigned long)pdl_process_runs(i));
        printf("\n");
    }
}
