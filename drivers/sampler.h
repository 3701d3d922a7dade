/*
 * Sensor sampler: a kernel thread that refreshes every analog input (24),
 * binary I/O line (16) and binary input (IP1-IP5) at a fixed period into a
 * snapshot with a timestamp. Readers take the latest snapshot in O(1) without
 * touching the bus: sampler_read copies it with interrupts masked (about 60
 * bytes), so a copy is never half old, half new.
 *
 * One sweep is one I2C transaction per bus: the chip reads (one
 * auto-increment read per PCF8591, one read per PCF8574A) chained with
 * repeated STARTs. The thread only starts a sweep when it is due; the I2C
 * interrupt handler runs it and publishes the snapshot at its end, and starts
 * the next one at once when the period is shorter than a sweep.
 */
#ifndef DRIVERS_SAMPLER_H
#define DRIVERS_SAMPLER_H

#include <stdint.h>

#include "drivers/analog.h"

/* valid bits: bit i (0..23) analog input i; these for the others: */
#define SAMPLER_VALID_BIO0  (1ul << 24)   /* BIO0-7 */
#define SAMPLER_VALID_BIO1  (1ul << 25)   /* BIO8-15 */
#define SAMPLER_VALID_BININ (1ul << 26)
#define SAMPLER_VALID_ALL   0x07FFFFFFul

struct sensor_snapshot {
    uint32_t seq;             /* sweeps published so far (0: none yet) */
    uint32_t time_us;         /* when the sweep started: uptime in us (wraps ~71 min) */
    uint32_t ticks;           /* the same in kernel ticks */
    uint32_t sweep_us;        /* how long the sweep took (tick resolution) */
    uint8_t analog[ANALOG_INPUTS];
    uint16_t bio;             /* BIO0-15 levels */
    uint8_t binin;            /* IP1..IP5 as bits 0..4 */
    uint32_t valid;           /* which values this sweep read successfully */
    int8_t last_error;        /* the last failed read's DRV_ERR_* code, 0 if none */
};

/* Starts the sampler thread (priority SAMPLER_PRIO) with one sweep every
 * period_ms (1..60000); called again, changes the period (in effect within
 * 100 ms). A period shorter than a sweep (about 6 ms) means back to back. The chips must have
 * been probed (board_io_init). DRV_OK, DRV_ERR_RANGE. */
#define SAMPLER_PRIO 20u
int sampler_start(unsigned period_ms);
/* Stops sweeping after the current one (the last snapshot stays readable). */
void sampler_stop(void);

/* Copies the latest snapshot (seq 0 before the first sweep). O(1), any context. */
void sampler_read(struct sensor_snapshot *out);

/* Waits (bounded) for a sweep that starts now (or, if one is running, for
 * the next one) and copies it into *out; it is published like every sweep.
 * Returns the number of failed chip reads (0 = all valid; 8 if no sweep came
 * in time, which the I2C deadlines rule out). Thread context. */
int sampler_sweep(struct sensor_snapshot *out);

/* Sweeps that overran their period, and sweeps done. */
uint32_t sampler_overruns(void);

#endif /* DRIVERS_SAMPLER_H */
