/*
 * RoboCube I/O devices (io helper): MC68332 TPU, PCF8584 I2C controllers,
 * PCF8591 / PCF8574A on the I/O board, DC motor model, fast binary outputs.
 * Internal interfaces between the files of the I/O side; the board only sees
 * robocube_io_init() from robocube_io.h. Register maps and the host interface
 * are documented in emu/IO.md.
 */
#ifndef ROBOCUBE_IO_DEVS_H
#define ROBOCUBE_IO_DEVS_H

#include "exec/memory.h"
#include "hw/sysbus.h"
#include "hw/i2c/i2c.h"
#include "qemu/timer.h"
#include "robocube_intc.h"
#include "robocube_io.h"

#define RC_TPU_BASE      0xFFFE00
#define RC_I2C_B_BASE    0xFFE000
#define RC_I2C_A_BASE    0xFFE200
#define RC_FASTBIN_BASE  0xFE0000

#define RC_TPU_CHANNELS 16
#define RC_MOTORS 3
#define RC_ADCS 6
#define RC_BIOS 2

/* ---- small QOM property helpers (robocube_io.c) ------------------------ */
typedef int64_t (*RcPropGet)(void *opaque, int index);
/* Returns false and sets errp when the value cannot be applied. */
typedef bool (*RcPropSet)(void *opaque, int index, int64_t value, Error **errp);
/* Adds an integer property "name" (range-checked on write; set == NULL:
 * read-only) to obj. */
void rc_prop_add_int(Object *obj, const char *name, int64_t min, int64_t max,
                     RcPropGet get, RcPropSet set, void *opaque, int index);

/* ---- TPU (mc68332_tpu.c) ------------------------------------------------ */
#define TYPE_MC68332_TPU "mc68332-tpu"
OBJECT_DECLARE_SIMPLE_TYPE(MC68332TpuState, MC68332_TPU)

/* Standard MC68332 (mask A) TPU ROM function numbers. */
enum {
    TPU_FN_QDEC = 0x6, TPU_FN_SPWM = 0x7, TPU_FN_DIO = 0x8, TPU_FN_PWM = 0x9,
    TPU_FN_ITC = 0xA, TPU_FN_PMA = 0xB, TPU_FN_PSP = 0xC, TPU_FN_SM = 0xD,
    TPU_FN_OC = 0xE, TPU_FN_PPWA = 0xF,
};

typedef struct TpuChannel {
    struct MC68332TpuState *tpu;
    int index;
    int init_fn;            /* function the last init HSR set up, -1: none */
    bool is_output;         /* pin driven by the TPU (PWM, DIO output) */
    bool out_level;         /* driven level (DIO output) */
    bool in_level;          /* level applied from outside */
    bool itc_armed;         /* ITC still counting (single-shot stops) */
    uint16_t pwm_high;      /* PWM high time / period in effect (TCR1 ticks) */
    uint16_t pwm_period;
    int64_t pwm_rise_ns;    /* virtual time of the last rising edge */
    QEMUTimer *timer;       /* PWM period / DIO match-rate timer */
} TpuChannel;

struct MC68332TpuState {
    SysBusDevice parent_obj;
    MemoryRegion iomem;
    RoboCubeIntc *intc;
    uint16_t mcr, tcr, dscr, dssr, ticr, cier, cisr, lr, sglr, dcnr;
    uint16_t cfsr[4], hsqr[2], hsrr[2], cpr[2];
    uint16_t param[RC_TPU_CHANNELS][8];
    TpuChannel ch[RC_TPU_CHANNELS];
    int64_t tcr1_epoch_ns;
};

/* Applies an external level to TP pin ch (edge processing for the channel's
 * input function happens here). */
void tpu_set_input(MC68332TpuState *s, int ch, bool level);
/* Current level of pin ch (driven output, or the external level). */
bool tpu_pin_level(MC68332TpuState *s, int ch);
/* PWM duty of channel ch in 1/10000 (0 when the channel is not running PWM). */
unsigned tpu_pwm_duty(MC68332TpuState *s, int ch);
uint16_t tpu_tcr1(MC68332TpuState *s);
void tpu_add_host_properties(MC68332TpuState *s);

/* ---- PCF8584 (pcf8584.c) ------------------------------------------------ */
#define TYPE_PCF8584 "pcf8584"
OBJECT_DECLARE_SIMPLE_TYPE(PCF8584State, PCF8584)

struct PCF8584State {
    SysBusDevice parent_obj;
    MemoryRegion iomem;
    I2CBus *bus;
    RoboCubeIntc *intc;
    int irq_source;         /* enum RoboCubeIrqSource */
    unsigned irq_level;
    uint8_t s0;             /* data / shift register */
    uint8_t own_addr;       /* S0' */
    uint8_t clock;          /* S2 */
    uint8_t vector;         /* S3 */
    uint8_t ctrl;           /* S1 control bits ES0 ES1 ES2 ENI ACK as written */
    bool pin;               /* PIN status bit: 1 = no transfer completed */
    bool busy;              /* this master holds the bus (status BB reads 0) */
    bool lrb;               /* last received bit (1 = slave did not ACK) */
    bool receiving;         /* master-receiver mode */
    bool repstart_armed;    /* STA written while holding the bus: next S0 write = address */
    bool transfer_open;     /* a QEMU I2C transfer is open */
    uint8_t cur_addr;       /* 7-bit address of the open transfer */
    bool rx_pending;        /* a byte is being received; lands in S0 on completion */
    uint8_t rx_byte;
    QEMUTimer *done_timer;  /* byte transfer completion (9 SCL clocks) */
    bool stuck;             /* fault injection: bus held low (host property) */
    bool byte_stalled;      /* a byte's time ran out while the bus was stuck */
};

/* ---- PCF8591 / PCF8574A (pcf8591.c, pcf8574a.c) --------------------------- */
#define TYPE_PCF8591 "pcf8591"
OBJECT_DECLARE_SIMPLE_TYPE(PCF8591State, PCF8591)
struct PCF8591State {
    I2CSlave parent_obj;
    uint8_t ain[4];         /* host-set input codes (0..255 = 0..Vref) */
    uint8_t control;
    uint8_t dac;
    uint8_t result;         /* last conversion, sent on the next read byte */
    uint8_t channel;        /* channel of the next conversion */
    bool expect_control;    /* next written byte is the control byte */
    bool nack;              /* fault injection: does not acknowledge its address */
};

#define TYPE_PCF8574A "pcf8574a"
OBJECT_DECLARE_SIMPLE_TYPE(PCF8574AState, PCF8574A)
struct PCF8574AState {
    I2CSlave parent_obj;
    uint8_t latch;          /* output latch; 1 = weak pull-up (quasi-bidirectional) */
    uint8_t ext;            /* host drive: bit 0 = pin pulled low from outside */
    uint8_t last_seen;      /* pin levels at the last read/write (INT reference) */
    bool int_pending;       /* /INT asserted */
    bool nack;              /* fault injection: does not acknowledge its address */
};
uint8_t pcf8574a_pins(PCF8574AState *s);

/* ---- motors and the container (robocube_motors.c, robocube_io.c) -------- */
#define TYPE_ROBOCUBE_MOTOR "robocube-motor"
OBJECT_DECLARE_SIMPLE_TYPE(RoboCubeMotor, ROBOCUBE_MOTOR)
struct RoboCubeMotor {
    Object parent_obj;
    MC68332TpuState *tpu;
    int index;
    int pwm_ch, enc_a_ch, enc_b_ch;
    bool model_enabled;
    uint32_t max_speed;     /* encoder counts/s at 100 % duty */
    uint32_t tau_ms;        /* time constant of the first-order model */
    double speed;           /* counts/s */
    double frac;            /* fractional count not yet emitted */
    int64_t encoder;        /* quadrature count (4 per encoder line) */
    int64_t last_ns;
};
void robocube_motor_setup(RoboCubeMotor *m, MC68332TpuState *tpu, int index);
void robocube_motor_step(RoboCubeMotor *m, int64_t now_ns, uint8_t opr);
void robocube_motor_reset(RoboCubeMotor *m);
int robocube_motor_direction(RoboCubeMotor *m, uint8_t opr);

#endif
