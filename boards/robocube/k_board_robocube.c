/*
 * Board support of the nanokernel on the RoboCube: implements the kernel's
 * board interface (kernel/include/k_board.h) with the console and PIT
 * drivers of this folder and registers the console writers with the kernel
 * (k_console_register), so the kernel itself calls no driver and no board.
 *
 * Console output: the kernel's shared transmitter (k_console_tx.h) on
 * channel B, whose TxRDYB interrupt (level 5, vectored through IVR) feeds it
 * and is masked when all is sent. Fault reports use k_console_write_sync,
 * whose writer here drains the ring and sends by polling, with interrupts
 * masked, so they get out even when the system is wedged. Until the ring is
 * set up, the polled writer serves both.
 *
 * The DUART's other users (radio, binary inputs, motor direction bits)
 * share its interrupt, its write-only IMR and ACR, and its output port
 * through boards/robocube/duart.h, implemented here beside the console.
 */
#include "kernel.h"
#include "k_board.h"
#include "k_console_tx.h"
#include "kernel/arch/cpu32/cpu.h"
#include "boards/robocube/mc68332.h"
#include "boards/robocube/mc68681.h"
#include "boards/robocube/duart.h"
#include "boards/robocube/duart_console.h"
#include "boards/robocube/pit.h"
#include "boards/robocube/tpu_stamp.h"

#define DUART_IMR_TXRDYB 0x10u
#define DUART_ISR_TXRDYB 0x10u

void (*volatile k_board_tick_callback)(void);

static uint8_t k_console_buf[K_BOARD_CONSOLE_RING];
static struct k_console_tx k_console;
static uint8_t k_duart_imr;      /* IMR is write-only: its shadow */
static uint8_t k_duart_opr;      /* so is OPR */
static uint8_t k_duart_acr;      /* and ACR */

struct k_duart_handler {
    uint8_t mask;
    duart_irq_handler fn;
    void *arg;
};
static struct k_duart_handler k_duart_handlers[DUART_MAX_HANDLERS];

static void k_duart_set_imr(uint8_t imr)
{
    k_duart_imr = imr;
    DUART_REG(DUART_IMR) = imr;
}

/* Channel B's transmitter, for the shared console transmitter. */
static int duart_tx_ready(void)
{
    return (DUART_REG(DUART_SRB) & DUART_SR_TXRDY) != 0u;
}

static void duart_tx_put(uint8_t b)
{
    DUART_REG(DUART_TBB) = b;
}

static void duart_tx_start(void)
{
    if ((k_duart_imr & DUART_IMR_TXRDYB) == 0u)
        k_duart_set_imr((uint8_t)(k_duart_imr | DUART_IMR_TXRDYB));
}

static void k_duart_isr(void *arg)
{
    uint8_t pending = (uint8_t)(DUART_REG(DUART_ISR) & k_duart_imr);
    unsigned i;
    (void)arg;
    if ((pending & DUART_ISR_TXRDYB) != 0u && k_console_tx_isr(&k_console))
        k_duart_set_imr((uint8_t)(k_duart_imr & ~DUART_IMR_TXRDYB));
    for (i = 0; i < DUART_MAX_HANDLERS; i++) {
        const struct k_duart_handler *h = &k_duart_handlers[i];
        if (h->fn != NULL && (pending & h->mask) != 0u)
            h->fn((uint8_t)(pending & h->mask), h->arg);
    }
}

int duart_irq_attach(uint8_t mask, duart_irq_handler fn, void *arg)
{
    uint8_t taken = DUART_IMR_TXRDYB;
    unsigned i, free_slot = DUART_MAX_HANDLERS;
    uint32_t irq;
    int rc = -1;
    if (mask == 0u || fn == NULL)
        return -1;
    irq = k_arch_irq_save();
    for (i = 0; i < DUART_MAX_HANDLERS; i++) {
        if (k_duart_handlers[i].fn != NULL)
            taken = (uint8_t)(taken | k_duart_handlers[i].mask);
        else if (free_slot == DUART_MAX_HANDLERS)
            free_slot = i;
    }
    if ((mask & taken) == 0u && free_slot < DUART_MAX_HANDLERS) {
        k_duart_handlers[free_slot].mask = mask;
        k_duart_handlers[free_slot].arg = arg;
        k_duart_handlers[free_slot].fn = fn;
        rc = 0;
    }
    k_arch_irq_restore(irq);
    return rc;
}

void duart_imr_update(uint8_t set, uint8_t clear)
{
    uint32_t irq = k_arch_irq_save();
    k_duart_set_imr((uint8_t)((k_duart_imr | set) & (uint8_t)~clear));
    k_arch_irq_restore(irq);
}

uint8_t duart_imr(void)
{
    return k_duart_imr;
}

void board_outputs_assert(uint8_t bits)
{
    uint32_t irq = k_arch_irq_save();
    k_duart_opr = (uint8_t)(k_duart_opr | bits);
    DUART_REG(DUART_OPR_SET) = bits;
    k_arch_irq_restore(irq);
}

void board_outputs_negate(uint8_t bits)
{
    uint32_t irq = k_arch_irq_save();
    k_duart_opr = (uint8_t)(k_duart_opr & (uint8_t)~bits);
    DUART_REG(DUART_OPR_RESET) = bits;
    k_arch_irq_restore(irq);
}

uint8_t duart_op(void)
{
    return k_duart_opr;
}

void duart_acr_ipchange(uint8_t ip_mask)
{
    uint32_t irq = k_arch_irq_save();
    k_duart_acr = (uint8_t)((k_duart_acr & 0xF0u) | (ip_mask & 0x0Fu));
    DUART_REG(DUART_ACR) = k_duart_acr;
    k_arch_irq_restore(irq);
}

int duart_ct_baud_clock(uint16_t preload)
{
    uint32_t irq;
    if (preload == 0u)
        return -1;
    irq = k_arch_irq_save();
    if ((k_duart_acr & 0x70u) != 0u) {
        k_arch_irq_restore(irq);
        return -1;
    }
    k_duart_acr = (uint8_t)(k_duart_acr | 0x60u);
    DUART_REG(DUART_ACR) = k_duart_acr;
    DUART_REG(DUART_CTUR) = (uint8_t)(preload >> 8);
    DUART_REG(DUART_CTLR) = (uint8_t)(preload & 0xFFu);
    (void)DUART_REG(DUART_START_COUNTER);
    k_arch_irq_restore(irq);
    return 0;
}

static size_t k_board_console_write(const char *s, size_t len)
{
    return k_console_tx_write(&k_console, s, len);
}

static void k_board_console_write_sync(const char *s, size_t len)
{
    uint32_t irq = k_arch_irq_save();
    k_console_tx_drain(&k_console); /* what was queued first, so the report comes out in order */
    console_write(s, len);
    k_arch_irq_restore(irq);
}

uint32_t k_board_console_dropped(void)
{
    return k_console.drops;
}

/* ---- the kernel's fine time stamp: TCR1 through TPU channel 15 ----
 *
 * TCR1 (16 bits, 1.048576 MHz: 0.954 us a count, once round in 62.5 ms)
 * is the MC68332's finest free-running counter (the PIT's count cannot be
 * read); the CPU reads it through a time function: QDEC's host service 01
 * copies TCR1 into the channel's TCR1_VALUE (parameter 2). The channel runs
 * nothing else and is never initialised (HSR 11): its pointers aim at its
 * own parameters, so an edge on the TP15 pin, if the microcode served one,
 * would write only there. The 16 bits are extended to 32 here, which holds
 * while a read comes at least once a round: the tick reads every
 * K_BOARD_STAMP_EVERY ticks (1/32 s at most). All of it starts with the
 * first k_timestamp_start (k_board_timestamp_start): until then TP15 is the
 * TPU driver's like any channel and the tick runs not one instruction for
 * the counter; from then on the driver refuses TP15 (board_tpu_reserved),
 * and the start fails with K_EBUSY if the driver runs a function there
 * already. On a real chip the copy
 * waits for the TPU's scheduler (microseconds when other channels are
 * busy): a stamp is TCR1 at that service, not at the write. The emulator
 * serves it at once. */
#define K_BOARD_STAMP_CH ROBOCUBE_TPU_STAMP_CHANNEL
#define K_BOARD_STAMP_TRIES 64u  /* polls of HSRR before a stale TCR1_VALUE is taken */
#define K_BOARD_STAMP_EVERY ((K_TICK_HZ + 31u) / 32u)
#if K_TICK_HZ < 32
#error "the TCR1 extension needs a tick of at least 32 Hz (a read every 1/32 s)"
#endif
volatile uint16_t board_tpu_reserved; /* board_io.h: TPU channels the TPU driver refuses */
static uint16_t k_stamp_last;   /* TCR1 at the last read */
static uint32_t k_stamp_high;   /* the rounds before it, in the upper 16 bits */
static uint32_t k_stamp_countdown;

static uint32_t k_board_timestamp(void)
{
    uint32_t irq = k_arch_irq_save();
    uint32_t stamp;
    unsigned tries = 0;
    uint16_t now;
    MC68332_TPU_HSRR0 = MC68332_TPU_FIELD2(K_BOARD_STAMP_CH, 1u); /* other fields 00: untouched */
    while ((MC68332_TPU_HSRR0 & MC68332_TPU_FIELD2(K_BOARD_STAMP_CH, 3u)) != 0u &&
           tries < K_BOARD_STAMP_TRIES)
        tries++;
    now = MC68332_TPU_PARAM(K_BOARD_STAMP_CH, 2u);
    if (now < k_stamp_last)
        k_stamp_high += 0x10000u;
    k_stamp_last = now;
    stamp = k_stamp_high | now;
    k_arch_irq_restore(irq);
    return stamp;
}

static void k_board_tick(uint32_t ticks);
static void k_board_tick_stamping(uint32_t ticks);

static int k_board_timestamp_start(void)
{
    uint32_t irq = k_arch_irq_save();
    if ((MC68332_TPU_CPR0 & MC68332_TPU_FIELD2(K_BOARD_STAMP_CH, 3u)) != 0u) {
        k_arch_irq_restore(irq); /* a function of the TPU driver runs on TP15 */
        return K_EBUSY;
    }
    board_tpu_reserved = (uint16_t)(board_tpu_reserved | (1u << K_BOARD_STAMP_CH));
    MC68332_TPUMCR = MC68332_TPUMCR_CUBEOS;
    MC68332_TPU_CPR0 = (uint16_t)(MC68332_TPU_CPR0 & ~MC68332_TPU_FIELD2(K_BOARD_STAMP_CH, 3u));
    MC68332_TPU_CFSR0 = (uint16_t)((MC68332_TPU_CFSR0 & 0x0FFFu) | (MC68332_TPU_FN_QDEC << 12));
    MC68332_TPU_HSQR0 = (uint16_t)(MC68332_TPU_HSQR0 & ~MC68332_TPU_FIELD2(K_BOARD_STAMP_CH, 3u));
    /* CORR_PINSTATE_ADDR: its own word 3; EDGE_TIME_LSB_ADDR: its own word 0. */
    MC68332_TPU_PARAM(K_BOARD_STAMP_CH, 4u) = (uint16_t)(16u * K_BOARD_STAMP_CH + 6u);
    MC68332_TPU_PARAM(K_BOARD_STAMP_CH, 5u) = (uint16_t)(16u * K_BOARD_STAMP_CH + 1u);
    MC68332_TPU_PARAM(K_BOARD_STAMP_CH, 2u) = 0;
    MC68332_TPU_CPR0 = (uint16_t)(MC68332_TPU_CPR0 | MC68332_TPU_FIELD2(K_BOARD_STAMP_CH, 3u));
    k_stamp_last = 0;
    k_stamp_high = 0;
    k_stamp_countdown = K_BOARD_STAMP_EVERY;
    (void)k_board_timestamp();
    pit_set_hook(k_board_tick_stamping);
    k_arch_irq_restore(irq);
    return K_OK;
}

/* PIT hook: runs inside the kernel's interrupt entry (k_board_pit_isr). */
static void k_board_tick(uint32_t ticks)
{
    void (*cb)(void);
    (void)ticks;
    k_tick();
    cb = k_board_tick_callback;
    if (cb != NULL)
        cb();
}

/* The PIT hook once the fine time stamp runs: the extension's read, then the tick. */
static void k_board_tick_stamping(uint32_t ticks)
{
    if (--k_stamp_countdown == 0u) {
        k_stamp_countdown = K_BOARD_STAMP_EVERY;
        (void)k_board_timestamp(); /* keeps the extension of TCR1 to 32 bits */
    }
    k_board_tick(ticks);
}

/* The tick goes through the kernel's interrupt entry like every other
 * interrupt: on the interrupt stack, with the scheduling decision at its
 * outermost exit. */
static void k_board_pit_isr(void *arg)
{
    (void)arg;
    pit_interrupt();
}

int k_board_init(void)
{
    console_init(); /* channel B at CONSOLE_BAUD 8N1, all DUART interrupts masked */
    k_console_register(NULL, console_write); /* the polled early writer */
    (void)k_console_tx_init(&k_console, k_console_buf, sizeof k_console_buf, duart_tx_ready,
                            duart_tx_put, duart_tx_start);
    k_duart_imr = 0;
    k_duart_opr = 0;       /* OPR resets to 0: every OPn negated (motors brake) */
    k_duart_acr = console_acr();
    {
        unsigned i;
        for (i = 0; i < DUART_MAX_HANDLERS; i++)
            k_duart_handlers[i].fn = NULL;
    }
    DUART_REG(DUART_IVR) = (uint8_t)DUART_IRQ_VECTOR;
    if (k_irq_register(DUART_IRQ_VECTOR, DUART_IRQ_LEVEL, k_duart_isr, NULL) != K_OK ||
        k_irq_register(VECTOR_PIT, IRQ_LEVEL_PIT, k_board_pit_isr, NULL) != K_OK)
        return -1;
    k_console_register(k_board_console_write, k_board_console_write_sync);
    k_timestamp_register(k_board_timestamp, ROBOCUBE_TCR1_HZ, k_board_timestamp_start);
    return pit_start(K_TICK_HZ, k_board_tick);
}
