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
#define SAMPLER_WAIT_TICKS ((SAMPLER_WAIT_MS * K_TICK_HZ + 999u) / 1000u)

static struct sensor_snapshot sampler_latest;
static struct k_thread sampler_thread;
K_STACK_DEFINE(sampler_stack, SAMPLER_STACK);
static volatile uint32_t sampler_period_ticks;
static volatile uint8_t sampler_running, sampler_created;
static uint32_t sampler_overrun_count;

struct sweep_slot {
    struct i2c_xfer x;
    uint8_t rd[ANALOG_CHIP_READ_LEN];
};

/* One sweep at a time (the sampler thread, or a measurement while it is
 * stopped): the slots are static so a sweep does not clear them on a stack. */
static struct sweep_slot sweep_slots[SAMPLER_XFERS];
static struct k_mutex sweep_lock;
static struct k_sem sweep_done;
static uint8_t sweep_ready;
static unsigned sweep_left;   /* transactions still running; written with interrupts masked */
/* The chains (one per bus) as built for the chip locations of these probe
 * generations; rebuilt when analog_init or bio_init probed again. */
static struct i2c_xfer *sweep_chain[I2C_BUS_COUNT];
static uint32_t sweep_analog_gen, sweep_bio_gen;
static uint8_t sweep_built;

/* The last bus to finish wakes the sweeping thread: one wake-up per sweep,
 * not one per chip. Runs in the I2C handler or service thread. */
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

/* Builds one chain of messages per bus: the chips' reads linked with
 * repeated STARTs (i2c.h, `more`), so a sweep costs one queue entry, one
 * start and one completion per bus instead of one per chip. A chip not found
 * gets its error as msg_status and no message. */
static void sweep_build(void)
{
    struct i2c_xfer *tail[I2C_BUS_COUNT] = { NULL };

    for (unsigned b = 0; b < I2C_BUS_COUNT; b++)
        sweep_chain[b] = NULL;
    for (unsigned i = 0; i < SAMPLER_XFERS; i++) {
        struct sweep_slot *sl = &sweep_slots[i];
        unsigned bus = 0;
        uint8_t addr = 0;
        const uint8_t *control = NULL;
        int rc;
        sl->x = (struct i2c_xfer){ .rd = sl->rd };
        if (i < ANALOG_CHIPS) {
            rc = analog_chip_location(i, &bus, &addr, &control);
            sl->x.wr = control;
            sl->x.wr_len = 1;
            sl->x.rd_len = ANALOG_CHIP_READ_LEN;
        } else {
            rc = bio_chip_location(i - ANALOG_CHIPS, &bus, &addr);
            sl->x.rd_len = 1;
        }
        sl->x.addr7 = addr;
        sl->x.msg_status = rc;
        if (rc != DRV_OK)
            continue;
        if (tail[bus] != NULL)
            tail[bus]->more = &sl->x;
        else
            sweep_chain[bus] = &sl->x;
        tail[bus] = &sl->x;
    }
    sweep_analog_gen = analog_generation();
    sweep_bio_gen = bio_generation();
    sweep_built = 1;
}

/* Queues every bus's chain; the last bus to finish posts sweep_done. */
static void sweep_submit(void)
{
    uint32_t s;

    if (!sweep_built || sweep_analog_gen != analog_generation() || sweep_bio_gen != bio_generation())
        sweep_build();
    sweep_left = 1u;                     /* 1: none can finish the count early */
    for (unsigned bus = 0; bus < I2C_BUS_COUNT; bus++) {
        struct i2c_xfer *x = sweep_chain[bus];
        int rc;
        if (x == NULL)
            continue;
        x->done = sweep_xfer_done;
        x->status = 0;
        x->next = NULL;
        s = k_arch_irq_save();
        sweep_left++;
        k_arch_irq_restore(s);
        rc = i2c_submit(bus, x);
        if (rc != DRV_OK) {
            for (struct i2c_xfer *m = x; m != NULL; m = m->more)
                m->msg_status = rc;
            s = k_arch_irq_save();
            sweep_left--;
            k_arch_irq_restore(s);
        }
    }
    s = k_arch_irq_save();
    if (--sweep_left == 0u)
        (void)k_sem_post(&sweep_done);
    k_arch_irq_restore(s);
}

int sampler_sweep(struct sensor_snapshot *out)
{
    unsigned failed = 0;
    k_ticks_t start;

    sweep_init_once();
    if (k_mutex_lock_ticks(&sweep_lock, SAMPLER_WAIT_TICKS) != K_OK)
        return (int)SAMPLER_XFERS;
    start = k_ticks();
    (void)k_sem_trywait(&sweep_done);            /* a stale post from a given-up sweep */
    sweep_submit();
    /* Binary inputs while the bus works. */
    out->binin = binin_read_all();
    out->valid = SAMPLER_VALID_BININ;
    out->last_error = 0;
    if (k_sem_wait_ticks(&sweep_done, SAMPLER_WAIT_TICKS) != K_OK) {
        /* Only if the I2C service thread is starved: every transaction ends by
         * its deadline, and the slots must not be reused before. */
        for (unsigned i = 0; i < SAMPLER_XFERS; i++) {
            while (sweep_slots[i].x.msg_status == I2C_PENDING)
                (void)k_sleep_ticks(1u);
        }
    }
    {
        /* Unpacked with no per-byte index arithmetic (this runs every sweep). */
        uint8_t *dst = out->analog;
        uint32_t valid = out->valid, bit = 0xFul;
        int err = 0;
        for (unsigned i = 0; i < ANALOG_CHIPS; i++, dst += 4, bit <<= 4) {
            const struct sweep_slot *sl = &sweep_slots[i];
            if (sl->x.msg_status != DRV_OK) {
                err = sl->x.msg_status;
                failed++;
                continue;
            }
            dst[0] = sl->rd[1];              /* rd[0]: the previous conversion */
            dst[1] = sl->rd[2];
            dst[2] = sl->rd[3];
            dst[3] = sl->rd[4];
            valid |= bit;
        }
        for (unsigned c = 0; c < BIO_CHIPS; c++) {
            const struct sweep_slot *sl = &sweep_slots[ANALOG_CHIPS + c];
            if (sl->x.msg_status != DRV_OK) {
                err = sl->x.msg_status;
                failed++;
                continue;
            }
            if (c == 0)
                out->bio = (uint16_t)((out->bio & 0xFF00u) | sl->rd[0]);
            else
                out->bio = (uint16_t)((out->bio & 0x00FFu) | ((unsigned)sl->rd[0] << 8));
            valid |= SAMPLER_VALID_BIO0 << c;
        }
        out->valid = valid;
        out->last_error = (int8_t)err;
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
