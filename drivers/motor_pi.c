/* PI speed controller of the motors: see motor_pi.h. 64-bit intermediates
 * (the compiler runtime on the CPU32): gain times error overflows 32 bits at the top of
 * the gain range. */
#include "drivers/motor_pi.h"

#define PI_LIMIT ((int64_t)MOTOR_PI_OUT_MAX << MOTOR_PI_Q)
/* Larger errors than this are clamped (speeds are at most 10^7 counts/s). */
#define PI_ERROR_MAX ((int64_t)1 << 25)
/* Longer periods are taken as this long. */
#define PI_DT_MAX_US 1000000u

static int64_t pi_clamp(int64_t v, int64_t lim)
{
    return v > lim ? lim : (v < -lim ? -lim : v);
}

/* Q8 to integer, rounding half away from zero (symmetric for both directions). */
static int32_t pi_round(int64_t q)
{
    const int64_t half = (int64_t)1 << (MOTOR_PI_Q - 1);
    return (int32_t)(q >= 0 ? (q + half) >> MOTOR_PI_Q : -((-q + half) >> MOTOR_PI_Q));
}

void motor_pi_init(struct motor_pi *pi, int32_t kp, int32_t ki)
{
    pi->kp = kp;
    pi->ki = ki;
    pi->integral = 0;
    pi->out = 0;
    pi->saturated = 0;
}

void motor_pi_preset(struct motor_pi *pi, int32_t out_permille)
{
    int64_t out = pi_clamp(out_permille, MOTOR_PI_OUT_MAX);
    pi->integral = (int32_t)(out * (1 << MOTOR_PI_Q));   /* a shift of a negative value is undefined */
    pi->out = (int32_t)out;
    pi->saturated = 0;
}

int32_t motor_pi_step(struct motor_pi *pi, int32_t setpoint, int32_t measured, uint32_t dt_us)
{
    int64_t error = pi_clamp((int64_t)setpoint - measured, PI_ERROR_MAX);
    int64_t p = (int64_t)pi->kp * error;
    /* dt in Q16 seconds without a division: 65536 / 10^6 = 4295 / 2^16
     * (relative error 8e-6); dt_us <= 10^6 keeps the product in 32 bits. */
    uint32_t dt_q16 = ((dt_us > PI_DT_MAX_US ? PI_DT_MAX_US : dt_us) * 4295u) >> 16;
    /* ki < 2^18, |error| <= 2^25, dt_q16 <= 2^16: the product fits 63 bits.
     * No 64-bit division (a compiler runtime loop on the CPU32): a power of two. */
    int64_t di = (int64_t)pi->ki * error * (int64_t)dt_q16 / 65536;
    int64_t integral = pi->integral;
    int64_t unclamped = p + integral + di;

    /* Anti-windup: integrate only as far as the output's limit, never
     * further into saturation (a P term alone beyond the limit freezes the
     * integral); integrating back out of saturation is always allowed. */
    if (unclamped > PI_LIMIT && di > 0) {
        int64_t room = PI_LIMIT - p;
        integral = room > integral ? (integral + di < room ? integral + di : room) : integral;
    } else if (unclamped < -PI_LIMIT && di < 0) {
        int64_t room = -PI_LIMIT - p;
        integral = room < integral ? (integral + di > room ? integral + di : room) : integral;
    } else {
        integral += di;
    }
    integral = pi_clamp(integral, PI_LIMIT);
    pi->integral = (int32_t)integral;
    unclamped = p + integral;
    pi->saturated = (uint8_t)(unclamped > PI_LIMIT || unclamped < -PI_LIMIT);
    pi->out = pi_round(pi_clamp(unclamped, PI_LIMIT));
    return pi->out;
}
