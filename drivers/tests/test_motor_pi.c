/* Host unit tests of the motors' PI speed controller (drivers/motor_pi.c). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "drivers/motor_pi.h"

#define Q(v) ((int32_t)((v) * 256))
#define DT_10MS 10000u

static void test_proportional_only(void **state)
{
    struct motor_pi pi;
    (void)state;
    motor_pi_init(&pi, Q(1), 0);
    assert_int_equal(motor_pi_step(&pi, 1000, 900, DT_10MS), 100);
    assert_int_equal(motor_pi_step(&pi, 900, 1000, DT_10MS), -100);
    assert_int_equal(motor_pi_step(&pi, 500, 500, DT_10MS), 0);
    assert_int_equal(pi.integral, 0);
}

static void test_rounding_is_symmetric(void **state)
{
    struct motor_pi pi;
    (void)state;
    motor_pi_init(&pi, Q(0.5), 0);
    assert_int_equal(motor_pi_step(&pi, 3, 0, DT_10MS), 2);    /* 1.5 -> 2 */
    assert_int_equal(motor_pi_step(&pi, -3, 0, DT_10MS), -2);  /* -1.5 -> -2 */
    assert_int_equal(motor_pi_step(&pi, 1, 0, DT_10MS), 1);    /* 0.5 -> 1 */
}

static void test_integral_accumulates_with_time(void **state)
{
    struct motor_pi pi;
    (void)state;
    motor_pi_init(&pi, 0, Q(20));
    /* 20 per-mille per (count/s * s): error 100 for 10 ms adds 20. */
    assert_int_equal(motor_pi_step(&pi, 100, 0, DT_10MS), 20);
    assert_int_equal(motor_pi_step(&pi, 100, 0, DT_10MS), 40);
    /* Twice the period, twice the step. */
    assert_int_equal(motor_pi_step(&pi, 100, 0, 2u * DT_10MS), 80);
    /* Zero error holds the output. */
    assert_int_equal(motor_pi_step(&pi, 100, 100, DT_10MS), 80);
    /* Negative error integrates back down. */
    assert_int_equal(motor_pi_step(&pi, 0, 100, DT_10MS), 60);
}

static void test_output_saturates_both_ways(void **state)
{
    struct motor_pi pi;
    (void)state;
    motor_pi_init(&pi, Q(1), 0);
    assert_int_equal(motor_pi_step(&pi, 5000, 0, DT_10MS), MOTOR_PI_OUT_MAX);
    assert_true(pi.saturated);
    assert_int_equal(motor_pi_step(&pi, -5000, 0, DT_10MS), -MOTOR_PI_OUT_MAX);
    assert_true(pi.saturated);
    assert_int_equal(motor_pi_step(&pi, 10, 0, DT_10MS), 10);
    assert_false(pi.saturated);
}

/* A long saturation from the P term must leave no integral behind: once the
 * error is gone the output is what the integral held before (0 here). A plain
 * integrator would have 100 steps x 1000 per-mille wound up. */
static void test_anti_windup_under_p_saturation(void **state)
{
    struct motor_pi pi;
    int i;
    (void)state;
    motor_pi_init(&pi, Q(1), Q(20));
    for (i = 0; i < 100; i++)
        assert_int_equal(motor_pi_step(&pi, 5000, 0, DT_10MS), MOTOR_PI_OUT_MAX);
    assert_int_equal(pi.integral, 0);
    assert_int_equal(motor_pi_step(&pi, 0, 0, DT_10MS), 0);
    /* The same in reverse. */
    for (i = 0; i < 100; i++)
        assert_int_equal(motor_pi_step(&pi, -5000, 0, DT_10MS), -MOTOR_PI_OUT_MAX);
    assert_int_equal(pi.integral, 0);
    assert_int_equal(motor_pi_step(&pi, 0, 0, DT_10MS), 0);
}

/* Saturated by the integral itself: it stops at the limit, and the first
 * step of opposite error brings the output below the limit at once. */
static void test_anti_windup_integral_recovers_at_once(void **state)
{
    struct motor_pi pi;
    int i;
    (void)state;
    motor_pi_init(&pi, 0, Q(20));
    for (i = 0; i < 1000; i++)
        (void)motor_pi_step(&pi, 2000, 0, DT_10MS);
    assert_int_equal(pi.out, MOTOR_PI_OUT_MAX);
    assert_true(pi.integral <= (MOTOR_PI_OUT_MAX << MOTOR_PI_Q));
    assert_int_equal(pi.integral, MOTOR_PI_OUT_MAX << MOTOR_PI_Q);
    /* error -50 for 10 ms: -10 per step */
    assert_true(motor_pi_step(&pi, 0, 50, DT_10MS) < MOTOR_PI_OUT_MAX);
    assert_true(motor_pi_step(&pi, 0, 50, DT_10MS) <= MOTOR_PI_OUT_MAX - 10);
    /* Same on the negative side. */
    for (i = 0; i < 1000; i++)
        (void)motor_pi_step(&pi, -2000, 0, DT_10MS);
    assert_int_equal(pi.out, -MOTOR_PI_OUT_MAX);
    assert_true(pi.integral >= -(MOTOR_PI_OUT_MAX << MOTOR_PI_Q));
    assert_true(motor_pi_step(&pi, 50, 0, DT_10MS) > -MOTOR_PI_OUT_MAX);
}

static void test_preset_is_bumpless(void **state)
{
    struct motor_pi pi;
    (void)state;
    motor_pi_init(&pi, Q(1), Q(20));
    motor_pi_preset(&pi, 500);
    assert_int_equal(motor_pi_step(&pi, 700, 700, DT_10MS), 500);
    motor_pi_preset(&pi, -2000);                    /* clamped */
    assert_int_equal(motor_pi_step(&pi, 0, 0, DT_10MS), -MOTOR_PI_OUT_MAX);
}

/* The largest gains, errors and periods stay in range (no overflow: the
 * sanitizer build of this suite would trap one). */
static void test_extremes_do_not_overflow(void **state)
{
    struct motor_pi pi;
    int i;
    (void)state;
    motor_pi_init(&pi, MOTOR_PI_GAIN_MAX, MOTOR_PI_GAIN_MAX);
    for (i = 0; i < 3; i++) {
        assert_int_equal(motor_pi_step(&pi, 10000000, -10000000, 4000000000u), MOTOR_PI_OUT_MAX);
        assert_int_equal(motor_pi_step(&pi, INT32_MIN, INT32_MAX, 4000000000u), -MOTOR_PI_OUT_MAX);
    }
    assert_true(pi.integral >= -(MOTOR_PI_OUT_MAX << MOTOR_PI_Q));
    assert_true(pi.integral <= (MOTOR_PI_OUT_MAX << MOTOR_PI_Q));
}

/* Closed loop against a discrete first-order motor like the board model's
 * default (2000 counts/s at full power, tau 50 ms), 10 ms periods: the
 * default gains reach 1000 counts/s within 5 % and stay there. */
static void test_closed_loop_first_order_plant(void **state)
{
    struct motor_pi pi;
    double speed = 0.0;
    int i, settled_at = -1;
    (void)state;
    motor_pi_init(&pi, Q(1), Q(20));
    for (i = 0; i < 100; i++) {
        int32_t u = motor_pi_step(&pi, 1000, (int32_t)speed, DT_10MS);
        double target = 2.0 * u;
        speed = target + (speed - target) * 0.8187307530779818;   /* exp(-10/50) */
        if (speed < 950.0 || speed > 1050.0)
            settled_at = -1;
        else if (settled_at < 0)
            settled_at = i;
    }
    assert_true(settled_at >= 0 && settled_at < 30);
    assert_true(speed > 990.0 && speed < 1010.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_proportional_only),
        cmocka_unit_test(test_rounding_is_symmetric),
        cmocka_unit_test(test_integral_accumulates_with_time),
        cmocka_unit_test(test_output_saturates_both_ways),
        cmocka_unit_test(test_anti_windup_under_p_saturation),
        cmocka_unit_test(test_anti_windup_integral_recovers_at_once),
        cmocka_unit_test(test_preset_is_bumpless),
        cmocka_unit_test(test_extremes_do_not_overflow),
        cmocka_unit_test(test_closed_loop_first_order_plant),
    };
    return cmocka_run_group_tests_name("motor_pi", tests, NULL, NULL);
}
