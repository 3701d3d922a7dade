/*
 * Sensor sampler (see sampler.h). A sweep submits every chip read at once
 * and waits for all of them on one counting semaphore; the I2C interrupt
 * handler runs them back to back, so a sweep costs the thread one wake-up.
 */
#include "drivers/sampler.h"

#include "drivers/bio.h"
#include "drivers/binin.h"
#include "drivers/drv_err.h"
#include "drivers/i2c.h"
#include "kernel.h"

#define SAMPLER_STACK 1024u
#define SAMPLER_XFERS (ANALOG_CHIPS + BIO_CHIPS)
/* Longest wait for one sweep's transactions: every one ends by its deadline
 * (a few ms, i2c.c), this only guards against a starved service thread. */
#define SAMPLER_WAIT_MS 500u
#define SAMPLER_PERIOD_MAX_MS 60000u

static struct sensor_snapshot sampler_latest;
static struct k_thread sampler_thread;
K_STACK_DEFINE(sampler_stack, SAMPLER_STACK);
static volatile uint32_t sampler_period_ticks;
static volatile uint8_t sampler_running, sampler_created;
static uint32_t sampler_overrun_count;

struct sweep_slot {
    struct i2c_xfer x;
    uint8_t control;
    uint8_t rd[ANALOG_CHIP_READ_LEN];
};

static void sweep_done(struct i2c_xfer *x, void *arg)
{
    (void)x;
    (void)k_sem_post(arg);
}

static uint32_t ticks_to_us(k_ticks_t t)
{
    return (uint32_t)(((uint64_t)t * 1000000u) / K_TICK_HZ);
}

int sampler_sweep(struct sensor_snapshot *out)
{
    struct sweep_slot slot[SAMPLER_XFERS];
    struct k_sem done;
    unsigned submitted = 0, failed = 0;
    k_ticks_t start = k_ticks();

    (void)k_sem_init(&done, 0u, SAMPLER_XFERS);
    out->valid = 0;
    out->last_error = 0;
    for (unsigned i = 0; i < SAMPLER_XFERS; i++) {
        struct sweep_slot *s = &slot[i];
        unsigned bus;
        uint8_t addr;
        int rc;
        s->x = (struct i2c_xfer){ .done = sweep_done, .arg = &done };
        if (i < ANALOG_CHIPS) {
            rc = analog_chip_location(i, &bus, &addr, &s->control);
            s->x.wr = &s->control;
            s->x.wr_len = 1;
            s->x.rd_len = ANALOG_CHIP_READ_LEN;
        } else {
            rc = bio_chip_location(i - ANALOG_CHIPS, &bus, &addr);
            s->x.rd_len = 1;
        }
        s->x.addr7 = addr;
        s->x.rd = s->rd;
        if (rc == DRV_OK)
            rc = i2c_submit(bus, &s->x);
        if (rc == DRV_OK) {
            submitted++;
        } else {
            s->x.status = rc;
        }
    }
    /* Binary inputs while the bus works. */
    out->binin = binin_read_all();
    out->valid |= SAMPLER_VALID_BININ;
    for (unsigned i = 0; i < submitted; i++) {
        if (k_sem_wait_ticks(&done, k_ms_to_ticks(SAMPLER_WAIT_MS)) != K_OK)
            break;
    }
    for (unsigned i = 0; i < SAMPLER_XFERS; i++) {
        struct sweep_slot *s = &slot[i];
        if (s->x.status == I2C_PENDING) {
            /* Not ended in time: wait for the I2C deadline to end it, since
             * the slot lives on this stack. */
            while (s->x.status == I2C_PENDING)
                (void)k_sleep_ticks(1u);
        }
        if (s->x.status != DRV_OK) {
            failed++;
            out->last_error = (int8_t)s->x.status;
            continue;
        }
        if (i < ANALOG_CHIPS) {
            for (unsigned k = 0; k < 4u; k++)
                out->analog[4u * i + k] = s->rd[k + 1u];
            out->valid |= 0xFul << (4u * i);
        } else {
            unsigned c = i - ANALOG_CHIPS;
            out->bio = (uint16_t)((out->bio & ~(0xFFu << (8u * c))) | ((unsigned)s->rd[0] << (8u * c)));
            out->valid |= SAMPLER_VALID_BIO0 << c;
        }
    }
    out->ticks = start;
    out->time_us = ticks_to_us(start);
    out->sweep_us = ticks_to_us(k_ticks() - start);
    return (int)failed;
}

static void publish(const struct sensor_snapshot *s)
{
    uint32_t st = k_arch_irq_save();
    uint32_t seq = sampler_latest.seq + 1u;
    sampler_latest = *s;
    sampler_latest.seq = seq;
    k_arch_irq_restore(st);
}

void sampler_read(struct sensor_snapshot *out)
{
    uint32_t st = k_arch_irq_save();
    *out = sampler_latest;
    k_arch_irq_restore(st);
}

static void *sampler_main(void *arg)
{
    struct sensor_snapshot snap = { 0 };
    k_ticks_t next = k_ticks();
    (void)arg;
    for (;;) {
        while (!sampler_running)
            (void)k_sleep_ticks(k_ms_to_ticks(10u));
        (void)sampler_sweep(&snap);
        publish(&snap);
        next += sampler_period_ticks;
        if ((int32_t)(k_ticks() - next) > 0) {
            sampler_overrun_count++;
            next = k_ticks();      /* late: start again from now, do not catch up */
        }
        (void)k_sleep_until(next);
    }
    return NULL;
}

int sampler_start(unsigned period_ms)
{
    if (period_ms < 1u || period_ms > SAMPLER_PERIOD_MAX_MS)
        return DRV_ERR_RANGE;
    sampler_period_ticks = k_ms_to_ticks(period_ms);
    sampler_running = 1;
    if (!sampler_created) {
        sampler_created = 1;
        if (k_thread_create(&sampler_thread, "sampler", sampler_main, NULL, sampler_stack,
                            sizeof(sampler_stack), SAMPLER_PRIO) != K_OK) {
            sampler_created = 0;
            return DRV_ERR_STATE;
        }
    }
    return DRV_OK;
}

void sampler_stop(void)
{
    sampler_running = 0;
}

uint32_t sampler_overruns(void)
{
    return sampler_overrun_count;
}
