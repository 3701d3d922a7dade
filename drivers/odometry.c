/*
 * Differential-drive odometry in fixed point: see odometry.h.
 *
 * Sine and cosine by CORDIC (rotation mode): 31 shift-and-add steps on Q30
 * values, no multiply, no table of sines. A small hand-written routine rather
 * than a fixed-point library: the ones that fit a freestanding CPU32 image
 * (e.g. libfixmath) are Q16 only, too coarse for the heading of long runs.
 */
#include <stddef.h>

#include "drivers/drv_err.h"
#include "drivers/odometry.h"

/* atan(2^-i) as binary angles (2^32 = one turn), i = 0..30. */
static const int32_t odometry_atan[31] = {
    536870912, 316933406, 167458907, 85004756, 42667331, 21354465, 10679838, 5340245,
    2670163, 1335087, 667544, 333772, 166886, 83443, 41722, 20861,
    10430, 5215, 2608, 1304, 652, 326, 163, 81,
    41, 20, 10, 5, 3, 1, 1,
};
/* 1 / prod(sqrt(1 + 2^-2i)) in Q30: the CORDIC gain, applied up front. */
#define ODOMETRY_CORDIC_K 652032874
/* Binary angle units per radian: 2^32 / (2 pi) (relative error 7e-10). */
#define ODOMETRY_BAM_PER_RAD 683565276LL
#define QUARTER_TURN 0x40000000L

void odometry_cos_sin(uint32_t angle, int32_t *cos_q30, int32_t *sin_q30)
{
    int32_t a = (int32_t)angle;
    int32_t x = ODOMETRY_CORDIC_K, y = 0;
    int flip = 0;
    unsigned i;

    /* CORDIC converges for |a| <= ~99.9 degrees: fold the back half-plane. */
    if (a > QUARTER_TURN || a < -QUARTER_TURN) {
        a = (int32_t)(angle + 0x80000000u);
        flip = 1;
    }
    for (i = 0; i < 31u; i++) {
        int32_t xs = x >> i, ys = y >> i;
        if (a >= 0) {
            x -= ys;
            y += xs;
            a -= odometry_atan[i];
        } else {
            x += ys;
            y -= xs;
            a += odometry_atan[i];
        }
    }
    if (flip) {
        x = -x;
        y = -y;
    }
    *cos_q30 = x;
    *sin_q30 = y;
}

int odometry_init(struct odometry *o, int32_t mm_per_count, int32_t wheel_base,
                  int32_t left_counts, int32_t right_counts)
{
    if (o == NULL || mm_per_count <= 0 || wheel_base <= 0)
        return DRV_ERR_PARAM;
    o->x = 0;
    o->y = 0;
    o->heading = 0;
    o->mm_per_count = mm_per_count;
    o->wheel_base = wheel_base;
    o->left = left_counts;
    o->right = right_counts;
    o->heading_rem = 0;
    return DRV_OK;
}

void odometry_set_pose(struct odometry *o, int32_t x, int32_t y, uint32_t heading)
{
    o->x = x;
    o->y = y;
    o->heading = heading;
    o->heading_rem = 0;
}

/* (v * q30 + 2^29) >> 30, rounding to nearest. */
static int32_t odometry_mul_q30(int64_t v, int32_t q30)
{
    int64_t p = v * q30;
    return (int32_t)((p + ((int64_t)1 << 29)) >> 30);
}

void odometry_update(struct odometry *o, int32_t left_counts, int32_t right_counts)
{
    /* Counts may wrap: the difference of two's complement values is right. */
    int32_t dl = (int32_t)((uint32_t)left_counts - (uint32_t)o->left);
    int32_t dr = (int32_t)((uint32_t)right_counts - (uint32_t)o->right);
    int64_t left_mm = (int64_t)dl * o->mm_per_count;      /* Q16 mm */
    int64_t right_mm = (int64_t)dr * o->mm_per_count;
    int64_t ds = (left_mm + right_mm) / 2;                /* path of the centre, Q16 */
    int64_t turn = (right_mm - left_mm) * ODOMETRY_BAM_PER_RAD + o->heading_rem;
    int32_t dtheta = (int32_t)(turn / o->wheel_base);     /* binary angle */
    int32_t c, s;
    uint32_t mid;

    o->heading_rem = turn - (int64_t)dtheta * o->wheel_base;
    o->left = left_counts;
    o->right = right_counts;
    /* Along the step's mean heading: exact for straight steps and turns in place. */
    mid = o->heading + (uint32_t)(dtheta / 2);
    odometry_cos_sin(mid, &c, &s);
    o->x += odometry_mul_q30(ds, c);
    o->y += odometry_mul_q30(ds, s);
    o->heading += (uint32_t)dtheta;
}
