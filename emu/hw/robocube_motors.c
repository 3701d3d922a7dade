/*
 * DC motor model of the RoboCube: motor m is driven by the TPU PWM channel
 * TP(2m) (duty) and the DUART output bits OP(2+2m)/OP(3+2m) (direction), and
 * has a quadrature wheel encoder on TP(2m+1) (phase A) and a phase-B channel
 * (TP12, TP14, TP13). First-order model in virtual time:
 *     tau * d(speed)/dt = duty * direction * max_speed - speed
 * The position integrates the speed; every whole count is emitted as a
 * quadrature edge on the encoder pins, so whatever TPU function the firmware
 * runs there (QDEC, ITC, DIO) sees real edges.
 */
#include "qemu/osdep.h"
#include "qemu/module.h"
#include "qapi/error.h"
#include "robocube_io_devs.h"
#include <math.h>

/* Phase-B channels: motor 0 and 2 as in CubeOS' icontrol (TP12, TP13);
 * motor 1 (no encoder in CubeOS) gets TP14. */
static const int enc_b_channel[RC_MOTORS] = { 12, 14, 13 };

#define DEFAULT_MAX_SPEED 2000      /* counts/s at 100 % duty */
#define DEFAULT_TAU_MS 50
#define MAX_HOST_JUMP 1000000       /* largest encoder step a host write may ask for */

/* Quadrature phase of count n: 0:(A0,B0) 1:(A1,B0) 2:(A1,B1) 3:(A0,B1);
 * counting up means A leads B. */
static void set_encoder_pins(RoboCubeMotor *m)
{
    unsigned phase = (unsigned)(m->encoder & 3);
    tpu_set_input(m->tpu, m->enc_a_ch, phase == 1 || phase == 2);
    tpu_set_input(m->tpu, m->enc_b_ch, phase == 2 || phase == 3);
}

static void motor_move_to(RoboCubeMotor *m, int64_t target)
{
    while (m->encoder != target) {
        m->encoder += m->encoder < target ? 1 : -1;
        set_encoder_pins(m);
    }
}

int robocube_motor_direction(RoboCubeMotor *m, uint8_t opr)
{
    bool fwd = (opr >> (2 + 2 * m->index)) & 1;
    bool rev = (opr >> (3 + 2 * m->index)) & 1;
    return fwd == rev ? 0 : (fwd ? 1 : -1);
}

void robocube_motor_step(RoboCubeMotor *m, int64_t now_ns, uint8_t opr)
{
    double dt = (double)(now_ns - m->last_ns) / 1e9;
    double target = robocube_motor_direction(m, opr) *
                    (tpu_pwm_duty(m->tpu, m->pwm_ch) / 10000.0) * m->max_speed;
    int64_t whole;

    m->last_ns = now_ns;
    if (!m->model_enabled || dt <= 0) {
        return;
    }
    if (m->tau_ms == 0) {
        m->speed = target;
    } else {
        m->speed += (target - m->speed) * (1.0 - exp(-dt * 1000.0 / m->tau_ms));
    }
    m->frac += m->speed * dt;
    whole = (int64_t)m->frac;          /* truncates toward zero */
    m->frac -= (double)whole;
    if (whole) {
        motor_move_to(m, m->encoder + whole);
    }
}

void robocube_motor_reset(RoboCubeMotor *m)
{
    /* A CPU reset cuts the drive but does not stop a turning wheel at once;
     * the model keeps its mechanical state (speed, encoder position). */
    m->last_ns = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
}

static int64_t prop_encoder_get(void *opaque, int i)
{
    return ROBOCUBE_MOTOR(opaque)->encoder;
}

static bool prop_encoder_set(void *opaque, int i, int64_t v, Error **errp)
{
    RoboCubeMotor *m = ROBOCUBE_MOTOR(opaque);
    if (v - m->encoder > MAX_HOST_JUMP || m->encoder - v > MAX_HOST_JUMP) {
        error_setg(errp, "motor%d: encoder jump %" PRId64 " -> %" PRId64
                   " larger than %d counts", m->index, m->encoder, v, MAX_HOST_JUMP);
        return false;
    }
    motor_move_to(m, v);
    m->frac = 0;
    return true;
}

static int64_t prop_speed_get(void *opaque, int i)
{
    return (int64_t)lround(ROBOCUBE_MOTOR(opaque)->speed);
}

static int64_t prop_duty_get(void *opaque, int i)
{
    RoboCubeMotor *m = ROBOCUBE_MOTOR(opaque);
    return tpu_pwm_duty(m->tpu, m->pwm_ch);
}

static int64_t prop_direction_get(void *opaque, int i)
{
    return robocube_motor_direction(ROBOCUBE_MOTOR(opaque), robocube_duart_opr());
}

static int64_t prop_dir_bits_get(void *opaque, int i)
{
    RoboCubeMotor *m = ROBOCUBE_MOTOR(opaque);
    return (robocube_duart_opr() >> (2 + 2 * m->index)) & 3;
}

static int64_t prop_model_get(void *opaque, int i)
{
    return ROBOCUBE_MOTOR(opaque)->model_enabled;
}

static bool prop_model_set(void *opaque, int i, int64_t v, Error **errp)
{
    RoboCubeMotor *m = ROBOCUBE_MOTOR(opaque);
    m->model_enabled = v != 0;
    if (!m->model_enabled) {
        m->speed = 0;
        m->frac = 0;
    }
    return true;
}

static int64_t prop_max_speed_get(void *opaque, int i)
{
    return ROBOCUBE_MOTOR(opaque)->max_speed;
}

static bool prop_max_speed_set(void *opaque, int i, int64_t v, Error **errp)
{
    ROBOCUBE_MOTOR(opaque)->max_speed = (uint32_t)v;
    return true;
}

static int64_t prop_tau_get(void *opaque, int i)
{
    return ROBOCUBE_MOTOR(opaque)->tau_ms;
}

static bool prop_tau_set(void *opaque, int i, int64_t v, Error **errp)
{
    ROBOCUBE_MOTOR(opaque)->tau_ms = (uint32_t)v;
    return true;
}

static int64_t prop_channel_get(void *opaque, int which)
{
    RoboCubeMotor *m = ROBOCUBE_MOTOR(opaque);
    return which == 0 ? m->pwm_ch : which == 1 ? m->enc_a_ch : m->enc_b_ch;
}

void robocube_motor_setup(RoboCubeMotor *m, MC68332TpuState *tpu, int index)
{
    Object *o = OBJECT(m);
    m->tpu = tpu;
    m->index = index;
    m->pwm_ch = 2 * index;
    m->enc_a_ch = 2 * index + 1;
    m->enc_b_ch = enc_b_channel[index];
    m->model_enabled = true;
    m->max_speed = DEFAULT_MAX_SPEED;
    m->tau_ms = DEFAULT_TAU_MS;
    m->last_ns = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    set_encoder_pins(m);

    rc_prop_add_int(o, "encoder", INT64_MIN, INT64_MAX, prop_encoder_get,
                    prop_encoder_set, m, 0);
    rc_prop_add_int(o, "speed", INT64_MIN, INT64_MAX, prop_speed_get, NULL, m, 0);
    rc_prop_add_int(o, "duty", 0, 10000, prop_duty_get, NULL, m, 0);
    rc_prop_add_int(o, "direction", -1, 1, prop_direction_get, NULL, m, 0);
    rc_prop_add_int(o, "dir-bits", 0, 3, prop_dir_bits_get, NULL, m, 0);
    rc_prop_add_int(o, "model-enabled", 0, 1, prop_model_get, prop_model_set, m, 0);
    rc_prop_add_int(o, "max-speed", 0, 10000000, prop_max_speed_get,
                    prop_max_speed_set, m, 0);
    rc_prop_add_int(o, "time-constant-ms", 0, 100000, prop_tau_get, prop_tau_set, m, 0);
    rc_prop_add_int(o, "pwm-channel", 0, 15, prop_channel_get, NULL, m, 0);
    rc_prop_add_int(o, "encoder-a-channel", 0, 15, prop_channel_get, NULL, m, 1);
    rc_prop_add_int(o, "encoder-b-channel", 0, 15, prop_channel_get, NULL, m, 2);
}

static const TypeInfo motor_info = {
    .name = TYPE_ROBOCUBE_MOTOR,
    .parent = TYPE_OBJECT,
    .instance_size = sizeof(RoboCubeMotor),
};

static void motor_register_types(void)
{
    type_register_static(&motor_info);
}

type_init(motor_register_types)
