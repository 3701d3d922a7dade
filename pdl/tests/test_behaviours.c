/* Host tests of the example behaviours (pdl/examples/behaviours.c) through
 * the binding table: the test sets the board's inputs, the runtime runs
 * cycles, the test reads the motor outputs. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "pdl/examples/behaviours.h"
#include "pdl/host/pdl_host.h"

static int start(unsigned which)
{
    int r;
    pdl_reset();
    r = behaviours_setup(which, 1);
    if (r == PDL_OK)
        r = run_pdl();
    return r;
}

static void inputs(int ll, int lr, int il, int ir, int bat)
{
    pdl_host_set_input(PDL_ANALOG_IN, 0, ll);
    pdl_host_set_input(PDL_ANALOG_IN, 1, lr);
    pdl_host_set_input(PDL_ANALOG_IN, 2, il);
    pdl_host_set_input(PDL_ANALOG_IN, 3, ir);
    pdl_host_set_input(PDL_ANALOG_IN, 4, bat);
}

static int32_t left(void) { return pdl_host_output(PDL_MOTOR, 0); }
static int32_t right(void) { return pdl_host_output(PDL_MOTOR, 1); }

static void test_cruise_settles_at_cruising_speed(void **state)
{
    (void)state;
    assert_int_equal(start(BEH_CRUISE), PDL_OK);
    inputs(0, 0, 0, 0, 255);
    pdl_run_cycles(200);
    /* integer leak of 1/8 stops within 7 of the target */
    assert_in_range(left(), CRUISE_SPEED - 7, CRUISE_SPEED);
    assert_int_equal(left(), right());
}

static void test_phototaxis_turns_toward_the_light(void **state)
{
    (void)state;
    assert_int_equal(start(BEH_CRUISE | BEH_PHOTOTAXIS), PDL_OK);
    inputs(200, 50, 0, 0, 255);                 /* light on the left */
    pdl_run_cycles(100);
    assert_true(right() > left() + 200);        /* turning left */
    inputs(50, 200, 0, 0, 255);                 /* now on the right */
    pdl_run_cycles(100);
    assert_true(left() > right() + 200);
    inputs(120, 120, 0, 0, 255);                /* straight ahead: no turn */
    pdl_run_cycles(100);
    /* both settle at the cruising speed, each within the integer leak's 7 */
    assert_in_range(left(), CRUISE_SPEED - 7, CRUISE_SPEED + 7);
    assert_in_range(right(), CRUISE_SPEED - 7, CRUISE_SPEED + 7);
}

static void test_avoidance_turns_away_and_backs_up(void **state)
{
    (void)state;
    assert_int_equal(start(BEH_CRUISE | BEH_AVOID), PDL_OK);
    inputs(0, 0, 200, 20, 255);                 /* obstacle on the left */
    pdl_run_cycles(100);
    assert_true(left() > right() + 300);        /* turning right */
    inputs(0, 0, 20, 200, 255);
    pdl_run_cycles(100);
    assert_true(right() > left() + 300);
    inputs(0, 0, 200, 200, 255);                /* wall ahead: brake hard */
    pdl_run_cycles(100);
    assert_true(left() < 0 && right() < 0);
    inputs(0, 0, 0, 0, 255);
    pdl_host_set_input(PDL_BINARY_IN, 2, 0);    /* right bumper pressed (pulled low) */
    pdl_run_cycles(100);
    assert_true(left() < 0 && right() < 0);     /* backing up */
    pdl_host_set_input(PDL_BINARY_IN, 2, 1);
    pdl_run_cycles(100);
    assert_true(left() > 300 && right() > 300); /* free again: cruising */
}

static void test_wander_varies_the_heading_within_bounds(void **state)
{
    int32_t min_diff = 0, max_diff = 0;
    unsigned i, changes = 0;
    int32_t last = 0;
    (void)state;
    assert_int_equal(start(BEH_CRUISE | BEH_WANDER), PDL_OK);
    inputs(0, 0, 0, 0, 255);
    for (i = 0; i < 400; i++) {
        int32_t d;
        pdl_run_cycles(1);
        d = left() - right();
        min_diff = d < min_diff ? d : min_diff;
        max_diff = d > max_diff ? d : max_diff;
        changes += value(wander_turn) != last;
        last = value(wander_turn);
    }
    assert_true(min_diff < -50 && max_diff > 50);   /* turns both ways */
    assert_in_range(changes, 30, 50);               /* a new bias every 8 cycles only */
    assert_true(value(wander_turn) >= -200 && value(wander_turn) <= 200);
}

static void test_battery_monitor_makes_the_robot_seek_the_charger(void **state)
{
    int32_t sated_turn, hungry_turn;
    (void)state;
    assert_int_equal(start(BEH_CRUISE | BEH_PHOTOTAXIS | BEH_BATTERY), PDL_OK);
    inputs(180, 80, 0, 0, 255);                 /* charger light on the left, battery full */
    pdl_run_cycles(512);
    sated_turn = right() - left();
    assert_int_equal(value(hunger), 0);
    assert_int_equal(pdl_host_output(PDL_LED, 0), 0);
    inputs(180, 80, 0, 0, 60);                  /* battery low */
    pdl_run_cycles(255);                        /* the monitor (pv 8) runs once in 256 */
    assert_true(value(hunger) <= HUNGER_STEP);
    pdl_run_cycles(256 * 10);
    assert_int_equal(value(hunger), 1000);
    assert_int_equal(pdl_host_output(PDL_LED, 0), 1);
    hungry_turn = right() - left();
    assert_true(hungry_turn > 2 * sated_turn);  /* stronger phototaxis when hungry */
    inputs(180, 80, 0, 0, 250);                 /* charged */
    pdl_run_cycles(256 * 12);
    assert_int_equal(value(hunger), 0);
    assert_int_equal(pdl_host_output(PDL_LED, 0), 0);
}

/* Superposition: from the same state (motors at rest), one cycle of all
 * behaviours changes each motor by the sum of the changes of each behaviour
 * alone. */
static int32_t one_cycle_delta(unsigned which, int motor, int ll, int lr, int il, int ir)
{
    start(which);
    inputs(ll, lr, il, ir, 255);   /* read at the start of the first cycle */
    pdl_run_cycles(1);
    return pdl_host_output(PDL_MOTOR, (unsigned)motor);
}

static void test_superposition_without_arbiter(void **state)
{
    static const int cases[][4] = {{200, 50, 30, 10}, {40, 90, 180, 60}, {0, 255, 90, 100}};
    unsigned c;
    int m;
    (void)state;
    for (c = 0; c < 3; c++) {
        for (m = 0; m < 2; m++) {
            const int *k = cases[c];
            int32_t all = one_cycle_delta(BEH_CRUISE | BEH_PHOTOTAXIS | BEH_AVOID, m, k[0], k[1], k[2], k[3]);
            int32_t sum = one_cycle_delta(BEH_CRUISE, m, k[0], k[1], k[2], k[3]) +
                          one_cycle_delta(BEH_PHOTOTAXIS, m, k[0], k[1], k[2], k[3]) +
                          one_cycle_delta(BEH_AVOID, m, k[0], k[1], k[2], k[3]);
            assert_int_not_equal(all, 0);
            assert_int_equal(all, sum);
        }
    }
}

static void test_setup_refused_after_run(void **state)
{
    (void)state;
    assert_int_equal(start(BEH_ALL), PDL_OK);
    /* declaring again after run_pdl is refused, with the error code */
    assert_int_equal(behaviours_setup(BEH_ALL, 1), PDL_ERR_RUNNING);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cruise_settles_at_cruising_speed),
        cmocka_unit_test(test_phototaxis_turns_toward_the_light),
        cmocka_unit_test(test_avoidance_turns_away_and_backs_up),
        cmocka_unit_test(test_wander_varies_the_heading_within_bounds),
        cmocka_unit_test(test_battery_monitor_makes_the_robot_seek_the_charger),
        cmocka_unit_test(test_superposition_without_arbiter),
        cmocka_unit_test(test_setup_refused_after_run),
    };
    return cmocka_run_group_tests_name("pdl-behaviours", tests, NULL, NULL);
}
