/*
 * TPU driver: see tpu.h. The TPU's configuration registers pack several
 * channels into one word, so every read-modify-write runs with interrupts
 * masked; HSRR is written with only the channel's own field set (a 00 field
 * leaves other channels' pending requests alone).
 *
 * A function is (re)started the way the TPU reference manual asks: priority
 * 0 (channel off), function and parameters, host sequence and service
 * request, then the priority, which lets the TPU serve the request.
 */
#include <stddef.h>
#include <stdint.h>

#include "kernel.h"
#include "drivers/drv_err.h"
#include "drivers/tpu.h"
#include "drivers/tpu_regs.h"

enum tpu_mode {
    TPU_MODE_NONE = 0,
    TPU_MODE_PWM,
    TPU_MODE_DIO_OUT,
    TPU_MODE_DIO_IN,
    TPU_MODE_ITC,
    TPU_MODE_QDEC_PRIMARY,
    TPU_MODE_QDEC_SECONDARY
};

struct tpu_channel {
    uint8_t mode;            /* enum tpu_mode */
    uint8_t partner;         /* QDEC: the other channel of the pair */
    uint16_t qdec_last;      /* QDEC primary: POSITION_COUNT at the last read */
    int32_t qdec_pos;        /* QDEC primary: the 32-bit position */
    uint32_t itc_base;       /* ITC: edges counted by the chunks already reported */
    uint32_t irqs;           /* interrupts served */
    tpu_irq_fn fn;
    void *arg;
};

static struct tpu_channel tpu_ch[TPU_CHANNELS];
/* Consistent-read retries: edges between two reads make a retry; this many
 * in a row (edges every few instructions) give DRV_ERR_BUSY, never a hang. */
#define TPU_READ_TRIES 8u
static int tpu_ready;

static void tpu_set_bits(volatile uint16_t *reg, unsigned shift, unsigned width_mask, unsigned v)
{
    *reg = (uint16_t)((*reg & ~(width_mask << shift)) | ((v & width_mask) << shift));
}

/* Callers hold the interrupt mask. */
static void tpu_channel_off(unsigned ch)
{
    tpu_set_bits(&TPU_CPR(ch), TPU_FIELD2_SHIFT(ch), 3u, TPU_PRIO_OFF);
    TPU_CIER = (uint16_t)(TPU_CIER & ~(1u << ch));
    TPU_CISR = (uint16_t)~(1u << ch);     /* writing 0 clears, 1 keeps */
}

static void tpu_function(unsigned ch, unsigned fn, unsigned hsq)
{
    tpu_set_bits(&TPU_CFSR(ch), TPU_CFSR_SHIFT(ch), 0xFu, fn);
    tpu_set_bits(&TPU_HSQR(ch), TPU_FIELD2_SHIFT(ch), 3u, hsq);
}

static void tpu_request(unsigned ch, unsigned hsr)
{
    TPU_HSRR(ch) = (uint16_t)((hsr & 3u) << TPU_FIELD2_SHIFT(ch));
}

static void tpu_enable(unsigned ch)
{
    tpu_set_bits(&TPU_CPR(ch), TPU_FIELD2_SHIFT(ch), 3u, TPU_PRIO_MID);
}

static void tpu_irq_enable(unsigned ch, int on)
{
    if (on)
        TPU_CIER = (uint16_t)(TPU_CIER | (1u << ch));
    else
        TPU_CIER = (uint16_t)(TPU_CIER & ~(1u << ch));
}

static void tpu_isr(void *arg)
{
    unsigned ch = (unsigned)(uintptr_t)arg;
    struct tpu_channel *c = &tpu_ch[ch];

    TPU_CISR = (uint16_t)~(1u << ch);
    c->irqs++;
    if (c->mode == TPU_MODE_ITC)
        c->itc_base += TPU_ITC_CHUNK;
    if (c->fn != NULL)
        c->fn(ch, c->arg);
}

int tpu_init(void)
{
    unsigned ch;

    if (tpu_ready)
        return DRV_OK;
    TPU_MCR = TPU_MCR_CUBEOS;
    TPU_CIER = 0;
    for (ch = 0; ch < TPU_CHANNELS; ch++) {
        int r = k_irq_register(TPU_VECTOR_BASE + ch, TPU_IRQ_LEVEL, tpu_isr, (void *)(uintptr_t)ch);
        if (r != K_OK)
            return DRV_ERR_STATE;
    }
    TPU_TICR = TPU_TICR_VALUE(TPU_IRQ_LEVEL, TPU_VECTOR_BASE);
    tpu_ready = 1;
    return DRV_OK;
}

static int tpu_check(unsigned ch)
{
    if (ch >= TPU_CHANNELS || (board_tpu_reserved & (1u << ch)) != 0u)
        return DRV_ERR_CHANNEL;
    if (!tpu_ready)
        return DRV_ERR_STATE;
    return DRV_OK;
}

/* tpu_check, and the channel must run `mode`. */
static int tpu_check_mode(unsigned ch, enum tpu_mode mode)
{
    int r = tpu_check(ch);
    if (r < 0)
        return r;
    return tpu_ch[ch].mode == mode ? DRV_OK : DRV_ERR_STATE;
}

/* Leaves a QDEC pair whole-or-nothing: taking one channel of a pair stops both. */
static void tpu_leave_mode(unsigned ch)
{
    struct tpu_channel *c = &tpu_ch[ch];
    if (c->mode == TPU_MODE_QDEC_PRIMARY || c->mode == TPU_MODE_QDEC_SECONDARY) {
        unsigned other = c->partner;
        tpu_channel_off(other);
        tpu_set_bits(&TPU_CFSR(other), TPU_CFSR_SHIFT(other), 0xFu, 0u);
        tpu_ch[other].mode = TPU_MODE_NONE;
    }
    tpu_channel_off(ch);
    c->mode = TPU_MODE_NONE;
}

/* ---- PWM ---- */

int tpu_pwm_ticks(unsigned ch, uint16_t high, uint16_t period)
{
    uint32_t irq;
    int r = tpu_check(ch);
    if (r < 0)
        return r;
    if (period == 0u || high > period)
        return DRV_ERR_RANGE;
    irq = k_arch_irq_save();
    TPU_PARAM(ch, 2) = high;
    TPU_PARAM(ch, 3) = period;
    if (tpu_ch[ch].mode == TPU_MODE_PWM) {
        tpu_request(ch, 1u);                 /* immediate update */
    } else {
        tpu_leave_mode(ch);
        tpu_function(ch, TPU_FN_PWM, 0u);
        TPU_PARAM(ch, 0) = 0x8C;             /* CHANNEL_CONTROL as CubeOS: pin high at match */
        tpu_request(ch, 2u);                 /* init */
        tpu_ch[ch].mode = TPU_MODE_PWM;
        tpu_irq_enable(ch, tpu_ch[ch].fn != NULL);
        tpu_enable(ch);
    }
    k_arch_irq_restore(irq);
    return DRV_OK;
}

static uint32_t tpu_div_round(uint32_t num, uint32_t den)
{
    return (num + den / 2u) / den;
}

int tpu_pwm(unsigned ch, uint32_t hz, int permille)
{
    uint32_t period, high;
    int r = tpu_check(ch);
    if (r < 0)
        return r;
    if (permille < 0 || permille > 1000 || (hz != 0u && (hz < TPU_PWM_HZ_MIN || hz > TPU_PWM_HZ_MAX)))
        return DRV_ERR_RANGE;
    if (hz == 0u)
        period = tpu_ch[ch].mode == TPU_MODE_PWM ? TPU_PARAM(ch, 3)
                                                 : tpu_div_round(TPU_TCR1_HZ, TPU_PWM_HZ_DEFAULT);
    else
        period = tpu_div_round(TPU_TCR1_HZ, hz);
    high = tpu_div_round(period * (uint32_t)permille, 1000u);
    return tpu_pwm_ticks(ch, (uint16_t)high, (uint16_t)period);
}

int tpu_pwm_get(unsigned ch, uint32_t *hz, int *permille)
{
    uint32_t high, period;
    int r = tpu_check_mode(ch, TPU_MODE_PWM);
    if (r < 0)
        return r;
    high = TPU_PARAM(ch, 2);
    period = TPU_PARAM(ch, 3);
    if (hz != NULL)
        *hz = tpu_div_round(TPU_TCR1_HZ, period);
    if (permille != NULL)
        *permille = (int)tpu_div_round(high * 1000u, period);
    return DRV_OK;
}

/* ---- DIO ---- */

int tpu_dio_write(unsigned ch, int v)
{
    uint32_t irq;
    unsigned hsr = v ? 1u : 2u;              /* 01 drive high, 10 drive low */
    int r = tpu_check(ch);
    if (r < 0)
        return r;
    irq = k_arch_irq_save();
    if (tpu_ch[ch].mode == TPU_MODE_DIO_OUT) {
        tpu_request(ch, hsr);
    } else {
        tpu_leave_mode(ch);
        tpu_function(ch, TPU_FN_DIO, 0u);
        TPU_PARAM(ch, 0) = 0x3;              /* CHANNEL_CONTROL: pin state control (ignored by the model) */
        tpu_request(ch, hsr);
        tpu_ch[ch].mode = TPU_MODE_DIO_OUT;
        tpu_enable(ch);
    }
    k_arch_irq_restore(irq);
    return DRV_OK;
}

int tpu_dio_read(unsigned ch)
{
    uint32_t irq;
    int level;
    int r = tpu_check(ch);
    if (r < 0)
        return r;
    irq = k_arch_irq_save();
    if (tpu_ch[ch].mode != TPU_MODE_DIO_IN && tpu_ch[ch].mode != TPU_MODE_DIO_OUT) {
        tpu_leave_mode(ch);
        /* HSQ 00: PIN_LEVEL records every transition, so bit 15 is the pin. */
        tpu_function(ch, TPU_FN_DIO, 0u);
        TPU_PARAM(ch, 0) = 0xF;              /* CHANNEL_CONTROL: input, both edges */
        tpu_request(ch, 3u);                 /* init as input, record the level now */
        tpu_ch[ch].mode = TPU_MODE_DIO_IN;
        tpu_irq_enable(ch, tpu_ch[ch].fn != NULL);
        tpu_enable(ch);
    }
    level = (TPU_PARAM(ch, 1) & 0x8000u) ? 1 : 0;
    k_arch_irq_restore(irq);
    return level;
}

/* ---- ITC ---- */

int tpu_itc_start(unsigned ch, unsigned edges)
{
    uint32_t irq;
    int r = tpu_check(ch);
    if (r < 0)
        return r;
    if (edges < TPU_EDGE_RISING || edges > TPU_EDGE_BOTH)
        return DRV_ERR_RANGE;
    irq = k_arch_irq_save();
    tpu_leave_mode(ch);
    tpu_function(ch, TPU_FN_ITC, 1u);        /* HSQ 01: continuous, no links */
    TPU_PARAM(ch, 0) = (uint16_t)(edges << 2);
    TPU_PARAM(ch, 2) = (uint16_t)TPU_ITC_CHUNK;
    TPU_PARAM(ch, 3) = 0;
    tpu_ch[ch].itc_base = 0;
    tpu_request(ch, 1u);                     /* init: TRANS_COUNT = 0 */
    tpu_ch[ch].mode = TPU_MODE_ITC;
    tpu_irq_enable(ch, 1);                   /* the chunk interrupt extends the count */
    tpu_enable(ch);
    k_arch_irq_restore(irq);
    return DRV_OK;
}

int tpu_itc_count(unsigned ch, uint32_t *count)
{
    uint32_t irq;
    uint16_t pending_before, pending_after, trans;
    unsigned tries = TPU_READ_TRIES;
    int r = tpu_check_mode(ch, TPU_MODE_ITC);
    if (r < 0)
        return r;
    if (count == NULL)
        return DRV_ERR_PARAM;
    irq = k_arch_irq_save();
    /* TRANS_COUNT restarts at 0 when it reaches the chunk and sets CISR; the
     * interrupt that adds the chunk may be held off by our mask. Read until
     * the CISR bit is the same on both sides of the count. */
    do {
        pending_before = (uint16_t)(TPU_CISR & (1u << ch));
        trans = TPU_PARAM(ch, 3);
        pending_after = (uint16_t)(TPU_CISR & (1u << ch));
    } while (pending_before != pending_after && --tries > 0u);
    if (tries == 0u) {
        k_arch_irq_restore(irq);
        return DRV_ERR_BUSY;        /* chunks completing faster than we can read */
    }
    *count = tpu_ch[ch].itc_base + trans + (pending_after ? TPU_ITC_CHUNK : 0u);
    k_arch_irq_restore(irq);
    return DRV_OK;
}

int tpu_itc_clear(unsigned ch)
{
    uint32_t irq;
    int r = tpu_check_mode(ch, TPU_MODE_ITC);
    if (r < 0)
        return r;
    irq = k_arch_irq_save();
    tpu_request(ch, 1u);
    TPU_CISR = (uint16_t)~(1u << ch);
    tpu_ch[ch].itc_base = 0;
    k_arch_irq_restore(irq);
    return DRV_OK;
}

/* ---- QDEC ---- */

static void tpu_qdec_channel(unsigned ch, unsigned partner, unsigned primary, unsigned hsq)
{
    tpu_function(ch, TPU_FN_QDEC, hsq);
    TPU_PARAM(ch, 0) = 0;
    TPU_PARAM(ch, 1) = 0;
    TPU_PARAM(ch, 4) = TPU_PARAM_ADDR(partner, 3);         /* CORR_PINSTATE_ADDR */
    TPU_PARAM(ch, 5) = (uint16_t)(TPU_PARAM_ADDR(primary, 0) + 1u); /* EDGE_TIME_LSB_ADDR */
    tpu_request(ch, 3u);                     /* init */
}

int tpu_qdec_start(unsigned primary_ch, unsigned secondary_ch)
{
    uint32_t irq;
    int r = tpu_check(primary_ch);
    if (r < 0)
        return r;
    if (secondary_ch >= TPU_CHANNELS || (board_tpu_reserved & (1u << secondary_ch)) != 0u ||
        secondary_ch == primary_ch)
        return DRV_ERR_CHANNEL;
    irq = k_arch_irq_save();
    tpu_leave_mode(primary_ch);
    tpu_leave_mode(secondary_ch);
    tpu_qdec_channel(primary_ch, secondary_ch, primary_ch, 0u);
    tpu_qdec_channel(secondary_ch, primary_ch, primary_ch, 1u);
    tpu_ch[primary_ch].mode = TPU_MODE_QDEC_PRIMARY;
    tpu_ch[primary_ch].partner = (uint8_t)secondary_ch;
    tpu_ch[primary_ch].qdec_last = 0;
    tpu_ch[primary_ch].qdec_pos = 0;
    tpu_ch[secondary_ch].mode = TPU_MODE_QDEC_SECONDARY;
    tpu_ch[secondary_ch].partner = (uint8_t)primary_ch;
    tpu_enable(primary_ch);
    tpu_enable(secondary_ch);
    k_arch_irq_restore(irq);
    return DRV_OK;
}

/* With the mask held: folds the 16-bit count into the 32-bit position. */
static int32_t tpu_qdec_fold(struct tpu_channel *c, uint16_t raw)
{
    c->qdec_pos += (int16_t)(uint16_t)(raw - c->qdec_last);
    c->qdec_last = raw;
    return c->qdec_pos;
}

int tpu_qdec_sample(unsigned primary_ch, int32_t *pos, uint16_t *edge_tcr1)
{
    uint32_t irq;
    uint16_t raw, again, edge;
    int32_t folded;
    unsigned tries = TPU_READ_TRIES;
    int r = tpu_check_mode(primary_ch, TPU_MODE_QDEC_PRIMARY);
    if (r < 0)
        return r;
    irq = k_arch_irq_save();
    /* The TPU updates count and edge time together, between our reads. */
    do {
        raw = TPU_PARAM(primary_ch, 1);
        edge = TPU_PARAM(primary_ch, 0);
        again = TPU_PARAM(primary_ch, 1);
    } while (raw != again && --tries > 0u);
    /* Fold even when the pair never held still: the position keeps up. */
    folded = tpu_qdec_fold(&tpu_ch[primary_ch], again);
    if (pos != NULL)
        *pos = folded;
    if (edge_tcr1 != NULL)
        *edge_tcr1 = edge;
    k_arch_irq_restore(irq);
    return tries == 0u ? DRV_ERR_BUSY : DRV_OK;
}

int tpu_qdec_position(unsigned primary_ch, int32_t *pos)
{
    if (pos == NULL)
        return DRV_ERR_PARAM;
    return tpu_qdec_sample(primary_ch, pos, NULL);
}

int tpu_qdec_set(unsigned primary_ch, int32_t pos)
{
    uint32_t irq;
    int r = tpu_check_mode(primary_ch, TPU_MODE_QDEC_PRIMARY);
    if (r < 0)
        return r;
    irq = k_arch_irq_save();
    tpu_ch[primary_ch].qdec_last = TPU_PARAM(primary_ch, 1);
    tpu_ch[primary_ch].qdec_pos = pos;
    k_arch_irq_restore(irq);
    return DRV_OK;
}

/* ---- interrupts, release ---- */

int tpu_attach_irq(unsigned ch, tpu_irq_fn fn, void *arg)
{
    uint32_t irq;
    int r = tpu_check(ch);
    if (r < 0)
        return r;
    irq = k_arch_irq_save();
    tpu_ch[ch].fn = fn;
    tpu_ch[ch].arg = arg;
    /* QDEC raises no interrupts; ITC needs its own. */
    if (tpu_ch[ch].mode != TPU_MODE_NONE && tpu_ch[ch].mode != TPU_MODE_ITC)
        tpu_irq_enable(ch, fn != NULL);
    k_arch_irq_restore(irq);
    return DRV_OK;
}

uint32_t tpu_irq_count(unsigned ch)
{
    return ch < TPU_CHANNELS ? tpu_ch[ch].irqs : 0u;
}

int tpu_release(unsigned ch)
{
    uint32_t irq;
    int r = tpu_check(ch);
    if (r < 0)
        return r;
    irq = k_arch_irq_save();
    tpu_leave_mode(ch);
    tpu_set_bits(&TPU_CFSR(ch), TPU_CFSR_SHIFT(ch), 0xFu, 0u);
    k_arch_irq_restore(irq);
    return DRV_OK;
}
