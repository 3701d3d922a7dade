/*
 * I2C master on the board's two PCF8584 controllers, interrupt-driven.
 *
 * Each bus has a queue of transactions. A transaction is a write, a read, or
 * a write followed by a read after a repeated START (the usual "register
 * address, then data" access). The controller interrupts after every byte
 * (9 SCL clocks, 100 us at 90 kHz) and the interrupt handler moves the
 * transaction on and starts the next one in the queue, so the CPU never waits
 * on a byte and back-to-back transactions cost no thread switch.
 *
 * Every transaction ends with a status: DRV_OK, DRV_ERR_ABSENT (address or
 * data byte not acknowledged), DRV_ERR_ARB (arbitration lost), DRV_ERR_TIMEOUT
 * (bus held busy or a byte that never completed: the controller is reset).
 * A service thread watches the active transaction's deadline, so a stuck bus
 * ends every transaction with DRV_ERR_TIMEOUT, never a hang.
 *
 * Controller set-up as CubeOS (facts 5.4): own address 0x55 (bus A) / 0x56
 * (bus B), S2 = 0x1C (12 MHz clock input, 90 kHz SCL), interrupt vector in S3
 * (bus A: vector 27, level 3; bus B: vector 25, level 1, as the v2 GAL routes
 * them).
 */
#ifndef DRIVERS_I2C_H
#define DRIVERS_I2C_H

#include <stddef.h>
#include <stdint.h>

#include "drivers/drv_err.h"

#define I2C_BUS_A 0u        /* the I/O board: PCF8584 at 0xFFE200 */
#define I2C_BUS_B 1u        /* PCF8584 at 0xFFE000 */
#define I2C_BUS_COUNT 2u

/* Longest write or read part of one transaction, bytes (bounds a transaction's
 * duration and so its deadline). */
#define I2C_MAX_LEN 64u

/* Status of a transaction still queued or running. */
#define I2C_PENDING 1

struct i2c_xfer;
/* Called once when x has ended (x->status holds the result). Runs in the
 * controller's interrupt handler or in the I2C service thread: keep it short
 * (post a semaphore, set an event, submit another transaction). */
typedef void (*i2c_done_fn)(struct i2c_xfer *x, void *arg);

struct i2c_xfer {
    /* Set by the caller. */
    uint8_t addr7;            /* 7-bit device address */
    const uint8_t *wr;        /* bytes to write first (may be NULL if wr_len == 0) */
    size_t wr_len;
    uint8_t *rd;              /* then bytes to read (repeated START if wr_len > 0) */
    size_t rd_len;            /* wr_len == rd_len == 0: address only (a probe) */
    i2c_done_fn done;         /* may be NULL: poll status (a queue of several
                                 transactions may give a callback to the last
                                 one only: a bus runs its queue in order) */
    void *arg;
    /* Further messages of the same transaction, each after a repeated START
     * (to any address): one queue entry, one deadline, one callback for a
     * whole chain. A message that is not acknowledged does not end the chain:
     * its msg_status says so and the next message follows. Only the first
     * message's done/arg are used. NULL: a single message. */
    struct i2c_xfer *more;
    /* Owned by the driver while status == I2C_PENDING. */
    volatile int status;      /* I2C_PENDING, then DRV_OK or the first error of
                                 the transaction's messages */
    volatile int msg_status;  /* this message's own result */
    struct i2c_xfer *next;
    uint32_t deadline;        /* ticks allowed, then the tick by which it must end */
    uint8_t started;          /* the controller has begun it */
};

/* Resets and programs the bus's controller (detection test as Linux's
 * i2c-algo-pcf: S1 reads back 0x80 after reset) and attaches its interrupt.
 * DRV_OK, DRV_ERR_CHANNEL (no such bus), DRV_ERR_ABSENT (no controller).
 * Call from a thread after k_start; calling again resets the controller
 * (pending transactions end with DRV_ERR_TIMEOUT). */
int i2c_init(unsigned bus);

/* Queues x (async; with its chain x->more, at most I2C_MAX_CHAIN messages).
 * DRV_OK: x->done will be called exactly once. Otherwise the error
 * (DRV_ERR_CHANNEL, DRV_ERR_PARAM for lengths above I2C_MAX_LEN, a NULL buffer
 * or a chain too long, DRV_ERR_STATE before i2c_init, DRV_ERR_BUSY when x is
 * already queued) and done is not called. x must stay valid until done. */
#define I2C_MAX_CHAIN 16u
int i2c_submit(unsigned bus, struct i2c_xfer *x);

/* Blocking write-then-read; waits at most the transaction's deadline plus the
 * queue ahead of it (bounded; see I2C_WAIT_MS in i2c.c). DRV_OK or an error. */
int i2c_transfer(unsigned bus, uint8_t addr7, const uint8_t *wr, size_t wr_len,
                 uint8_t *rd, size_t rd_len);

/* Address-only transaction: DRV_OK if a device acknowledges addr7. */
int i2c_probe(unsigned bus, uint8_t addr7);

/* Probes 0x08..0x77; writes up to max acknowledging addresses to found (in
 * increasing order) and returns how many acknowledged (may exceed max), or a
 * negative error when the bus itself failed (timeout). */
int i2c_scan(unsigned bus, uint8_t *found, unsigned max);

/* Counters per bus, for reports and tests. */
struct i2c_stats {
    uint32_t done, absent, arb, timeouts, resets, interrupts, spurious;
};
int i2c_get_stats(unsigned bus, struct i2c_stats *out);

#endif /* DRIVERS_I2C_H */
