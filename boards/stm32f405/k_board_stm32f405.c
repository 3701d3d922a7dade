/*
 * Board support of the nanokernel on the STM32F405 (kernel/include/k_board.h):
 * the console on USART1 and the tick on SysTick. The one file that glues the
 * board's console and tick to the kernel.
 *
 * Console output: the kernel's shared transmitter (k_console_tx.h) on
 * USART1, whose TXE interrupt (kernel level 5, NVIC line 37) feeds it and is
 * disabled when all is sent (see usart_tx_start for what QEMU's model lacks
 * there). The polled writer drains the ring and sends by polling, with
 * interrupts masked, for fault reports; it is the console until
 * k_board_init has set up the interrupt-driven one (both registered with
 * k_console_register).
 *
 * Console input: the same interrupt hands each received byte to the
 * receiver's sink (stm32f405_console_rx_attach); while the sink is full,
 * RXNE's interrupt is off and the next byte waits in the data register,
 * which holds the rest back (QEMU's model takes no byte from the host while
 * it is occupied; a real chip overruns, and says so). One byte may be held
 * here instead (see k_console_isr).
 *
 * The tick: SysTick from the 168 MHz core clock at K_TICK_HZ, kernel level 4
 * (below the console, as the PIT is below the DUART on the RoboCube). The
 * kernel's fine time stamp (k_timestamp) counts the same clock through
 * SysTick (armv7m_systick_cycles), at 168 MHz.
 */
#include "kernel.h"
#include "k_board.h"
#include "k_console_tx.h"
#include "k_struct.h"
#include "armv7m.h"
#include "stm32f405.h"
#include "kernel/lib/kprintf.h"
#include "boards/stm32f405/board_stm32f405.h"
#include "boards/include/board.h"

#define CONSOLE_LEVEL 5u

void (*volatile k_board_tick_callback)(void);

static uint8_t k_console_buf[K_BOARD_CONSOLE_RING];
static struct k_console_tx k_console;
static volatile board_console_rx_sink k_console_rx_fn;
/* A byte taken from the USART as reception paused (see k_console_isr), and
 * its flags; handed to the sink when reception resumes. */
static int k_console_rx_held = -1;
static unsigned k_console_rx_held_flags;

static unsigned usart_rx_flags(uint32_t sr)
{
    return (sr & USART_SR_ORE) != 0u ? BOARD_RX_OVERRUN : (sr & USART_SR_ERRORS) != 0u ? BOARD_RX_ERROR : 0u;
}

/* Polled output, for kprintf and the fault reports. */
static void console_putc_polled(char c)
{
    if (c == '\n')
        console_putc_polled('\r');
    while ((USART_SR(USART1_BASE) & USART_SR_TXE) == 0u) {
    }
    USART_DR(USART1_BASE) = (uint8_t)c;
}

/* USART1's transmitter, for the shared console transmitter. */
static int usart_tx_ready(void)
{
    return (USART_SR(USART1_BASE) & USART_SR_TXE) != 0u;
}

static void usart_tx_put(uint8_t b)
{
    USART_DR(USART1_BASE) = b;
}

/* Enables the TXE interrupt and also sets the line pending in the NVIC:
 * QEMU 7.2's USART model raises its interrupt for received bytes only, never
 * for TXE (its transmitter is always empty). On a real chip the pending bit
 * only brings the handler in a little early: it feeds while TXE is set. */
static void usart_tx_start(void)
{
    USART_CR1(USART1_BASE) |= USART_CR1_TXEIE;
    NVIC_ISPR(USART1_IRQ / 32u) = 1u << (USART1_IRQ % 32u);
}

static void k_console_isr(void *arg)
{
    uint32_t sr = USART_SR(USART1_BASE), cr1 = USART_CR1(USART1_BASE);
    (void)arg;
    if ((cr1 & USART_CR1_RXNEIE) != 0u && (sr & USART_SR_RXNE) != 0u) {
        /* reading DR after SR clears RXNE and the error flags */
        board_console_rx_sink fn = k_console_rx_fn;
        if (fn == NULL || !fn((uint8_t)USART_DR(USART1_BASE), usart_rx_flags(sr))) {
            USART_CR1(USART1_BASE) &= ~USART_CR1_RXNEIE;
            /* A byte that came in before the interrupt was off has raised
             * the line, and QEMU's model lowers it only when DR is read (a
             * chip lowers it with RXNEIE): left there, it would call this
             * handler for ever. It is taken now and handed over on resume. */
            sr = USART_SR(USART1_BASE);
            if ((sr & USART_SR_RXNE) != 0u) {
                k_console_rx_held_flags = usart_rx_flags(sr);
                k_console_rx_held = (int)(USART_DR(USART1_BASE) & 0xFFu);
            }
        }
    }
    if ((cr1 & USART_CR1_TXEIE) != 0u && (sr & USART_SR_TXE) != 0u &&
        k_console_tx_isr(&k_console))
        USART_CR1(USART1_BASE) &= ~USART_CR1_TXEIE;
}

/* The interrupt-driven writer the board registers (k_console_register). */
static size_t stm32_console_write(const char *s, size_t len)
{
    return k_console_tx_write(&k_console, s, len);
}

/* The polled writer: the early console, and fault reports in any context. */
static void stm32_console_write_sync(const char *s, size_t len)
{
    uint32_t irq = k_arch_irq_save();
    size_t i;
    k_console_tx_drain(&k_console); /* what was queued first, so the report comes out in order */
    for (i = 0; i < len; i++)
        console_putc_polled(s[i]);
    k_arch_irq_restore(irq);
}

uint32_t k_board_console_dropped(void)
{
    return k_console.drops;
}

int stm32f405_console_rx_attach(board_console_rx_sink fn)
{
    uint32_t irq = k_arch_irq_save();
    int rc = fn != NULL && k_console_rx_fn != NULL ? -1 : 0;
    if (rc == 0) {
        k_console_rx_fn = fn;
        stm32f405_console_rx_resume();
    }
    k_arch_irq_restore(irq);
    return rc;
}

void stm32f405_console_rx_resume(void)
{
    uint32_t irq = k_arch_irq_save();
    board_console_rx_sink fn = k_console_rx_fn;
    int more = fn != NULL;
    if (more && k_console_rx_held >= 0) {
        more = fn((uint8_t)k_console_rx_held, k_console_rx_held_flags);
        k_console_rx_held = -1;
    }
    if (more)
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
    (void)k_console_tx_init(&k_console, k_console_buf, sizeof k_console_buf, usart_tx_ready,
                            usart_tx_put, usart_tx_start);
    k_console_rx_fn = NULL;
    k_console_rx_held = -1;
    if (k_irq_register(ARMV7M_IRQ_VECTOR(USART1_IRQ), CONSOLE_LEVEL, k_console_isr, NULL) != K_OK)
        return -1;
    k_console_register(stm32_console_write, stm32_console_write_sync);
    if (armv7m_systick_start(STM32F405_CPU_HZ, K_TICK_HZ, k_board_tick) != 0)
        return -1;
    /* The kernel's fine time stamp: processor clocks, from SysTick. Not
     * the DWT's cycle counter: QEMU 7.2 has no DWT (its registers read as
     * 0); SysTick's count it models, in virtual time. */
    k_timestamp_register(armv7m_systick_cycles, STM32F405_CPU_HZ, NULL);
    return 0;
}
