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

/* One sweep at a time (the sampler thread, or a measurement while it is
 * stopped): the slots are static so a sweep does not clear them on a stack. */
static struct sweep_slot sweep_slots[SAMPLER_XFERS];
static struct k_mutex sweep_lock;
static struct k_sem sweep_done;
static uint8_t sweep_ready;
static unsigned sweep_left;   /* transactions still running; written with interrupts masked */

/* The last transaction of a sweep wakes the sweeping thread: one wake-up per
 * sweep, not one per chip. Runs in the I2C handler or service thread. */
static void sweep_xfer_done(struct i2c_xfer *x, void *arg)
{
    (void)x;
    (void)arg;
    if (--sweep_left == 0u)
        (void)k_sem_post(&sweep_done);
}

/* In 32 bits (a 64-bit division costs hundreds of instructions on the CPU32). */
static uint32_t ticks_to_us(k_ticks_t t)
{
    return (t / K_TICK_HZ) * 1000000u + ((t % K_TICK_HZ) * 1000000u) / K_TICK_HZ;
}

static void sweep_init_once(void)
{
    uint32_t s = k_arch_irq_save();
    if (!sweep_ready) {
        (void)k_mutex_init(&sweep_lock);
        (void)k_sem_init(&sweep_done, 0u, 1u);
        sweep_ready = 1;
    }
    k_arch_irq_restore(s);
}

/* Fills and submits every slot; returns how many are running. A bus runs its
 * queue in order, so only the last slot queued on each bus gets the callback
 * (the others end without any kernel call in the interrupt handler). */
static unsigned sweep_submit(void)
{
    unsigned running = 0, bus_of[SAMPLER_XFERS];
    int last_on_bus[I2C_BUS_COUNT];
    uint32_t s;

    for (unsigned b = 0; b < I2C_BUS_COUNT; b++)
        last_on_bus[b] = -1;
    for (unsigned i = 0; i < SAMPLER_XFERS; i++) {
        struct sweep_slot *sl = &sweep_slots[i];
        uint8_t addr = 0;
        int rc;
        sl->x.rd = sl->rd;
        sl->x.next = NULL;
        sl->x.done = NULL;
        if (i < ANALOG_CHIPS) {
            rc = analog_chip_location(i, &bus_of[i], &addr, &sl->control);
            sl->x.wr = &sl->control;
            sl->x.wr_len = 1;
            sl->x.rd_len = ANALOG_CHIP_READ_LEN;
        } else {
            rc = bio_chip_location(i - ANALOG_CHIPS, &bus_of[i], &addr);
            sl->x.wr = NULL;
            sl->x.wr_len = 0;
            sl->x.rd_len = 1;
        }
        sl->x.addr7 = addr;
        sl->x.status = rc;               /* not I2C_PENDING: not queued yet */
        if (rc == DRV_OK)
            last_on_bus[bus_of[i]] = (int)i;
    }
    sweep_left = 1u;                     /* 1: none can finish the count early */
    for (unsigned b = 0; b < I2C_BUS_COUNT; b++) {
        if (last_on_bus[b] >= 0) {
            sweep_slots[last_on_bus[b]].x.done = sweep_xfer_done;
            sweep_left++;
        }
    }
    for (unsigned i = 0; i < SAMPLER_XFERS; i++) {
        struct sweep_slot *sl = &sweep_slots[i];
        int rc;
        if (sl->x.status != DRV_OK)
            continue;
        rc = i2c_submit(bus_of[i], &sl->x);
        if (rc == DRV_OK) {
            running++;
        } else {
            sl->x.status = rc;
            if (sl->x.done != NULL) {    /* its bus' callback will not come */
                s = k_arch_irq_save();
                sweep_left--;
                k_arch_irq_restore(s);
            }
        }
    }
    s = k_arch_irq_save();
    if (--sweep_left == 0u)
        (void)k_sem_post(&sweep_done);
    k_arch_irq_restore(s);
    return running;
}

int sampler_sweep(struct sensor_snapshot *out)
{
    unsigned failed = 0;
    k_ticks_t start;

    sweep_init_once();
    if (k_mutex_lock_ticks(&sweep_lock, k_ms_to_ticks(SAMPLER_WAIT_MS)) != K_OK)
        return (int)SAMPLER_XFERS;
    start = k_ticks();
    (void)k_sem_trywait(&sweep_done);            /* a stale post from a given-up sweep */
    (void)sweep_submit();
    /* Binary inputs while the bus works. */
    out->binin = binin_read_all();
    out->valid = SAMPLER_VALID_BININ;
    out->last_error = 0;
    if (k_sem_wait_ticks(&sweep_done, k_ms_to_ticks(SAMPLER_WAIT_MS)) != K_OK) {
        /* Only if the I2C service thread is starved: every transaction ends by
         * its deadline, and the slots must not be reused before. */
        for (unsigned i = 0; i < SAMPLER_XFERS; i++) {
            while (sweep_slots[i].x.status == I2C_PENDING)
                (void)k_sleep_ticks(1u);
        }
    }
    for (unsigned i = 0; i < SAMPLER_XFERS; i++) {
        const struct sweep_slot *sl = &sweep_slots[i];
        if (sl->x.status != DRV_OK) {
            failed++;
            out->last_error = (int8_t)sl->x.status;
            continue;
        }
        if (i < ANALOG_CHIPS) {
            for (unsigned k = 0; k < 4u; k++)
                out->analog[4u * i + k] = sl->rd[k + 1u];
            out->valid |= 0xFul << (4u * i);
        } else {
            unsigned c = i - ANALOG_CHIPS;
            out->bio = (uint16_t)((out->bio & ~(0xFFu << (8u * c))) | ((unsigned)sl->rd[0] << (8u * c)));
            out->valid |= SAMPLER_VALID_BIO0 << c;
        }
    }
    out->ticks = start;
    out->time_us = ticks_to_us(start);
    out->sweep_us = ticks_to_us(k_ticks() - start);
    (void)k_mutex_unlock(&sweep_lock);
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
