/*
 * Board support of the nanokernel on the MPS2 AN385 (kernel/include/k_board.h):
 * the console on the CMSDK UART0 and the tick on SysTick. The one file that
 * glues the board's console and tick to the kernel.
 *
 * Console output: the kernel's shared transmitter (k_console_tx.h) on UART0.
 * The UART raises its TX interrupt (kernel level 5, NVIC line 1) when a byte
 * has left, so the handler feeds the next; the first of a burst has no byte
 * before it, so starting sets the line pending (uart_tx_start). The polled
 * writer drains the ring and sends by polling, with interrupts masked, for
 * fault reports; it is the console until k_board_init has set up the
 * interrupt-driven one (both registered with k_console_register).
 *
 * Console input: the RX interrupt (line 0, the same level and handler) hands
 * each received byte to the receiver's sink (mps2_an385_console_rx_attach);
 * while the sink is full the RX interrupt is off and the next byte waits in
 * the UART, which takes no more from the line until it is read.
 *
 * The tick: SysTick from the 25 MHz core clock at K_TICK_HZ, kernel level 4
 * (below the console, as on the other boards).
 */
#include "kernel.h"
#include "k_board.h"
#include "k_console_tx.h"
#include "k_struct.h"
#include "armv7m.h"
#include "mps2_an385.h"
#include "kernel/lib/kprintf.h"
#include "boards/mps2-an385/board_mps2_an385.h"
#include "boards/include/board.h"

#define CONSOLE_LEVEL 5u

void (*volatile k_board_tick_callback)(void);

static uint8_t k_console_buf[K_BOARD_CONSOLE_RING];
static struct k_console_tx k_console;
static volatile board_console_rx_sink k_console_rx_fn;

/* Polled output, for kprintf and the fault reports. */
static void console_putc_polled(char c)
{
    if (c == '\n')
        console_putc_polled('\r');
    while ((UART_STATE(UART0_BASE) & UART_STATE_TXFULL) != 0u) {
    }
    UART_DATA(UART0_BASE) = (uint8_t)c;
}

/* UART0's transmitter, for the shared console transmitter. */
static int uart_tx_ready(void)
{
    return (UART_STATE(UART0_BASE) & UART_STATE_TXFULL) == 0u;
}

static void uart_tx_put(uint8_t b)
{
    UART_DATA(UART0_BASE) = b;
}

/* Enables the TX interrupt and sets its line pending: the interrupt comes
 * when a byte has been sent, and the first byte of a burst is sent by the
 * handler. */
static void uart_tx_start(void)
{
    UART_CTRL(UART0_BASE) |= UART_CTRL_TX_INTEN;
    NVIC_ISPR(UART0_TX_IRQ / 32u) = 1u << (UART0_TX_IRQ % 32u);
}

static void k_console_isr(void *arg)
{
    uint32_t ctrl = UART_CTRL(UART0_BASE);
    (void)arg;
    if ((ctrl & UART_CTRL_RX_INTEN) != 0u) {
        UART_INT(UART0_BASE) = UART_INT_RX;
        while ((UART_STATE(UART0_BASE) & UART_STATE_RXFULL) != 0u) {
            uint32_t state = UART_STATE(UART0_BASE);
            unsigned flags = (state & UART_STATE_RXOVERRUN) != 0u ? BOARD_RX_OVERRUN : 0u;
            board_console_rx_sink fn = k_console_rx_fn;
            UART_STATE(UART0_BASE) = UART_STATE_RXOVERRUN;   /* write 1: clear */
            /* reading DATA empties the receiver, which then takes the next byte */
            if (fn == NULL || !fn((uint8_t)UART_DATA(UART0_BASE), flags)) {
                UART_CTRL(UART0_BASE) &= ~UART_CTRL_RX_INTEN;
                break;
            }
        }
    }
    if ((ctrl & UART_CTRL_TX_INTEN) != 0u) {
        UART_INT(UART0_BASE) = UART_INT_TX;
        if (k_console_tx_isr(&k_console)) {
            UART_CTRL(UART0_BASE) &= ~UART_CTRL_TX_INTEN;
            UART_INT(UART0_BASE) = UART_INT_TX;   /* the last byte's, raised as it left */
        }
    }
}

/* The interrupt-driven writer the board registers (k_console_register). */
static size_t mps2_console_write(const char *s, size_t len)
{
    return k_console_tx_write(&k_console, s, len);
}

/* The polled writer: the early console, and fault reports in any context. */
static void mps2_console_write_sync(const char *s, size_t len)
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

int mps2_an385_console_rx_attach(board_console_rx_sink fn)
{
    uint32_t irq = k_arch_irq_save();
    int rc = fn != NULL && k_console_rx_fn != NULL ? -1 : 0;
    if (rc == 0) {
        k_console_rx_fn = fn;
        mps2_an385_console_rx_resume();
    }
    k_arch_irq_restore(irq);
    return rc;
}

/* A byte that came while reception paused raised no interrupt: the line is
 * set pending so the handler takes it. */
void mps2_an385_console_rx_resume(void)
{
    uint32_t irq = k_arch_irq_save();
    if (k_console_rx_fn != NULL) {
        UART_CTRL(UART0_BASE) |= UART_CTRL_RX_INTEN;
        if ((UART_STATE(UART0_BASE) & UART_STATE_RXFULL) != 0u)
            NVIC_ISPR(UART0_RX_IRQ / 32u) = 1u << (UART0_RX_IRQ % 32u);
    } else {
        UART_CTRL(UART0_BASE) &= ~UART_CTRL_RX_INTEN;
    }
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
    UART_CTRL(UART0_BASE) = 0;
    UART_BAUDDIV(UART0_BASE) = UART0_BAUDDIV_115200;
    UART_CTRL(UART0_BASE) = UART_CTRL_TX_EN | UART_CTRL_RX_EN;
    kprintf_set_output(console_putc_polled);
    k_console_register(NULL, mps2_console_write_sync);
    (void)k_console_tx_init(&k_console, k_console_buf, sizeof k_console_buf, uart_tx_ready,
                            uart_tx_put, uart_tx_start);
    k_console_rx_fn = NULL;
    if (k_irq_register(ARMV7M_IRQ_VECTOR(UART0_TX_IRQ), CONSOLE_LEVEL, k_console_isr, NULL) != K_OK ||
        k_irq_register(ARMV7M_IRQ_VECTOR(UART0_RX_IRQ), CONSOLE_LEVEL, k_console_isr, NULL) != K_OK)
        return -1;
    k_console_register(mps2_console_write, mps2_console_write_sync);
    if (armv7m_systick_start(MPS2_AN385_CPU_HZ, K_TICK_HZ, k_board_tick) != 0)
        return -1;
    /* The kernel's fine time stamp: processor clocks counted through SysTick
     * (QEMU models no DWT cycle counter), as on the STM32F405. */
    k_timestamp_register(armv7m_systick_cycles, MPS2_AN385_CPU_HZ, NULL);
    return 0;
}
