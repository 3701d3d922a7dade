/* Host unit tests of the fixed-point odometry (drivers/odometry.c) against a
 * floating-point reference: the exact geometry of a straight line, a turn in
 * place and a circular arc, and libm's sine and cosine. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <math.h>
#include <cmocka.h>

#include "drivers/drv_err.h"
#include "drivers/odometry.h"

#define MM_PER_COUNT 0.25      /* mm of wheel travel per count */
#define WHEEL_BASE 112.0       /* mm (the RoboCube's, facts 3.3) */
#define TWO_PI 6.283185307179586

static double mm(int32_t q16) { return q16 / 65536.0; }
static double turns(uint32_t bam) { return bam / 4294967296.0; }
/* Heading in radians, -pi..pi. */
static double radians(uint32_t bam) { return (int32_t)bam / 4294967296.0 * TWO_PI; }

static struct odometry robot(void)
{
    struct odometry o;
    assert_int_equal(odometry_init(&o, (int32_t)(MM_PER_COUNT * 65536), (int32_t)(WHEEL_BASE * 65536), 0, 0), DRV_OK);
    return o;
}

static void test_cos_sin_against_libm(void **state)
{
    double worst = 0.0;
    uint32_t a = 0;
    int i;
    (void)state;
    for (i = 0; i < 100000; i++) {
        int32_t c, s;
        double rad = a / 4294967296.0 * TWO_PI;
        odometry_cos_sin(a, &c, &s);
        worst = fmax(worst, fabs(c / 1073741824.0 - cos(rad)));
        worst = fmax(worst, fabs(s / 1073741824.0 - sin(rad)));
        a += 42949u * 1000u + 12345u;   /* steps through every quadrant */
    }
    /* The quadrant edges exactly. */
    for (i = 0; i < 8; i++) {
        int32_t c, s;
        uint32_t e = (uint32_t)i << 29;
        double rad = e / 4294967296.0 * TWO_PI;
        odometry_cos_sin(e, &c, &s);
        worst = fmax(worst, fabs(c / 1073741824.0 - cos(rad)));
        worst = fmax(worst, fabs(s / 1073741824.0 - sin(rad)));
    }
    print_message("worst cos/sin error %.3g (2^-25 = %.3g)\n", worst, ldexp(1.0, -25));
    assert_true(worst < ldexp(1.0, -25));
}

static void test_straight_line(void **state)
{
    struct odometry o = robot();
    int32_t n;
    (void)state;
    for (n = 10; n <= 4000; n += 10)
        odometry_update(&o, n, n);
    assert_true(fabs(mm(o.x) - 4000 * MM_PER_COUNT) < 0.01);
    assert_true(fabs(mm(o.y)) < 0.01);
    assert_int_equal(o.heading, 0);
    /* Backwards, after turning the pose to 90 degrees: y goes down. */
    odometry_set_pose(&o, 0, 0, ODOMETRY_DEG(90));
    odometry_update(&o, 3000, 3000);
    assert_true(fabs(mm(o.x)) < 0.01);
    assert_true(fabs(mm(o.y) - (-1000 * MM_PER_COUNT)) < 0.01);
}

static void test_turn_in_place(void **state)
{
    struct odometry o = robot();
    /* One full turn: each wheel travels pi * base. */
    double wheel_mm = TWO_PI * WHEEL_BASE / 2.0;
    int32_t counts = (int32_t)lround(wheel_mm / MM_PER_COUNT);
    double expect_turns = 2.0 * counts * MM_PER_COUNT / WHEEL_BASE / TWO_PI;
    int32_t n;
    (void)state;
    for (n = 1; n <= counts; n++)
        odometry_update(&o, -n, n);
    assert_true(fabs(mm(o.x)) < 0.001);
    assert_true(fabs(mm(o.y)) < 0.001);
    /* expect_turns is one turn, give or take a fraction of a count's rotation */
    assert_true(fabs(remainder(turns(o.heading) - expect_turns, 1.0)) < 1e-7);
    /* A quarter turn clockwise the other way: heading -90 degrees. */
    odometry_set_pose(&o, 0, 0, 0);
    counts = (int32_t)lround(wheel_mm / 4.0 / MM_PER_COUNT);
    odometry_update(&o, -n + 1 + counts, n - 1 - counts);
    assert_true(fabs(radians(o.heading) - (-2.0 * counts * MM_PER_COUNT / WHEEL_BASE)) < 1e-6);
    assert_true(fabs(mm(o.x)) < 0.001 && fabs(mm(o.y)) < 0.001);
}

/* Constant wheel speeds: a circle of radius R = b/2 (r+l)/(r-l) about
 * (0, R); after the wheels turned by dl, dr the exact pose is
 * theta = (dr - dl)/b, x = R sin theta, y = R (1 - cos theta). */
static void check_arc(int32_t step_l, int32_t step_r, int steps, double tol_mm)
{
    struct odometry o = robot();
    int32_t l = 0, r = 0;
    double dl, dr, theta, radius, x, y;
    int i;
    for (i = 0; i < steps; i++) {
        l += step_l;
        r += step_r;
        odometry_update(&o, l, r);
    }
    dl = l * MM_PER_COUNT;
    dr = r * MM_PER_COUNT;
    theta = (dr - dl) / WHEEL_BASE;
    radius = WHEEL_BASE / 2.0 * (dr + dl) / (dr - dl);
    x = radius * sin(theta);
    y = radius * (1.0 - cos(theta));
    print_message("arc %d/%d x %d: fixed (%.4f, %.4f, %.6f rad) reference (%.4f, %.4f, %.6f)\n",
                  step_l, step_r, steps, mm(o.x), mm(o.y), radians(o.heading), x, y,
                  remainder(theta, TWO_PI));
    assert_true(fabs(mm(o.x) - x) < tol_mm);
    assert_true(fabs(mm(o.y) - y) < tol_mm);
    assert_true(fabs(remainder(radians(o.heading) - theta, TWO_PI)) < 1e-6);
}

static void test_arc_left(void **state)
{
    (void)state;
    check_arc(3, 5, 2000, 0.02);      /* 2 m of path, 1.36 turns */
}

static void test_arc_right_backwards(void **state)
{
    (void)state;
    check_arc(-7, -4, 1000, 0.02);
}

/* Encoder counts are 32-bit and may wrap: the steps across the wrap count. */
static void test_counts_wrap(void **state)
{
    struct odometry o;
    int32_t start = INT32_MAX - 500;
    int i;
    (void)state;
    assert_int_equal(odometry_init(&o, 65536 / 4, 112 * 65536, start, start), DRV_OK);
    for (i = 1; i <= 100; i++) {
        int32_t c = (int32_t)((uint32_t)start + (uint32_t)(10 * i));
        odometry_update(&o, c, c);
    }
    assert_true(fabs(mm(o.x) - 1000 * MM_PER_COUNT) < 0.01);
}

static void test_bad_geometry(void **state)
{
    struct odometry o;
    (void)state;
    assert_int_equal(odometry_init(NULL, 1, 1, 0, 0), DRV_ERR_PARAM);
    assert_int_equal(odometry_init(&o, 0, 1, 0, 0), DRV_ERR_PARAM);
    assert_int_equal(odometry_init(&o, 1, -5, 0, 0), DRV_ERR_PARAM);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cos_sin_against_libm),
        cmocka_unit_test(test_straight_line),
        cmocka_unit_test(test_turn_in_place),
        cmocka_unit_test(test_arc_left),
        cmocka_unit_test(test_arc_right_backwards),
        cmocka_unit_test(test_counts_wrap),
        cmocka_unit_test(test_bad_geometry),
    };
    return cmocka_run_group_tests_name("odometry", tests, NULL, NULL);
}
