/*
 * Interim I/O of the ecosystem image (see eco_io.h): a polled PCF8584
 * master on I2C bus A for the two PCF8591 converters, the DUART input port
 * for the bumpers and the charger contact, TPU PWM for the wheel motors.
 * Every wait on the I2C controller is bounded (I2C_POLL_LIMIT polls).
 */
#include <stdint.h>

#include "eco_io.h"
#include "drivers/duart.h"
#include "mc68332.h"

/* PCF8584 bus A: S0 (data/own address/clock) at +0, S1 (control/status) at +1. */
#define I2C_S0  MC68332_REG8(0xFFE200)
#define I2C_S1  MC68332_REG8(0xFFE201)
#define S1_PIN  0x80u
#define S1_ES0  0x40u
#define S1_STA  0x04u
#define S1_STO  0x02u
#define S1_ACK  0x01u
/* 9 SCL clocks at 90 kHz are 100 us; a poll is a few instructions: plenty. */
#define I2C_POLL_LIMIT 20000u
#define I2C_ETIMEDOUT (-1)

#define PCF8591_ADDR(chip)   (0x48u + (chip))
#define PCF8591_AUTOINC      0x04u

/* DUART input port (IP0-IP5 levels), read-only. */
#define DUART_IP  MC68332_REG8(0xFFE40D)
#define IP_BUMP_L 0x02u
#define IP_BUMP_R 0x04u
#define IP_CHARGE 0x08u

/* TPU: TPUMCR, CFSR3 (channels 0-3), HSRR1, CPR1 and channel parameters. */
#define TPU_MCR    MC68332_REG16(0xFFFE00)
#define TPU_CFSR3  MC68332_REG16(0xFFFE12)
#define TPU_HSRR1  MC68332_REG16(0xFFFE1A)
#define TPU_CPR1   MC68332_REG16(0xFFFE1E)
#define TPU_PARAM(ch, k) MC68332_REG16(0xFFFF00u + 16u * (ch) + 2u * (k))
#define TPU_FN_PWM 9u
#define PWM_PERIOD 1049u          /* TCR1 ticks at 1.048576 MHz: 1 kHz */
#define PWM_CONTROL 0x008Cu       /* TCR1, pin high at the rising edge */

static const unsigned motor_pwm_ch[2] = {0u, 2u};
static const uint8_t motor_fwd[2] = {0x04u, 0x10u};   /* OP2, OP4 */
static const uint8_t motor_rev[2] = {0x08u, 0x20u};   /* OP3, OP5 */

static uint32_t i2c_errors;
static uint8_t analog[8];

static int i2c_wait(void)
{
    uint32_t n;
    for (n = 0; n < I2C_POLL_LIMIT; n++) {
        if ((I2C_S1 & S1_PIN) == 0u) {
            return 0;
        }
    }
    return I2C_ETIMEDOUT;
}

static void i2c_stop(void)
{
    I2C_S1 = S1_PIN | S1_ES0 | S1_STO | S1_ACK;
}

/* Writes the control byte, then reads n results of the channels in turn
 * (the PCF8591 returns the previous conversion first: one extra byte). */
static int pcf8591_read(unsigned chip, uint8_t control, uint8_t *out, unsigned n)
{
    uint8_t addr = (uint8_t)(PCF8591_ADDR(chip) << 1);
    unsigned i;

    I2C_S0 = addr;
    I2C_S1 = S1_PIN | S1_ES0 | S1_STA | S1_ACK;
    if (i2c_wait() != 0) {
        goto fail;
    }
    I2C_S0 = control;
    if (i2c_wait() != 0) {
        goto fail;
    }
    i2c_stop();
    I2C_S0 = (uint8_t)(addr | 1u);
    I2C_S1 = S1_PIN | S1_ES0 | S1_STA | S1_ACK;
    if (i2c_wait() != 0) {
        goto fail;
    }
    (void)I2C_S0;                        /* dummy read: starts the first byte */
    /* n + 1 bytes: the stale conversion, then the n channels. */
    for (i = 0; i < n; i++) {
        uint8_t b;
        if (i2c_wait() != 0) {
            goto fail;
        }
        if (i == n - 1u) {
            I2C_S1 = S1_ES0;             /* NACK the last byte */
        }
        b = I2C_S0;                      /* starts the next byte */
        if (i > 0u) {
            out[i - 1u] = b;
        }
    }
    if (i2c_wait() != 0) {
        goto fail;
    }
    i2c_stop();
    out[n - 1u] = I2C_S0;
    return 0;
fail:
    i2c_stop();
    i2c_errors++;
    return I2C_ETIMEDOUT;
}

int eco_io_init(void)
{
    unsigned m;

    I2C_S1 = S1_PIN;                     /* select S0' */
    I2C_S0 = 0x55u;                      /* own address */
    I2C_S1 = 0xA0u;                      /* select S2 */
    I2C_S0 = 0x1Cu;                      /* 90 kHz SCL */
    I2C_S1 = S1_PIN | S1_ES0 | S1_ACK;   /* serial interface on, idle */

    TPU_MCR = 0x4ACDu;                   /* TCR1 = fsys / 16 (as CubeOS) */
    TPU_CFSR3 = (uint16_t)((TPU_CFSR3 & 0xF0F0u) | TPU_FN_PWM | (TPU_FN_PWM << 8));
    for (m = 0; m < 2u; m++) {
        unsigned ch = motor_pwm_ch[m];
        TPU_PARAM(ch, 0) = PWM_CONTROL;
        TPU_PARAM(ch, 2) = 0u;
        TPU_PARAM(ch, 3) = PWM_PERIOD;
    }
    TPU_HSRR1 = (uint16_t)(TPU_HSRR1 | 0x0022u);   /* HSR 10 (init) on ch0 and ch2 */
    TPU_CPR1 = (uint16_t)(TPU_CPR1 | 0x0022u);     /* priority 2 (10) */
    duart_op_negate(0x3Cu);              /* both motors: brake */
    return 0;
}

int eco_io_read(struct eco_inputs *in)
{
    int rc = pcf8591_read(0u, PCF8591_AUTOINC, &analog[0], 4u);
    int rc1 = pcf8591_read(1u, PCF8591_AUTOINC, &analog[4], 3u);
    uint8_t ip = DUART_IP;

    in->light_l = analog[0];
    in->light_r = analog[1];
    in->ir_l = analog[2];
    in->ir_r = analog[3];
    in->battery = analog[4];
    in->comp_l = analog[5];
    in->comp_r = analog[6];
    in->bump_l = (ip & IP_BUMP_L) == 0u;
    in->bump_r = (ip & IP_BUMP_R) == 0u;
    in->charging = (ip & IP_CHARGE) == 0u;
    return rc != 0 ? rc : rc1;
}

void eco_io_motors(int32_t left, int32_t right)
{
    int32_t set[2] = {left, right};
    unsigned m;

    for (m = 0; m < 2u; m++) {
        int32_t v = set[m];
        uint32_t mag = (uint32_t)(v < 0 ? -v : v);
        if (mag > 1000u) {
            mag = 1000u;
        }
        /* Direction first, then the duty (taken at the next rising edge). */
        if (v > 0) {
            duart_op_negate(motor_rev[m]);
            duart_op_assert(motor_fwd[m]);
        } else if (v < 0) {
            duart_op_negate(motor_fwd[m]);
            duart_op_assert(motor_rev[m]);
        } else {
            duart_op_negate((uint8_t)(motor_fwd[m] | motor_rev[m]));
        }
        TPU_PARAM(motor_pwm_ch[m], 2) = (uint16_t)(mag * PWM_PERIOD / 1000u);
    }
}

uint32_t eco_io_errors(void)
{
    return i2c_errors;
}
