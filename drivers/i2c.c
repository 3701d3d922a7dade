/*
 * I2C bus service on the two PCF8584 controllers (see i2c.h): per-bus queue,
 * interrupt handler that drives the state machine (i2c_fsm.c) and chains the
 * queued transactions, and one service thread that enforces deadlines and
 * retries a START while the bus reads busy.
 *
 * Locking: the queue and the state machine of a bus are touched by its
 * interrupt handler and by threads; threads hold all interrupts masked
 * (k_arch_irq_save) while they touch them, for a few dozen instructions.
 */
#include "drivers/i2c.h"

#include "drivers/i2c_fsm.h"
#include "boards/include/board_io.h"
#include "kernel.h"

/* Deadline of one transaction: 4 ms plus 200 us per byte (twice the 100 us a
 * byte takes at 90 kHz). A bus that stays busy or a byte that never ends is
 * detected within this time and the controller is reset. */
#define I2C_DEADLINE_BASE_MS 4u
#define I2C_DEADLINE_US_PER_BYTE 200u
/* How long a blocking caller waits at most: the deadlines of a full queue of
 * long transactions are far shorter; the service thread ends every
 * transaction by its deadline, so this only matters if it is starved. */
#define I2C_WAIT_MS 500u

#define I2C_SERVICE_PRIO (K_PRIO_SERVICE_MIN + 1u)
#define I2C_SERVICE_STACK 1024u

struct i2c_bus {
    struct i2c_fsm fsm;
    struct i2c_xfer *head;     /* active transaction (on the wire or waiting for the bus) */
    struct i2c_xfer *tail;
    uint8_t ready;
    uint8_t own_addr;
    uint8_t vector;            /* S3; the handler is cpu32_vector_<vector> */
    struct i2c_stats stats;
};

static struct i2c_bus i2c_buses[I2C_BUS_COUNT] = {
    { .fsm = { .base = board_i2c_a_regs }, .own_addr = 0x55u, .vector = 27u },
    { .fsm = { .base = board_i2c_b_regs }, .own_addr = 0x56u, .vector = 25u },
};

static struct k_thread i2c_service_thread;
K_STACK_DEFINE(i2c_service_stack, I2C_SERVICE_STACK);
static struct k_sem i2c_service_wake;
static uint8_t i2c_service_running;
/* The service thread waits on i2c_service_wake (every queue was empty): the
 * next submit must wake it. Otherwise it sleeps until the nearest deadline,
 * which is never later than a new transaction's, so no wake-up is needed. */
static volatile uint8_t i2c_service_idle;

static void controller_reset(struct i2c_bus *b)
{
    (void)i2c_fsm_reset(&b->fsm, b->own_addr, b->vector);
    b->stats.resets++;
}

/* Tries to put the head on the wire (interrupts masked). */
static void start_head(struct i2c_bus *b)
{
    struct i2c_xfer *x = b->head;
    if (x == NULL || b->fsm.x != NULL)
        return;
    if (!x->started) {
        x->started = 1;
        x->deadline += k_ticks();   /* held the allowed duration until now */
    }
    (void)i2c_fsm_start(&b->fsm, x);   /* bus busy: the service thread retries */
}

/* Removes the ended head and starts the next one; returns the ended one,
 * its callback not yet run. Interrupts masked (or in the bus's handler). */
static struct i2c_xfer *retire_head(struct i2c_bus *b)
{
    struct i2c_xfer *x = b->head;
    b->head = x->next;
    if (b->head == NULL)
        b->tail = NULL;
    x->next = NULL;
    switch (x->status) {
    case DRV_OK: b->stats.done++; break;
    case DRV_ERR_ABSENT: b->stats.absent++; break;
    case DRV_ERR_ARB: b->stats.arb++; break;
    default: b->stats.timeouts++; break;
    }
    if (b->fsm.need_reset)
        controller_reset(b);
    start_head(b);
    return x;
}

/* retire_head, then the ended transaction's callback. */
static void complete_head(struct i2c_bus *b)
{
    struct i2c_xfer *x = retire_head(b);
    if (x->done != NULL)
        x->done(x, x->arg);
}

/*
 * The controllers' interrupts, claimed by name in the flash vector table
 * (start.S; copied to the kernel's RAM table) instead of through
 * k_irq_register: a byte interrupt only moves the state machine on and
 * touches no kernel state, so it skips the kernel's interrupt entry and
 * scheduling decision (measured: about 170 instructions per byte that way,
 * against about 50 here; at 256 ns per instruction and 100 us per byte that is
 * the difference between 43 % and 13 % of the CPU). Only the end of a
 * transaction, which may wake a thread, runs through k_isr_call (as a kernel
 * handler, on the interrupt stack).
 * A transaction without a callback ends without any kernel call at all.
 * The handler masks all interrupts at once, so no tick nests inside it.
 * Vectors: S3 holds 27 (bus A, level 3) / 25 (bus B, level 1), the
 * autovector numbers of those levels, so the vector is right whether the
 * board autovectors or takes the PCF8584's.
 */
/* complete_head through k_isr_call: on the kernel's interrupt stack, not on
 * the interrupted thread's. */
static void complete_head_isr(void *bus)
{
    complete_head(bus);
}

static inline __attribute__((always_inline)) void i2c_irq(struct i2c_bus *b)
{
    /* Mask everything while the handler runs (RTE restores the mask): the
     * kernel does not know it is inside this handler, so a tick nested here
     * could switch threads and let another instance of this interrupt run
     * between our status read and register write. About 25 instructions. */
    __asm__ __volatile__("ori.w #0x0700,%%sr" : : : "memory", "cc");
    enum i2c_fsm_event ev;
    b->stats.interrupts++;
    ev = i2c_fsm_interrupt(&b->fsm);
    if (ev == I2C_FSM_RUNNING)          /* most interrupts: one test */
        return;
    if (ev == I2C_FSM_SPURIOUS && b->fsm.x == NULL) {
        /* A request with nothing on the wire (cannot happen with the
         * sequences used; would repeat forever): writing PIN drops it. */
        b->stats.spurious++;
        I2C_FSM_WR(&b->fsm, PCF_S1, PCF_CTL_IDLE);
    } else if (ev == I2C_FSM_DONE) {
        if (b->head->done != NULL) {   /* it may wake a thread: as a kernel handler */
            k_isr_call(complete_head_isr, b);
        } else {
            (void)retire_head(b);      /* no callback: nothing to wake */
        }
    }
}

void cpu32_vector_27(void) __attribute__((interrupt_handler));
void cpu32_vector_27(void)
{
    i2c_irq(&i2c_buses[I2C_BUS_A]);
}

void cpu32_vector_25(void) __attribute__((interrupt_handler));
void cpu32_vector_25(void)
{
    i2c_irq(&i2c_buses[I2C_BUS_B]);
}

/* Ends the head with DRV_ERR_TIMEOUT and resets the controller (interrupts masked). */
/* A transaction that ends without having run: it and its messages fail. */
static void fail_unstarted(struct i2c_xfer *x, int err)
{
    for (struct i2c_xfer *m = x; m != NULL; m = m->more)
        m->msg_status = err;
    x->status = err;
}

static void timeout_head(struct i2c_bus *b)
{
    if (i2c_fsm_abort(&b->fsm) == NULL)
        fail_unstarted(b->head, DRV_ERR_TIMEOUT);   /* never got the bus */
    b->fsm.need_reset = 1;
    complete_head(b);
}

/* Deadlines and bus-free retries. Sleeps on i2c_service_wake while every
 * queue is empty; otherwise until the nearest deadline, or one tick while a
 * transaction waits for a busy bus. */
static void *i2c_service(void *arg)
{
    (void)arg;
    for (;;) {
        k_ticks_t now = k_ticks(), wake = now + K_TICK_HZ;
        int active = 0;
        for (unsigned i = 0; i < I2C_BUS_COUNT; i++) {
            struct i2c_bus *b = &i2c_buses[i];
            uint32_t s = k_arch_irq_save();
            if (b->head != NULL && (int32_t)(now - b->head->deadline) >= 0)
                timeout_head(b);
            if (b->head != NULL && b->fsm.x == NULL)
                start_head(b);
            if (b->head != NULL) {
                k_ticks_t next = b->fsm.x == NULL ? now + 1u : b->head->deadline;
                if ((int32_t)(next - wake) < 0)
                    wake = next;
                active = 1;
            }
            k_arch_irq_restore(s);
        }
        if (active) {
            (void)k_sleep_until(wake);
        } else {
            uint32_t s = k_arch_irq_save();
            int empty = 1;
            for (unsigned i = 0; i < I2C_BUS_COUNT; i++)
                empty = empty && i2c_buses[i].head == NULL;
            i2c_service_idle = (uint8_t)empty;
            k_arch_irq_restore(s);
            if (empty)
                (void)k_sem_wait(&i2c_service_wake);
        }
    }
    return NULL;
}

int i2c_init(unsigned bus)
{
    struct i2c_bus *b;
    uint32_t s;
    int rc;

    if (bus >= I2C_BUS_COUNT)
        return DRV_ERR_CHANNEL;
    b = &i2c_buses[bus];
    s = k_arch_irq_save();
    if (!i2c_service_running) {
        (void)k_sem_init(&i2c_service_wake, 0u, 1u);
        i2c_service_running = 1;
        k_arch_irq_restore(s);
        if (k_thread_create(&i2c_service_thread, "i2c", i2c_service, NULL, i2c_service_stack,
                            sizeof(i2c_service_stack), I2C_SERVICE_PRIO) != K_OK)
            return DRV_ERR_STATE;
        s = k_arch_irq_save();
    }
    while (b->head != NULL)
        timeout_head(b);
    rc = i2c_fsm_reset(&b->fsm, b->own_addr, b->vector);
    b->stats.resets++;
    k_arch_irq_restore(s);
    if (rc != 0) {
        b->ready = 0;
        return DRV_ERR_ABSENT;
    }
    b->ready = 1;
    return DRV_OK;
}

/* Checks every message of x's chain and marks it pending; returns the ticks
 * the transaction may take (I2C_DEADLINE_BASE_MS plus
 * I2C_DEADLINE_US_PER_BYTE per byte on the wire, rounded up to whole ticks;
 * computed here so the interrupt handler only adds), or 0 for a bad chain. */
static k_ticks_t chain_prepare(struct i2c_xfer *x)
{
    uint32_t bytes = 0, n = 0;
    for (struct i2c_xfer *m = x; m != NULL; m = m->more) {
        if (++n > I2C_MAX_CHAIN || m->addr7 > 0x7Fu || m->wr_len > I2C_MAX_LEN
            || m->rd_len > I2C_MAX_LEN || (m->wr_len > 0 && m->wr == NULL)
            || (m->rd_len > 0 && m->rd == NULL))
            return 0;
        bytes += 1u + (uint32_t)m->wr_len + (m->rd_len ? 2u + (uint32_t)m->rd_len : 0u);
    }
    if (n == 0)
        return 0;
    return (I2C_DEADLINE_BASE_MS * K_TICK_HZ + 999u) / 1000u +
           (bytes * I2C_DEADLINE_US_PER_BYTE * K_TICK_HZ + 999999u) / 1000000u;
}

int i2c_submit(unsigned bus, struct i2c_xfer *x)
{
    struct i2c_bus *b;
    k_ticks_t allowed;
    uint32_t s;

    if (bus >= I2C_BUS_COUNT)
        return DRV_ERR_CHANNEL;
    b = &i2c_buses[bus];
    if (!b->ready)
        return DRV_ERR_STATE;
    allowed = chain_prepare(x);
    if (allowed == 0)
        return DRV_ERR_PARAM;
    s = k_arch_irq_save();
    if (x->status == I2C_PENDING && (x->next != NULL || b->tail == x || b->head == x)) {
        k_arch_irq_restore(s);
        return DRV_ERR_BUSY;
    }
    for (struct i2c_xfer *m = x; m != NULL; m = m->more)
        m->msg_status = I2C_PENDING;     /* only now: x may have been queued */
    x->status = I2C_PENDING;
    x->next = NULL;
    x->started = 0;
    x->deadline = allowed;
    if (b->tail != NULL) {
        b->tail->next = x;
        b->tail = x;
    } else {
        b->head = b->tail = x;
        start_head(b);
        if (i2c_service_idle) {                /* watch its deadline */
            i2c_service_idle = 0;
            (void)k_sem_post(&i2c_service_wake);
        }
    }
    k_arch_irq_restore(s);
    return DRV_OK;
}

/* Takes x out of bus's queue if it is still there (the caller gave up). */
static void i2c_cancel(struct i2c_bus *b, struct i2c_xfer *x)
{
    uint32_t s = k_arch_irq_save();
    if (x->status == I2C_PENDING) {
        if (b->head == x) {
            timeout_head(b);
        } else {
            struct i2c_xfer *p = b->head;
            while (p != NULL && p->next != x)
                p = p->next;
            if (p != NULL) {
                p->next = x->next;
                if (b->tail == x)
                    b->tail = p;
                x->next = NULL;
            }
            fail_unstarted(x, DRV_ERR_TIMEOUT);
        }
    }
    k_arch_irq_restore(s);
}

static void post_done(struct i2c_xfer *x, void *arg)
{
    (void)x;
    (void)k_sem_post(arg);
}

int i2c_transfer(unsigned bus, uint8_t addr7, const uint8_t *wr, size_t wr_len,
                 uint8_t *rd, size_t rd_len)
{
    struct k_sem done;
    struct i2c_xfer x = {
        .addr7 = addr7, .wr = wr, .wr_len = wr_len, .rd = rd, .rd_len = rd_len,
        .done = post_done, .arg = &done,
    };
    int rc;

    if (k_in_isr())
        return DRV_ERR_STATE;
    (void)k_sem_init(&done, 0u, 1u);
    rc = i2c_submit(bus, &x);
    if (rc != DRV_OK)
        return rc;
    if (k_sem_wait_ticks(&done, k_ms_to_ticks(I2C_WAIT_MS)) != K_OK)
        i2c_cancel(&i2c_buses[bus], &x);
    return x.status;
}

int i2c_probe(unsigned bus, uint8_t addr7)
{
    return i2c_transfer(bus, addr7, NULL, 0, NULL, 0);
}

int i2c_scan(unsigned bus, uint8_t *found, unsigned max)
{
    int n = 0;
    for (uint8_t a = 0x08u; a <= 0x77u; a++) {
        int rc = i2c_probe(bus, a);
        if (rc == DRV_OK) {
            if ((unsigned)n < max && found != NULL)
                found[n] = a;
            n++;
        } else if (rc != DRV_ERR_ABSENT) {
            return rc;
        }
    }
    return n;
}

int i2c_get_stats(unsigned bus, struct i2c_stats *out)
{
    uint32_t s;
    if (bus >= I2C_BUS_COUNT)
        return DRV_ERR_CHANNEL;
    if (out == NULL)
        return DRV_ERR_PARAM;
    s = k_arch_irq_save();
    *out = i2c_buses[bus].stats;
    k_arch_irq_restore(s);
    return DRV_OK;
}
