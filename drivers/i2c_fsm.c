/*
 * PCF8584 master state machine (see i2c_fsm.h). The sequences follow the
 * PCF8584 data sheet and Linux's i2c-algo-pcf: START = address into S0, then
 * S1 = START; repeated START = S1 without PIN, then the address into S0;
 * reception: a dummy read of S0 starts the first byte; the byte before the
 * last is read after clearing ACK (so the last byte is not acknowledged); the
 * last byte is read after STOP (so no further byte is clocked).
 */
#include "drivers/i2c_fsm.h"

#include <stddef.h>

int i2c_fsm_reset(struct i2c_fsm *f, uint8_t own_addr, uint8_t vector)
{
    f->x = NULL;
    f->state = I2C_FSM_IDLE;
    f->need_reset = 0;
    I2C_FSM_WR(f, PCF_S1, PCF_CTL_RESET);        /* serial interface off, S0' selected */
    if (I2C_FSM_RD(f, PCF_S1) != PCF_CTL_RESET)  /* control bits read back */
        return -1;
    I2C_FSM_WR(f, PCF_S0, own_addr);
    I2C_FSM_WR(f, PCF_S1, PCF_PIN | PCF_ES1);    /* S2: clock */
    I2C_FSM_WR(f, PCF_S0, PCF_S2_12MHZ_90KHZ);
    I2C_FSM_WR(f, PCF_S1, PCF_PIN | PCF_ES2);    /* S3: interrupt vector */
    I2C_FSM_WR(f, PCF_S0, vector);
    I2C_FSM_WR(f, PCF_S1, PCF_CTL_IDLE);
    return 0;
}

static enum i2c_fsm_event finish(struct i2c_fsm *f, int status, int need_reset)
{
    struct i2c_xfer *x = f->x;
    f->x = NULL;
    f->state = I2C_FSM_IDLE;
    f->need_reset = (uint8_t)need_reset;
    x->status = status;
    return I2C_FSM_DONE;
}

/* Ends the transaction with STOP (the normal end, and after a NACK). */
static enum i2c_fsm_event stop(struct i2c_fsm *f, int status)
{
    I2C_FSM_WR(f, PCF_S1, PCF_CTL_STOP);
    return finish(f, status, 0);
}

/* START or repeated START with the read address. */
static void begin_read(struct i2c_fsm *f, int repeated)
{
    f->state = I2C_FSM_ADDR_R;
    if (repeated) {
        I2C_FSM_WR(f, PCF_S1, PCF_CTL_REPSTART);
        I2C_FSM_WR(f, PCF_S0, (uint8_t)((f->x->addr7 << 1) | 1u));
    } else {
        I2C_FSM_WR(f, PCF_S0, (uint8_t)((f->x->addr7 << 1) | 1u));
        I2C_FSM_WR(f, PCF_S1, PCF_CTL_START);
    }
}

enum i2c_fsm_event i2c_fsm_start(struct i2c_fsm *f, struct i2c_xfer *x)
{
    if (!(I2C_FSM_RD(f, PCF_S1) & PCF_ST_BB))
        return I2C_FSM_BUS_BUSY;
    f->x = x;
    f->need_reset = 0;
    f->wp = x->wr;
    f->wr_end = x->wr_len > 0 ? x->wr + x->wr_len : x->wr;
    f->rp = x->rd;
    f->rd_fast_end = x->rd_len >= 2u ? x->rd + (x->rd_len - 2u) : x->rd;
    if (x->wr_len == 0 && x->rd_len > 0) {
        begin_read(f, 0);
    } else {
        f->state = I2C_FSM_DATA_W;
        I2C_FSM_WR(f, PCF_S0, (uint8_t)(x->addr7 << 1));
        I2C_FSM_WR(f, PCF_S1, PCF_CTL_START);
    }
    return I2C_FSM_RUNNING;
}

enum i2c_fsm_event i2c_fsm_step(struct i2c_fsm *f, uint8_t st)
{
    struct i2c_xfer *x = f->x;

    if (x == NULL)
        return I2C_FSM_SPURIOUS;
    if (st & (PCF_ST_PIN | PCF_ST_LAB | PCF_ST_BER)) {
        if (st & PCF_ST_PIN)      /* byte not done: not ours */
            return I2C_FSM_SPURIOUS;
        if (st & PCF_ST_LAB)      /* another master won: we no longer drive the bus */
            return finish(f, DRV_ERR_ARB, 1);
        return finish(f, DRV_ERR_TIMEOUT, 1);   /* BER: misplaced START/STOP on the bus */
    }

    switch (f->state) {
    case I2C_FSM_DATA_W:
        if (st & PCF_ST_LRB)
            return stop(f, DRV_ERR_ABSENT);
        if (f->wp < f->wr_end) {
            I2C_FSM_WR(f, PCF_S0, *f->wp++);
            return I2C_FSM_RUNNING;
        }
        if (x->rd_len > 0) {
            begin_read(f, 1);
            return I2C_FSM_RUNNING;
        }
        return stop(f, DRV_OK);
    case I2C_FSM_ADDR_R:
        if (st & PCF_ST_LRB)
            return stop(f, DRV_ERR_ABSENT);
        f->state = I2C_FSM_DATA_R;
        if (x->rd_len == 1)
            I2C_FSM_WR(f, PCF_S1, PCF_CTL_NACK);   /* the only byte is the last */
        (void)I2C_FSM_RD(f, PCF_S0);               /* dummy read: clocks in byte 0 */
        return I2C_FSM_RUNNING;
    case I2C_FSM_DATA_R:
        if (f->rp + 1 >= x->rd + x->rd_len) {
            I2C_FSM_WR(f, PCF_S1, PCF_CTL_STOP);   /* before the read: no more clocks */
            *f->rp = I2C_FSM_RD(f, PCF_S0);
            return finish(f, DRV_OK, 0);
        }
        if (f->rp + 2 == x->rd + x->rd_len)
            I2C_FSM_WR(f, PCF_S1, PCF_CTL_NACK);   /* the next byte is the last */
        *f->rp++ = I2C_FSM_RD(f, PCF_S0);
        return I2C_FSM_RUNNING;
    default:
        return I2C_FSM_SPURIOUS;
    }
}

struct i2c_xfer *i2c_fsm_abort(struct i2c_fsm *f)
{
    struct i2c_xfer *x = f->x;
    if (x != NULL)
        (void)finish(f, DRV_ERR_TIMEOUT, 1);
    return x;
}
