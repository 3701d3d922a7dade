/*
 * Board support of the nanokernel on the RoboCube: implements the kernel's
 * board interface (kernel/include/k_board.h) with the console and PIT
 * drivers of this folder and registers the console writers with the kernel
 * (k_console_register), so the kernel itself calls no driver and no board.
 *
 * Console output: threads put bytes into a ring; the DUART's TxRDYB
 * interrupt (level 5, vectored through IVR) moves them to the transmitter
 * and masks itself when the ring runs dry. A thread that finds the ring
 * full waits on a semaphore the interrupt posts; a handler (or code before
 * k_start) cannot wait, so its surplus is dropped and counted. LF goes out
 * as CR LF, as with the firmware's polled console. Fault reports use
 * k_console_write_sync, whose writer here drains the ring and sends by
 * polling, with interrupts masked, so they get out even when the system is
 * wedged. Until the ring is set up, the polled writer serves both.
 *
 * The DUART's other users (radio, binary inputs, motor direction bits)
 * share its interrupt, its write-only IMR and ACR, and its output port
 * through boards/robocube/duart.h, implemented here beside the console.
 */
#include "kernel.h"
#include "k_board.h"
#include "kernel/arch/cpu32/cpu.h"
#include "boards/robocube/mc68332.h"
#include "boards/robocube/mc68681.h"
#include "boards/robocube/duart.h"
#include "boards/robocube/duart_console.h"
#include "boards/robocube/pit.h"

#define DUART_IMR_TXRDYB 0x10u
#define DUART_ISR_TXRDYB 0x10u

void (*volatile k_board_tick_callback)(void);

static uint8_t k_console_buf[K_BOARD_CONSOLE_RING];
static struct k_ring k_console_ring;
static struct k_sem k_console_space;
static uint8_t k_duart_imr;      /* IMR is write-only: its shadow */
static uint8_t k_duart_opr;      /* so is OPR */
static uint8_t k_duart_acr;      /* and ACR */

struct k_duart_handler {
    uint8_t mask;
    duart_irq_handler fn;
    void *arg;
};
static struct k_duart_handler k_duart_handlers[DUART_MAX_HANDLERS];
static int k_console_lf_held;    /* CR sent, LF still to send */
static uint32_t k_console_drops;

static void k_duart_set_imr(uint8_t imr)
{
    k_duart_imr = imr;
    DUART_REG(DUART_IMR) = imr;
}

/* Feeds the transmitter while it is ready and there is something to send.
 * Interrupts masked (handler or caller). Returns whether the ring is empty. */
static int k_console_feed(void)
{
    while ((DUART_REG(DUART_SRB) & DUART_SR_TXRDY) != 0u) {
        uint8_t b;
        if (k_console_lf_held) {
            k_console_lf_held = 0;
            DUART_REG(DUART_TBB) = '\n';
            continue;
        }
        if (!k_ring_get(&k_console_ring, &b))
            return 1;
        if (b == '\n') {
            k_console_lf_held = 1;
            b = '\r';
        }
        DUART_REG(DUART_TBB) = b;
    }
    return 0;
}

static void k_duart_isr(void *arg)
{
    uint8_t pending = (uint8_t)(DUART_REG(DUART_ISR) & k_duart_imr);
    unsigned i;
    (void)arg;
    if ((pending & DUART_ISR_TXRDYB) != 0u) {
        if (k_console_feed() && !k_console_lf_held)
            k_duart_set_imr((uint8_t)(k_duart_imr & ~DUART_IMR_TXRDYB));
        if (k_sem_has_waiter(&k_console_space))
            (void)k_sem_post(&k_console_space);
    }
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

void duart_op_assert(uint8_t bits)
{
    uint32_t irq = k_arch_irq_save();
    k_duart_opr = (uint8_t)(k_duart_opr | bits);
    DUART_REG(DUART_OPR_SET) = bits;
    k_arch_irq_restore(irq);
}

void duart_op_negate(uint8_t bits)
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
    size_t done = 0;
    int can_wait = k_can_block();
    while (done < len) {
        uint32_t irq = k_arch_irq_save();
        int put = k_ring_put(&k_console_ring, (uint8_t)s[done]);
        if ((k_duart_imr & DUART_IMR_TXRDYB) == 0u)
            k_duart_set_imr((uint8_t)(k_duart_imr | DUART_IMR_TXRDYB));
        k_arch_irq_restore(irq);
        if (put) {
            done++;
        } else if (can_wait && irq == 0u) {
            (void)k_sem_wait(&k_console_space);
        } else {
            k_console_drops += (uint32_t)(len - done);
            break;
        }
    }
    return done;
}

static void k_board_console_write_sync(const char *s, size_t len)
{
    uint32_t irq = k_arch_irq_save();
    while (!k_console_feed() || k_console_lf_held) {
        /* drain what was queued first, so the report comes out in order */
    }
    console_write(s, len);
    k_arch_irq_restore(irq);
}

uint32_t k_board_console_dropped(void)
{
    return k_console_drops;
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
    (void)k_ring_init(&k_console_ring, k_console_buf, sizeof k_console_buf);
    (void)k_sem_init(&k_console_space, 0, 1);
    k_console_lf_held = 0;
    k_console_drops = 0;
    k_duart_imr = 0;
    k_duart_opr = 0;       /* OPR resets to 0: every OPn negated (motors brake) */
    k_duart_acr = console_acr();
    {
        unsigned i;
        for (i = 0; i < DUART_MAX_HANDLERS; i++)
            k_duart_handlers[i].fn = NULL;
    }
    DUART_REG(DUART_IVR) = (uint8_t)K_BOARD_DUART_VECTOR;
    if (k_irq_register(K_BOARD_DUART_VECTOR, K_BOARD_DUART_LEVEL, k_duart_isr, NULL) != K_OK ||
        k_irq_register(VECTOR_PIT, IRQ_LEVEL_PIT, k_board_pit_isr, NULL) != K_OK)
        return -1;
    k_console_register(k_board_console_write, k_board_console_write_sync);
    return pit_start(K_TICK_HZ, k_board_tick);
}
