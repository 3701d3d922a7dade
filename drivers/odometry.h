/*
 * Differential-drive odometry in fixed point (the CPU32 has no FPU): the
 * pose (x, y, heading) from the two wheel encoders' counts.
 *
 * Units: x and y in Q16.16 millimetres (ODOMETRY_MM(v) = v mm; range
 * +-32.7 m), heading as a binary angle: a full turn is 2^32 (uint32_t, wraps
 * like the angle does; ODOMETRY_DEG(d) converts). x points along heading 0,
 * heading grows counter-clockwise (left turn), y to the left.
 *
 * Each update integrates the step from the previous counts along the arc's
 * mean heading (heading + dtheta/2), which is exact for straight steps and
 * for turns in place and second order in dtheta for arcs; update at least
 * every few counts (the motor service period gives a few counts at most).
 * Sine and cosine come from CORDIC in shifts and adds (odometry.c).
 */
#ifndef DRIVERS_ODOMETRY_H
#define DRIVERS_ODOMETRY_H

#include <stdint.h>

#define ODOMETRY_Q 16
#define ODOMETRY_MM(mm) ((int32_t)((mm) * 65536))
/* Binary angle of d degrees (integer d). */
#define ODOMETRY_DEG(d) ((uint32_t)((int64_t)(d) * 4294967296LL / 360))

struct odometry {
    int32_t x;                 /* Q16 mm */
    int32_t y;                 /* Q16 mm */
    uint32_t heading;          /* binary angle, 2^32 = one turn */
    /* geometry */
    int32_t mm_per_count;      /* Q16 mm of wheel travel per encoder count */
    int32_t wheel_base;        /* Q16 mm between the wheels' contact points */
    /* last counts seen */
    int32_t left;
    int32_t right;
    /* Remainders of the fixed-point divisions, carried so they do not drift. */
    int64_t heading_rem;
};

/* mm_per_count and wheel_base in Q16 mm (> 0); the counts the encoders show
 * now. The pose starts at (0, 0), heading 0. Returns 0, or DRV_ERR_PARAM for
 * a NULL o or a geometry <= 0. */
int odometry_init(struct odometry *o, int32_t mm_per_count, int32_t wheel_base,
                  int32_t left_counts, int32_t right_counts);
/* Sets the pose (the counts stay). */
void odometry_set_pose(struct odometry *o, int32_t x, int32_t y, uint32_t heading);
/* Integrates from the last counts to these (32-bit counts may wrap). */
void odometry_update(struct odometry *o, int32_t left_counts, int32_t right_counts);

/* Q30 cosine and sine of a binary angle (CORDIC), |error| < 2^-25 (measured 1.6e-8). */
void odometry_cos_sin(uint32_t angle, int32_t *cos_q30, int32_t *sin_q30);

#endif /* DRIVERS_ODOMETRY_H */
