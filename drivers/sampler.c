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
#define SAMPLER_CHECK_SWEEPS 4u
#define SAMPLER_LOOK_MS 100u
#define SAMPLER_LOOK_TICKS ((SAMPLER_LOOK_MS * K_TICK_HZ + 999u) / 1000u)
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

/* One sweep at a time: the slots are static (a sweep does not clear them on
 * a stack) and sweep_in_flight guards them. */
static struct sweep_slot sweep_slots[SAMPLER_XFERS];
static struct k_mutex sweep_lock;    /* one blocking sampler_sweep caller at a time */
static struct k_sem sweep_done;      /* a sweep ended (posted while sweep_waiter) */
static uint8_t sweep_ready;
static volatile uint8_t sweep_in_flight, sweep_waiter;
static unsigned sweep_left;   /* chains still running + 1; written with interrupts masked */
static k_ticks_t sweep_start_tick;
static struct sensor_snapshot sweep_out;   /* built at the end of the sweep in flight */
static uint32_t sweep_failed_last;         /* failed reads of the last published sweep */
static k_ticks_t sweep_ticks_last = 1u;    /* how long the last sweep took, ticks (>= 1) */
/* When the thread's next sweep is due; read and written with interrupts masked. */
static k_ticks_t sampler_next;
/* The chains (one per bus) as built for the chip locations of these probe
 * generations; rebuilt when analog_init or bio_init probed again. */
static struct i2c_xfer *sweep_chain[I2C_BUS_COUNT];
static uint32_t sweep_analog_gen, sweep_bio_gen;
static uint8_t sweep_built;

static int sweep_begin(void);

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

/* Unpacks the slots into sweep_out and publishes it (interrupts masked). */
static void sweep_publish(void)
{
    struct sensor_snapshot *out = &sweep_out;
    uint8_t *dst = out->analog;
    uint32_t valid = SAMPLER_VALID_BININ, bit = 0xFul, failed = 0;
    int err = 0;

    /* Unpacked with no per-byte index arithmetic (this runs every sweep). */
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
    out->ticks = sweep_start_tick;
    out->time_us = ticks_to_us(sweep_start_tick);
    sweep_ticks_last = k_ticks() - sweep_start_tick + 1u;
    out->sweep_us = ticks_to_us(sweep_ticks_last - 1u);
    out->seq = sampler_latest.seq + 1u;
    sampler_latest = *out;
    sweep_failed_last = failed;
}

/* The sweep ended (the last chain's callback, or sweep_begin when nothing
 * could be queued; interrupts masked): publish, wake a blocking caller, and
 * start the thread's next sweep at once if it is already due, so sweeps at a
 * period shorter than a sweep run back to back without the thread. */
static void sweep_complete(int may_restart)
{
    sweep_publish();
    sweep_in_flight = 0;
    if (sweep_waiter)
        (void)k_sem_post(&sweep_done);
    if (may_restart && sampler_running && (int32_t)(k_ticks() - sampler_next) >= 0) {
        sampler_next += sampler_period_ticks;
        if ((int32_t)(k_ticks() - sampler_next) > 0) {
            sampler_overrun_count++;
            sampler_next = k_ticks() + sampler_period_ticks;
        }
        (void)sweep_begin();
    }
}

/* The last bus to finish ends the sweep: one wake-up (or none) per sweep, not
 * one per chip. Runs in the I2C handler or service thread, interrupts masked. */
static void sweep_xfer_done(struct i2c_xfer *x, void *arg)
{
    (void)x;
    (void)arg;
    if (--sweep_left == 0u)
        sweep_complete(1);
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

/* Starts a sweep: every bus's chain queued; it ends in sweep_complete.
 * DRV_OK, or DRV_ERR_BUSY while one is in flight. Thread or interrupt context. */
static int sweep_begin(void)
{
    uint32_t s = k_arch_irq_save();

    if (sweep_in_flight) {
        k_arch_irq_restore(s);
        return DRV_ERR_BUSY;
    }
    sweep_in_flight = 1;
    sweep_left = 1u;                     /* 1: no chain can end the sweep early */
    k_arch_irq_restore(s);

    if (!sweep_built || sweep_analog_gen != analog_generation() || sweep_bio_gen != bio_generation())
        sweep_build();
    sweep_start_tick = k_ticks();
    sweep_out.binin = binin_read_all();  /* the binary inputs while the bus works */
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
        sweep_complete(0);               /* nothing queued, or all ended already */
    k_arch_irq_restore(s);
    return DRV_OK;
}

int sampler_sweep(struct sensor_snapshot *out)
{
    k_ticks_t t0 = k_ticks(), deadline = t0 + SAMPLER_WAIT_TICKS;
    int failed = (int)SAMPLER_XFERS;
    uint32_t s;

    sweep_init_once();
    if (k_mutex_lock_ticks(&sweep_lock, SAMPLER_WAIT_TICKS) != K_OK)
        return failed;
    s = k_arch_irq_save();
    sweep_waiter = 1;
    k_arch_irq_restore(s);
    (void)k_sem_trywait(&sweep_done);            /* a post from an earlier sweep */
    /* Wait for a sweep that started at or after t0: start one, or let the one
     * in flight (the thread's) end and start ours. Every sweep ends by the
     * I2C deadlines, so this loop ends long before `deadline`. */
    for (;;) {
        s = k_arch_irq_save();
        if (sampler_latest.seq != 0 && (int32_t)(sampler_latest.ticks - t0) >= 0) {
            *out = sampler_latest;
            failed = (int)sweep_failed_last;
            k_arch_irq_restore(s);
            break;
        }
        k_arch_irq_restore(s);
        if ((int32_t)(k_ticks() - deadline) >= 0)
            break;
        (void)sweep_begin();                     /* DRV_ERR_BUSY: one is in flight */
        (void)k_sem_wait_ticks(&sweep_done, deadline - k_ticks());
    }
    s = k_arch_irq_save();
    sweep_waiter = 0;
    k_arch_irq_restore(s);
    (void)k_mutex_unlock(&sweep_lock);
    return failed;
}

void sampler_read(struct sensor_snapshot *out)
{
    uint32_t st = k_arch_irq_save();
    *out = sampler_latest;
    k_arch_irq_restore(st);
}

/* Starts each sweep when it is due; the sweep itself runs in the I2C
 * interrupt handler and publishes from there (no wake-up at its end). */
static void *sampler_main(void *arg)
{
    (void)arg;
    sweep_init_once();
    for (;;) {
        k_ticks_t wake;
        uint32_t s;
        while (!sampler_running)
            (void)k_sleep_ticks(k_ms_to_ticks(10u));
        s = k_arch_irq_save();
        if ((int32_t)(k_ticks() - sampler_next) >= 0 && !sweep_in_flight) {
            sampler_next += sampler_period_ticks;
            if ((int32_t)(k_ticks() - sampler_next) > 0) {
                sampler_overrun_count++;     /* late: from now on, do not catch up */
                sampler_next = k_ticks() + sampler_period_ticks;
            }
            k_arch_irq_restore(s);
            (void)sweep_begin();
            s = k_arch_irq_save();
        }
        /* In flight and due: sweep_complete starts the next one itself (back
         * to back while the period is shorter than a sweep), so the thread
         * only looks again after a few sweeps' time, in case the chain of
         * sweeps stopped (sampler_stop, then sampler_start). */
        wake = sampler_next;
        if ((int32_t)(wake - k_ticks()) <= 0)
            wake = k_ticks() + SAMPLER_CHECK_SWEEPS *
                   (sampler_period_ticks > sweep_ticks_last ? sampler_period_ticks : sweep_ticks_last);
        /* A new period (sampler_start) takes effect within SAMPLER_LOOK_MS. */
        if ((int32_t)(wake - (k_ticks() + SAMPLER_LOOK_TICKS)) > 0)
            wake = k_ticks() + SAMPLER_LOOK_TICKS;
        k_arch_irq_restore(s);
        (void)k_sleep_until(wake);
    }
    return NULL;
}

int sampler_start(unsigned period_ms)
{
    uint32_t s;
    if (period_ms < 1u || period_ms > SAMPLER_PERIOD_MAX_MS)
        return DRV_ERR_RANGE;
    s = k_arch_irq_save();
    sampler_period_ticks = k_ms_to_ticks(period_ms);
    sampler_next = k_ticks();
    sampler_running = 1;
    k_arch_irq_restore(s);
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
