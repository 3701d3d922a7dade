/*
 * Motors: see motor.h. Wiring per emu/IO.md section 1.4.
 *
 * Speed: from the QDEC's edge times rather than from counts per period: at
 * 10 ms and 1000 counts/s a period holds only 10 counts (10 % steps), while
 * the TCR1 time of the last edge (0.95 us resolution) gives the time the
 * counts took. Each period, speed = counts between the newest sample and the
 * oldest of the last MOTOR_SPEED_WINDOW samples that saw the count change /
 * TCR1 ticks between their last edges. The window (about 30-40 ms at the
 * default period) is there because the board model emits its edges in 1 ms
 * steps: over one 10 ms period that quantisation alone is 10 %. TCR1 wraps
 * after 62.5 ms, so older samples are not used; with only an older one, the
 * counts are divided by the time since its sample; with no edge in a period,
 * the speed is bounded by one count per the time since the last edge, and
 * after MOTOR_STOPPED_US without one (under 4 counts/s) it is 0.
 *
 * Concurrency: the service thread and the API callers share each motor's
 * state; every access is a short section with interrupts masked (no lock a
 * caller could wait on). The thread computes the controller step on a copy
 * and applies it only if the motor is still under closed loop and no API
 * call changed it in between (a generation count).
 */
#include <stddef.h>
#include <stdint.h>

#include "kernel.h"
#include "drivers/drv_err.h"
#include "boards/include/board_io.h"
#include "drivers/motor.h"
#include "drivers/motor_pi.h"
#include "drivers/tpu.h"

#define MOTOR_TCR1_WRAP_US 62000u   /* a little under 65536 / 1.048576 MHz */
/* Samples the speed spans at most (with the newest): at 10 ms about 30-40 ms,
 * so that the model's 1 ms edge steps make at most about 3 % of it. */
#define MOTOR_SPEED_WINDOW 4u
#define MOTOR_AGE_MAX_US 2000000u   /* ages stop here (no wrap) */
/* No edge for this long reads as standing still (below 4 counts/s). */
#define MOTOR_STOPPED_US 250000u

struct motor_wiring {
    uint8_t pwm;       /* TPU channel */
    uint8_t enc_a;     /* TPU channel, QDEC primary */
    uint8_t enc_b;     /* TPU channel, QDEC secondary */
    uint8_t op_fwd;    /* DUART OPR bit asserted alone = forward; op_fwd + 1 = reverse */
};

static const struct motor_wiring motor_wiring[MOTOR_COUNT] = {
    {0u, 1u, 12u, 2u},
    {2u, 3u, 14u, 4u},
    {4u, 5u, 13u, 6u},
};

/* A sample in which the count changed: the count, the TCR1 time of its
 * last edge, and how long ago the sample was taken. */
struct motor_edge_sample {
    int32_t pos;
    uint16_t edge;
    uint8_t valid;
    uint32_t age_us;
};

struct motor_state {
    int32_t power;           /* per-mille applied */
    int8_t direction;        /* -1, 0, 1 as the DUART bits are now */
    uint8_t closed;          /* under the speed controller */
    uint32_t generation;     /* counts API changes (set-point, gains, open loop) */
    int32_t setpoint;        /* counts/s */
    struct motor_pi pi;
    /* speed estimate: the last samples that saw the count change */
    struct motor_edge_sample hist[MOTOR_SPEED_WINDOW];
    uint8_t newest;          /* index of the newest entry of hist */
    int32_t last_pos;
    int32_t speed;
};

static struct motor_state motors[MOTOR_COUNT];
static int motor_ready;
static struct k_thread motor_thread;
static volatile k_ticks_t motor_period_ticks;
static struct motor_service_stats motor_stats;
K_STACK_DEFINE(motor_stack, 1536u);


static uint8_t motor_fwd_bit(unsigned m)
{
    return (uint8_t)(1u << motor_wiring[m].op_fwd);
}

static uint8_t motor_rev_bit(unsigned m)
{
    return (uint8_t)(1u << (motor_wiring[m].op_fwd + 1u));
}

/* Drives motor m (interrupts masked by the caller or not: each step is its
 * own register write). The direction changes through brake (neither bit),
 * never through both bits asserted. */
static int motor_apply(unsigned m, int32_t permille)
{
    struct motor_state *st = &motors[m];
    int8_t dir = (int8_t)(permille > 0 ? 1 : (permille < 0 ? -1 : 0));
    int r;

    if (dir != st->direction) {
        board_outputs_negate((uint8_t)(motor_fwd_bit(m) | motor_rev_bit(m)));
        if (dir > 0)
            board_outputs_assert(motor_fwd_bit(m));
        else if (dir < 0)
            board_outputs_assert(motor_rev_bit(m));
        st->direction = dir;
    }
    r = tpu_pwm(motor_wiring[m].pwm, MOTOR_PWM_HZ, (int)(permille < 0 ? -permille : permille));
    if (r < 0)
        return r;
    st->power = permille;
    return DRV_OK;
}

static int motor_check(unsigned m)
{
    if (m >= MOTOR_COUNT)
        return DRV_ERR_CHANNEL;
    if (!motor_ready)
        return DRV_ERR_STATE;
    return DRV_OK;
}

/* counts / (ticks / TCR1_HZ). TCR1_HZ is 2^20: with fewer than 2^11 counts
 * the product fits 32 bits and the CPU32's DIVS.L does it; more (only at
 * very high speeds) takes the compiler runtime's 64-bit division. */
static int32_t motor_counts_per_s(int32_t counts, uint16_t ticks)
{
    if (counts > -2048 && counts < 2048)
        return (counts * (int32_t)TPU_TCR1_HZ) / (int32_t)ticks;
    return (int32_t)((int64_t)counts * TPU_TCR1_HZ / ticks);
}

/* One speed sample of motor m, dt_us after the previous one. */
static void motor_sample(unsigned m, uint32_t dt_us)
{
    struct motor_state *st = &motors[m];
    int32_t pos, counts;
    uint16_t edge;
    unsigned i, oldest = MOTOR_SPEED_WINDOW;

    if (tpu_qdec_sample(motor_wiring[m].enc_a, &pos, &edge) < 0)
        return;
    for (i = 0; i < MOTOR_SPEED_WINDOW; i++) {
        if (st->hist[i].valid && st->hist[i].age_us < MOTOR_AGE_MAX_US)
            st->hist[i].age_us += dt_us;
    }
    counts = pos - st->last_pos;
    if (counts == 0) {
        /* No edge since the last change: at most one count in that time. */
        uint32_t since = st->hist[st->newest].valid ? st->hist[st->newest].age_us : MOTOR_AGE_MAX_US;
        int32_t bound = since >= MOTOR_STOPPED_US ? 0 : (int32_t)(1000000u / since);
        if (st->speed > bound)
            st->speed = bound;
        else if (st->speed < -bound)
            st->speed = -bound;
        return;
    }
    /* The oldest remembered edge whose time TCR1 cannot have wrapped from:
     * it happened at most one period before its sample. */
    for (i = 1; i < MOTOR_SPEED_WINDOW; i++) {
        unsigned k = (st->newest + MOTOR_SPEED_WINDOW - i + 1u) % MOTOR_SPEED_WINDOW;
        if (st->hist[k].valid && st->hist[k].age_us + dt_us < MOTOR_TCR1_WRAP_US)
            oldest = k;
    }
    if (oldest < MOTOR_SPEED_WINDOW && (uint16_t)(edge - st->hist[oldest].edge) != 0u) {
        st->speed = motor_counts_per_s(pos - st->hist[oldest].pos,
                                       (uint16_t)(edge - st->hist[oldest].edge));
    } else {
        /* Only an old edge to go by: counts over the time since its sample. */
        uint32_t since = st->hist[st->newest].valid ? st->hist[st->newest].age_us : dt_us;
        st->speed = (int32_t)((int64_t)counts * 1000000 / (since ? since : 1u));
    }
    st->newest = (uint8_t)((st->newest + 1u) % MOTOR_SPEED_WINDOW);
    st->hist[st->newest].pos = pos;
    st->hist[st->newest].edge = edge;
    st->hist[st->newest].age_us = 0;
    st->hist[st->newest].valid = 1;
    st->last_pos = pos;
}

static void *motor_service(void *arg)
{
    k_ticks_t next = k_ticks();
    (void)arg;

    for (;;) {
        k_ticks_t period = motor_period_ticks;
        /* period <= 1024 ticks (1 s): the product stays within 32 bits */
        uint32_t dt_us = (uint32_t)period * 1000000u / K_TICK_HZ;
        unsigned m;

        next += period;
        if ((int32_t)(k_ticks() - next) > 0) {
            motor_stats.late++;
            next = k_ticks();            /* resynchronise, no burst of catch-up periods */
        }
        (void)k_sleep_until(next);
        for (m = 0; m < MOTOR_COUNT; m++) {
            struct motor_state *st = &motors[m];
            struct motor_pi pi;
            int32_t setpoint, speed, out;
            uint32_t irq, generation;
            uint8_t closed;

            motor_sample(m, dt_us);
            /* The controller step (64-bit arithmetic) runs on a copy with
             * interrupts enabled; the result is applied only if no API call
             * changed the motor meanwhile (generation). */
            irq = k_arch_irq_save();
            closed = st->closed;
            generation = st->generation;
            pi = st->pi;
            setpoint = st->setpoint;
            speed = st->speed;
            k_arch_irq_restore(irq);
            if (!closed)
                continue;
            out = motor_pi_step(&pi, setpoint, speed, dt_us);
            irq = k_arch_irq_save();
            if (st->closed && st->generation == generation) {
                st->pi = pi;
                (void)motor_apply(m, out);
            }
            k_arch_irq_restore(irq);
        }
        motor_stats.periods++;
    }
    return NULL;
}

int motor_control_start(unsigned period_ms)
{
    int r;
    if (period_ms < 1u || period_ms > MOTOR_PERIOD_MS_MAX)
        return DRV_ERR_RANGE;
    if (!motor_ready)
        return DRV_ERR_STATE;
    motor_period_ticks = k_ms_to_ticks(period_ms);
    motor_stats.period_ms = period_ms;
    if (motor_thread.state != K_THREAD_UNUSED)
        return DRV_OK;
    r = k_thread_create(&motor_thread, "motor", motor_service, NULL, motor_stack,
                        sizeof motor_stack, MOTOR_SERVICE_PRIO);
    return r == K_OK ? DRV_OK : DRV_ERR_STATE;
}

int motor_init(void)
{
    unsigned m;
    int r;

    if (motor_ready)
        return DRV_OK;
    r = tpu_init();
    if (r < 0)
        return r;
    for (m = 0; m < MOTOR_COUNT; m++) {
        struct motor_state *st = &motors[m];
        st->direction = 1;               /* forces motor_apply to write both bits */
        r = motor_apply(m, 0);
        if (r < 0)
            return r;
        r = tpu_qdec_start(motor_wiring[m].enc_a, motor_wiring[m].enc_b);
        if (r < 0)
            return r;
        motor_pi_init(&st->pi, MOTOR_KP_DEFAULT, MOTOR_KI_DEFAULT);
        st->closed = 0;
        st->last_pos = 0;
        st->newest = 0;
        for (unsigned i = 0; i < MOTOR_SPEED_WINDOW; i++)
            st->hist[i].valid = 0;
        st->speed = 0;
    }
    motor_ready = 1;
    return motor_control_start(MOTOR_DEFAULT_PERIOD_MS);
}

int motor_set(unsigned m, int permille)
{
    uint32_t irq;
    int r = motor_check(m);
    if (r < 0)
        return r;
    if (permille < -1000 || permille > 1000)
        return DRV_ERR_RANGE;
    irq = k_arch_irq_save();
    motors[m].closed = 0;
    motors[m].generation++;
    r = motor_apply(m, permille);
    k_arch_irq_restore(irq);
    return r;
}

int motor_power(unsigned m, int *permille)
{
    int r = motor_check(m);
    if (r < 0)
        return r;
    if (permille == NULL)
        return DRV_ERR_PARAM;
    *permille = (int)motors[m].power;
    return DRV_OK;
}

int motor_position(unsigned m, int32_t *counts)
{
    int r = motor_check(m);
    if (r < 0)
        return r;
    if (counts == NULL)
        return DRV_ERR_PARAM;
    return tpu_qdec_position(motor_wiring[m].enc_a, counts);
}

int motor_speed(unsigned m, int32_t *counts_per_s)
{
    int r = motor_check(m);
    if (r < 0)
        return r;
    if (counts_per_s == NULL)
        return DRV_ERR_PARAM;
    *counts_per_s = motors[m].speed;
    return DRV_OK;
}

int motor_set_speed(unsigned m, int32_t counts_per_s)
{
    uint32_t irq;
    int r = motor_check(m);
    if (r < 0)
        return r;
    if (counts_per_s < -MOTOR_SPEED_MAX || counts_per_s > MOTOR_SPEED_MAX)
        return DRV_ERR_RANGE;
    if (motor_thread.state != K_THREAD_READY && motor_thread.state != K_THREAD_BLOCKED)
        return DRV_ERR_STATE;
    irq = k_arch_irq_save();
    if (!motors[m].closed)
        motor_pi_preset(&motors[m].pi, motors[m].power);
    motors[m].setpoint = counts_per_s;
    motors[m].closed = 1;
    motors[m].generation++;
    k_arch_irq_restore(irq);
    return DRV_OK;
}

int motor_control_off(unsigned m)
{
    return motor_set(m, 0);
}

int motor_set_gains(unsigned m, int32_t kp, int32_t ki)
{
    uint32_t irq;
    int r = motor_check(m);
    if (r < 0)
        return r;
    if (kp < 0 || kp > MOTOR_GAIN_MAX || ki < 0 || ki > MOTOR_GAIN_MAX)
        return DRV_ERR_RANGE;
    irq = k_arch_irq_save();
    motors[m].pi.kp = kp;
    motors[m].pi.ki = ki;
    motors[m].generation++;
    k_arch_irq_restore(irq);
    return DRV_OK;
}

int motor_get_gains(unsigned m, int32_t *kp, int32_t *ki)
{
    int r = motor_check(m);
    if (r < 0)
        return r;
    if (kp == NULL || ki == NULL)
        return DRV_ERR_PARAM;
    *kp = motors[m].pi.kp;
    *ki = motors[m].pi.ki;
    return DRV_OK;
}

int motor_service_stats(struct motor_service_stats *out)
{
    if (out == NULL)
        return DRV_ERR_PARAM;
    if (!motor_ready)
        return DRV_ERR_STATE;
    *out = motor_stats;
    return DRV_OK;
}
