/*
 * The PCF8584 master transaction state machine (pure logic, no kernel): it
 * starts a transaction and, on every controller interrupt, reads the status,
 * moves data and decides the next register write. The interrupt handler and
 * queue live in i2c.c; the host tests (drivers/tests/) run this file against a
 * scripted fake controller.
 *
 * Register access goes through I2C_FSM_RD / I2C_FSM_WR: volatile byte
 * accesses at f->base on the target; the host tests build with
 * -DI2C_FSM_FAKE_HW and provide i2c_fake_rd / i2c_fake_wr.
 */
#ifndef DRIVERS_I2C_FSM_H
#define DRIVERS_I2C_FSM_H

#include <stdint.h>

#include "drivers/i2c.h"

/* Registers: A0 = 0 S0 (data / own address / clock / vector per ES bits),
 * A0 = 1 S1 (control on write, status on read). */
#define PCF_S0 0u
#define PCF_S1 1u

/* S1 control bits. */
#define PCF_PIN 0x80u
#define PCF_ES0 0x40u
#define PCF_ES1 0x20u
#define PCF_ES2 0x10u
#define PCF_ENI 0x08u
#define PCF_STA 0x04u
#define PCF_STO 0x02u
#define PCF_ACK 0x01u
/* S1 status bits (ES0 = 1). */
#define PCF_ST_PIN 0x80u
#define PCF_ST_BER 0x10u
#define PCF_ST_LRB 0x08u
#define PCF_ST_LAB 0x02u
#define PCF_ST_BB  0x01u   /* 1 = bus free (the bit is "not busy") */

/* Control words (CubeOS values, facts 5.4). */
#define PCF_CTL_IDLE   (PCF_PIN | PCF_ES0 | PCF_ENI | PCF_ACK)            /* 0xC9 */
#define PCF_CTL_START  (PCF_PIN | PCF_ES0 | PCF_ENI | PCF_STA | PCF_ACK)  /* 0xCD */
#define PCF_CTL_STOP   (PCF_PIN | PCF_ES0 | PCF_ENI | PCF_STO | PCF_ACK)  /* 0xCB */
#define PCF_CTL_REPSTART (PCF_ES0 | PCF_ENI | PCF_STA | PCF_ACK)          /* 0x4D */
#define PCF_CTL_NACK   (PCF_ES0 | PCF_ENI)                                /* 0x48 */
#define PCF_CTL_RESET  PCF_PIN                                            /* 0x80: serial interface off */
#define PCF_S2_12MHZ_90KHZ 0x1Cu

enum i2c_fsm_state {
    I2C_FSM_IDLE = 0,
    I2C_FSM_DATA_W,    /* the write address or a data byte on the wire */
    I2C_FSM_ADDR_R,    /* (repeated) START + address (read) on the wire */
    I2C_FSM_DATA_R     /* receiving into rp */
};

/* What a call did. */
enum i2c_fsm_event {
    I2C_FSM_RUNNING = 0,   /* waiting for the next interrupt */
    I2C_FSM_DONE,          /* the transaction ended: x->status holds the result */
    I2C_FSM_BUS_BUSY,      /* start: bus not free, nothing was sent */
    I2C_FSM_SPURIOUS       /* interrupt with PIN still 1 or no transaction: ignored */
};

struct i2c_fsm {
    volatile uint8_t *base;    /* S0 at base[0], S1 at base[1] */
    struct i2c_xfer *x;        /* the transaction on the wire, or NULL */
    struct i2c_xfer *m;        /* its message on the wire (x or one of x->more) */
    int first_err;             /* the first failed message's status */
    uint8_t state;             /* enum i2c_fsm_state */
    uint8_t need_reset;        /* the result requires a controller reset */
    /* Cursors, so the per-byte path does no index arithmetic. */
    const uint8_t *wp;         /* next byte to write */
    const uint8_t *wr_end;
    uint8_t *rp;               /* where the byte being received goes */
    uint8_t *rd_fast_end;      /* rp below this: neither of the last two bytes */
    uint8_t read_addr;         /* address byte of the read part after the write, 0: none */
};

#ifdef I2C_FSM_FAKE_HW
uint8_t i2c_fake_rd(struct i2c_fsm *f, unsigned reg);
void i2c_fake_wr(struct i2c_fsm *f, unsigned reg, uint8_t v);
#define I2C_FSM_RD(f, reg) i2c_fake_rd((f), (reg))
#define I2C_FSM_WR(f, reg, v) i2c_fake_wr((f), (reg), (uint8_t)(v))
#else
#define I2C_FSM_RD(f, reg) ((f)->base[(reg)])
#define I2C_FSM_WR(f, reg, v) ((f)->base[(reg)] = (uint8_t)(v))
#endif

/* Programs the controller: serial interface off, own address, clock, vector,
 * then enabled with interrupts (CubeOS sequence). Returns 0, or -1 when S1 did
 * not read back 0x80 after the reset write (no PCF8584 there). */
int i2c_fsm_reset(struct i2c_fsm *f, uint8_t own_addr, uint8_t vector);

/* Starts x and its chain x->more (lengths already checked). I2C_FSM_RUNNING,
 * or I2C_FSM_BUS_BUSY (nothing sent; x not taken). */
enum i2c_fsm_event i2c_fsm_start(struct i2c_fsm *f, struct i2c_xfer *x);

/* Points the cursors at message m and sends its address (the START or
 * repeated START condition has been set up by the caller). */
static inline __attribute__((always_inline)) void i2c_fsm_send_address(struct i2c_fsm *f,
                                                                       struct i2c_xfer *m)
{
    uint8_t a = (uint8_t)(m->addr7 << 1);
    f->m = m;
    f->wp = m->wr;
    f->wr_end = m->wr_len > 0 ? m->wr + m->wr_len : m->wr;
    f->rp = m->rd;
    f->rd_fast_end = m->rd_len >= 2u ? m->rd + (m->rd_len - 2u) : m->rd;
    f->read_addr = 0;
    if (m->wr_len == 0 && m->rd_len > 0) {
        f->state = I2C_FSM_ADDR_R;
        a |= 1u;
    } else {
        f->state = I2C_FSM_DATA_W;
        if (m->rd_len > 0)
            f->read_addr = (uint8_t)(a | 1u);
    }
    I2C_FSM_WR(f, PCF_S0, a);
}

/* One controller interrupt, st = the status register read in it (PIN and
 * the error bits are checked here). I2C_FSM_DONE ends f->x (status set, f->x
 * NULL, f->need_reset set when the controller must be reset before the next
 * start). */
enum i2c_fsm_event i2c_fsm_step(struct i2c_fsm *f, uint8_t st);

/* One controller interrupt. The common cases are inline: a byte acknowledged
 * in the middle of a write (the address included), the repeated START of the
 * read part, a byte of a read but the last, the read address of a read of 3
 * bytes or more (about 25 instructions instead of about 65 through the
 * general step); the last byte, the end of a message, a short read and the
 * errors go to i2c_fsm_step. Both make the same register accesses. */
static inline __attribute__((always_inline)) enum i2c_fsm_event i2c_fsm_interrupt(struct i2c_fsm *f)
{
    uint8_t st;
    if (f->x == NULL)
        return I2C_FSM_SPURIOUS;
    st = I2C_FSM_RD(f, PCF_S1);
    if (!(st & (PCF_ST_PIN | PCF_ST_LAB | PCF_ST_BER))) {
        if (f->state == I2C_FSM_DATA_R) {
            /* Receiving: LRB is the acknowledge we sent, not an error. */
            if (f->rp < f->rd_fast_end) {
                *f->rp++ = I2C_FSM_RD(f, PCF_S0);  /* and the next byte starts */
                return I2C_FSM_RUNNING;
            }
            if (f->rp == f->rd_fast_end && f->rp != f->m->rd) {
                I2C_FSM_WR(f, PCF_S1, PCF_CTL_NACK);   /* the next byte is the last */
                *f->rp++ = I2C_FSM_RD(f, PCF_S0);
                return I2C_FSM_RUNNING;
            }
            if (f->m->more != NULL && f->rp > f->rd_fast_end) {
                /* The last byte, and the chain goes on: repeated START set up
                 * before the read (no further byte is clocked), then the next
                 * message's address (as i2c_fsm_step's end of a message). */
                struct i2c_xfer *m = f->m;
                I2C_FSM_WR(f, PCF_S1, PCF_CTL_REPSTART);
                *f->rp = I2C_FSM_RD(f, PCF_S0);
                m->msg_status = DRV_OK;
                i2c_fsm_send_address(f, m->more);
                return I2C_FSM_RUNNING;
            }
        } else if (!(st & PCF_ST_LRB)) {           /* acknowledged */
            if (f->state == I2C_FSM_DATA_W) {
                if (f->wp < f->wr_end) {
                    I2C_FSM_WR(f, PCF_S0, *f->wp++);
                    return I2C_FSM_RUNNING;
                }
                if (f->read_addr != 0) {               /* the read part: repeated START */
                    f->state = I2C_FSM_ADDR_R;
                    I2C_FSM_WR(f, PCF_S1, PCF_CTL_REPSTART);
                    I2C_FSM_WR(f, PCF_S0, f->read_addr);
                    return I2C_FSM_RUNNING;
                }
            } else if (f->state == I2C_FSM_ADDR_R && f->rp < f->rd_fast_end) {
                f->state = I2C_FSM_DATA_R;         /* 3 bytes or more: no NACK yet */
                (void)I2C_FSM_RD(f, PCF_S0);       /* dummy read: clocks in byte 0 */
                return I2C_FSM_RUNNING;
            }
        }
    }
    return i2c_fsm_step(f, st);
}

/* Abandons the transaction on the wire (deadline passed): x->status and the
 * msg_status of the messages not done = DRV_ERR_TIMEOUT; returns the
 * transaction or NULL. The caller resets. */
struct i2c_xfer *i2c_fsm_abort(struct i2c_fsm *f);

#endif /* DRIVERS_I2C_FSM_H */
