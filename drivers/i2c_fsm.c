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
    f->m = NULL;
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

/* Ends the transaction (all its messages done or abandoned). */
static enum i2c_fsm_event finish(struct i2c_fsm *f, int status, int need_reset)
{
    struct i2c_xfer *x = f->x;
    f->x = NULL;
    f->m = NULL;
    f->state = I2C_FSM_IDLE;
    f->need_reset = (uint8_t)need_reset;
    x->status = status;
    return I2C_FSM_DONE;
}

/* The bus is lost (arbitration, bus error, deadline): the message on the wire
 * and the ones after it end with err, and so does the transaction. */
static enum i2c_fsm_event fail_all(struct i2c_fsm *f, int err)
{
    for (struct i2c_xfer *m = f->m; m != NULL; m = m->more)
        m->msg_status = err;
    return finish(f, err, 1);
}

/* The message on the wire is over with status. last: where the last byte of
 * a read goes (read after the STOP or repeated START is set up, so no further
 * byte is clocked), or NULL. Then the next message of the chain after a
 * repeated START, or STOP and the end of the transaction. */
static inline __attribute__((always_inline)) enum i2c_fsm_event msg_done(struct i2c_fsm *f, int status, uint8_t *last)
{
    struct i2c_xfer *m = f->m, *next = m->more;
    m->msg_status = status;
    if (status != DRV_OK && f->first_err == DRV_OK)
        f->first_err = status;
    I2C_FSM_WR(f, PCF_S1, next != NULL ? PCF_CTL_REPSTART : PCF_CTL_STOP);
    if (last != NULL)
        *last = I2C_FSM_RD(f, PCF_S0);
    if (next != NULL) {
        i2c_fsm_send_address(f, next);
        return I2C_FSM_RUNNING;
    }
    return finish(f, f->first_err, 0);
}

enum i2c_fsm_event i2c_fsm_start(struct i2c_fsm *f, struct i2c_xfer *x)
{
    if (!(I2C_FSM_RD(f, PCF_S1) & PCF_ST_BB))
        return I2C_FSM_BUS_BUSY;
    f->x = x;
    f->need_reset = 0;
    f->first_err = DRV_OK;
    i2c_fsm_send_address(f, x);
    I2C_FSM_WR(f, PCF_S1, PCF_CTL_START);
    return I2C_FSM_RUNNING;
}

enum i2c_fsm_event i2c_fsm_step(struct i2c_fsm *f, uint8_t st)
{
    struct i2c_xfer *m = f->m;

    if (f->x == NULL)
        return I2C_FSM_SPURIOUS;
    if (st & (PCF_ST_PIN | PCF_ST_LAB | PCF_ST_BER)) {
        if (st & PCF_ST_PIN)      /* byte not done: not ours */
            return I2C_FSM_SPURIOUS;
        if (st & PCF_ST_LAB)      /* another master won: we no longer drive the bus */
            return fail_all(f, DRV_ERR_ARB);
        return fail_all(f, DRV_ERR_TIMEOUT);   /* BER: misplaced START/STOP on the bus */
    }

    switch (f->state) {
    case I2C_FSM_DATA_W:
        if (st & PCF_ST_LRB)
            return msg_done(f, DRV_ERR_ABSENT, NULL);
        if (f->wp < f->wr_end) {
            I2C_FSM_WR(f, PCF_S0, *f->wp++);
            return I2C_FSM_RUNNING;
        }
        if (m->rd_len > 0) {      /* the read part, after a repeated START */
            f->state = I2C_FSM_ADDR_R;
            I2C_FSM_WR(f, PCF_S1, PCF_CTL_REPSTART);
            I2C_FSM_WR(f, PCF_S0, (uint8_t)((m->addr7 << 1) | 1u));
            return I2C_FSM_RUNNING;
        }
        return msg_done(f, DRV_OK, NULL);
    case I2C_FSM_ADDR_R:
        if (st & PCF_ST_LRB)
            return msg_done(f, DRV_ERR_ABSENT, NULL);
        f->state = I2C_FSM_DATA_R;
        if (m->rd_len == 1)
            I2C_FSM_WR(f, PCF_S1, PCF_CTL_NACK);   /* the only byte is the last */
        (void)I2C_FSM_RD(f, PCF_S0);               /* dummy read: clocks in byte 0 */
        return I2C_FSM_RUNNING;
    case I2C_FSM_DATA_R:
        if (f->rp + 1 >= m->rd + m->rd_len)
            return msg_done(f, DRV_OK, f->rp);
        if (f->rp + 2 == m->rd + m->rd_len)
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
        (void)fail_all(f, DRV_ERR_TIMEOUT);
    return x;
}
