/*
 * Board support of the nanokernel on the STM32F405 (kernel/include/k_board.h):
 * the console on USART1 and the tick on SysTick. The one file that glues the
 * board's console and tick to the kernel.
 *
 * Console output: threads put bytes into a ring; the USART's TXE interrupt
 * (kernel level 5, NVIC line 37) moves them to the transmitter and disables
 * itself when the ring runs dry (see k_console_tx_start for what QEMU's
 * model lacks there). A thread that finds the ring full waits on
 * a semaphore the interrupt posts; a handler (or code before k_start) cannot
 * wait, so its surplus is dropped and counted. LF goes out as CR LF.
 * The polled writer drains the ring and sends by polling, with interrupts
 * masked, for fault reports; it is the console until k_board_init has set up
 * the interrupt-driven one (both registered with k_console_register).
 *
 * The tick: SysTick from the 168 MHz core clock at K_TICK_HZ, kernel level 4
 * (below the console, as the PIT is below the DUART on the RoboCube).
 */
#include "kernel.h"
#include "k_board.h"
#include "k_struct.h"
#include "armv7m.h"
#include "stm32f405.h"
#include "kernel/lib/kprintf.h"
#include "boards/stm32f405/board_stm32f405.h"

#define CONSOLE_LEVEL 5u

void (*volatile k_board_tick_callback)(void);

static uint8_t k_console_buf[K_BOARD_CONSOLE_RING];
static struct k_ring k_console_ring;
static struct k_sem k_console_space;
static int k_console_lf_held;    /* CR sent, LF still to send */
static uint32_t k_console_drops;
static void (*volatile k_console_rx_fn)(uint8_t byte);

/* Polled output, for kprintf and the fault reports. */
static void console_putc_polled(char c)
{
    if (c == '\n')
        console_putc_polled('\r');
    while ((USART_SR(USART1_BASE) & USART_SR_TXE) == 0u) {
    }
    USART_DR(USART1_BASE) = (uint8_t)c;
}

/* Feeds the transmitter while it is empty and there is something to send.
 * Interrupts masked (handler or caller). Returns whether the ring is empty. */
static int k_console_feed(void)
{
    while ((USART_SR(USART1_BASE) & USART_SR_TXE) != 0u) {
        uint8_t b;
        if (k_console_lf_held) {
            k_console_lf_held = 0;
            USART_DR(USART1_BASE) = '\n';
            continue;
        }
        if (!k_ring_get(&k_console_ring, &b))
            return 1;
        if (b == '\n') {
            k_console_lf_held = 1;
            b = '\r';
        }
        USART_DR(USART1_BASE) = b;
    }
    return 0;
}

/* Enables the TXE interrupt and also sets the line pending in the NVIC:
 * QEMU 7.2's USART model raises its interrupt for received bytes only, never
 * for TXE (its transmitter is always empty). On a real chip the pending bit
 * only brings the handler in a little early: it feeds while TXE is set. */
static void k_console_tx_start(void)
{
    USART_CR1(USART1_BASE) |= USART_CR1_TXEIE;
    NVIC_ISPR(USART1_IRQ / 32u) = 1u << (USART1_IRQ % 32u);
}

static void k_console_isr(void *arg)
{
    uint32_t sr = USART_SR(USART1_BASE), cr1 = USART_CR1(USART1_BASE);
    (void)arg;
    if ((sr & USART_SR_RXNE) != 0u) {
        uint8_t b = (uint8_t)USART_DR(USART1_BASE);
        void (*fn)(uint8_t) = k_console_rx_fn;
        if (fn != NULL)
            fn(b);
    }
    if ((cr1 & USART_CR1_TXEIE) != 0u && (sr & USART_SR_TXE) != 0u) {
        if (k_console_feed() && !k_console_lf_held)
            USART_CR1(USART1_BASE) = cr1 & ~USART_CR1_TXEIE;
        if (k_sem_has_waiter(&k_console_space))
            (void)k_sem_post(&k_console_space);
    }
}

/* The interrupt-driven writer the board registers (k_console_register). */
static size_t stm32_console_write(const char *s, size_t len)
{
    size_t done = 0;
    int can_wait = k_can_block();
    while (done < len) {
        uint32_t irq = k_arch_irq_save();
        int put = k_ring_put(&k_console_ring, (uint8_t)s[done]);
        k_console_tx_start();
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

/* The polled writer: the early console, and fault reports in any context. */
static void stm32_console_write_sync(const char *s, size_t len)
{
    uint32_t irq = k_arch_irq_save();
    size_t i;
    while (!k_console_feed() || k_console_lf_held) {
        /* drain what was queued first, so the report comes out in order */
    }
    for (i = 0; i < len; i++)
        console_putc_polled(s[i]);
    k_arch_irq_restore(irq);
}

uint32_t k_board_console_dropped(void)
{
    return k_console_drops;
}

void stm32f405_console_rx_attach(void (*fn)(uint8_t byte))
{
    uint32_t irq = k_arch_irq_save();
    k_console_rx_fn = fn;
    if (fn != NULL)
        USART_CR1(USART1_BASE) |= USART_CR1_RXNEIE;
    else
        USART_CR1(USART1_BASE) &= ~USART_CR1_RXNEIE;
    k_arch_irq_restore(irq);
}

static void k_board_tick(void)
{
    void (*cb)(void);
    k_tick();
    cb = k_board_tick_callback;
    if (cb != NULL)
        cb();
}

int k_board_init(void)
{
    RCC_APB2ENR |= RCC_APB2ENR_USART1EN;
    USART_CR1(USART1_BASE) = 0;
    USART_BRR(USART1_BASE) = USART1_BRR_115200;
    USART_CR1(USART1_BASE) = USART_CR1_UE | USART_CR1_TE | USART_CR1_RE;
    kprintf_set_output(console_putc_polled);
    k_console_register(NULL, stm32_console_write_sync);
    (void)k_ring_init(&k_console_ring, k_console_buf, sizeof k_console_buf);
    (void)k_sem_init(&k_console_space, 0, 1);
    k_console_lf_held = 0;
    k_console_drops = 0;
    k_console_rx_fn = NULL;
    if (k_irq_register(ARMV7M_IRQ_VECTOR(USART1_IRQ), CONSOLE_LEVEL, k_console_isr, NULL) != K_OK)
        return -1;
    k_console_register(stm32_console_write, stm32_console_write_sync);
    return armv7m_systick_start(STM32F405_CPU_HZ, K_TICK_HZ, k_board_tick);
}
