/* Interrupt-driven console input; see console_in.h. */
#include "console_in.h"

#include "kernel.h"
#include "drivers/drv_err.h"
#include "boards/robocube/duart.h"
#include "drivers/line_edit.h"
#include "boards/robocube/mc68681.h"

#define SR_ERRORS 0xF0u            /* received break, framing, parity, overrun */

static uint8_t rx_buf[CONSOLE_IN_RING];
static struct k_ring rx_ring;
static struct k_sem rx_ready;      /* posted by the interrupt when bytes arrive */
static volatile int rx_paused;     /* the ring filled: RxRDYB masked until drained */
static int initialised;
static int echo_on = 1;
static char line_buf[CONSOLE_IN_LINE_MAX + 1u];
static struct line_edit editor;
static struct console_in_stats stats;

static void console_rx_isr(uint8_t pending, void *arg)
{
    int got = 0;
    (void)pending;
    (void)arg;
    for (;;) {
        uint8_t sr = DUART_REG(DUART_SRB);
        if ((sr & DUART_SR_RXRDY) == 0u)
            break;
        if (k_ring_free(&rx_ring) == 0u) {
            /* leave the byte in the FIFO: the host (or the chip) holds the rest */
            duart_imr_update(0, DUART_INT_RXRDYB);
            rx_paused = 1;
            stats.ring_full++;
            break;
        }
        if ((sr & SR_ERRORS) != 0u) {
            if ((sr & DUART_SR_OVERRUN) != 0u)
                stats.overruns++;
            else
                stats.errors++;
            DUART_REG(DUART_CRB) = DUART_CR_RESET_ERROR;
        }
        (void)k_ring_put(&rx_ring, DUART_REG(DUART_RBB));
        stats.bytes++;
        got = 1;
    }
    if (got)
        (void)k_sem_post(&rx_ready);
}

int console_in_init(void)
{
    if (initialised)
        return DRV_ERR_STATE;
    (void)k_ring_init(&rx_ring, rx_buf, sizeof rx_buf);
    (void)k_sem_init(&rx_ready, 0, 1);
    line_edit_init(&editor, line_buf, sizeof line_buf);
    rx_paused = 0;
    if (duart_irq_attach(DUART_INT_RXRDYB, console_rx_isr, NULL) != 0)
        return DRV_ERR_STATE;
    initialised = 1;
    duart_imr_update(DUART_INT_RXRDYB, 0);
    return DRV_OK;
}

void console_in_set_echo(int on)
{
    echo_on = on != 0;
}

void console_in_stats(struct console_in_stats *out)
{
    uint32_t s = k_arch_irq_save();
    *out = stats;
    k_arch_irq_restore(s);
}

/* One byte from the ring, resuming reception once there is room again. */
static int ring_take(uint8_t *byte)
{
    if (!k_ring_get(&rx_ring, byte))
        return 0;
    if (rx_paused && k_ring_free(&rx_ring) >= CONSOLE_IN_RING / 2u) {
        rx_paused = 0;
        duart_imr_update(DUART_INT_RXRDYB, 0);
    }
    return 1;
}

/* Waits until the deadline for the interrupt to bring something. */
static int wait_bytes(k_ticks_t deadline)
{
    k_ticks_t now = k_ticks();
    k_ticks_t left = (k_ticks_t)(deadline - now);
    if (left == 0u || left > (k_ticks_t)0x7FFFFFFFu)
        return DRV_ERR_TIMEOUT;
    return k_sem_wait_ticks(&rx_ready, left) == K_OK ? DRV_OK : DRV_ERR_TIMEOUT;
}

int console_read_line(char *buf, size_t size, uint32_t timeout_ms)
{
    k_ticks_t deadline;
    size_t limit;
    if (!initialised)
        return DRV_ERR_STATE;
    if (buf == NULL || size == 0u)
        return DRV_ERR_PARAM;
    if (timeout_ms > CONSOLE_IN_TIMEOUT_MAX_MS)
        timeout_ms = CONSOLE_IN_TIMEOUT_MAX_MS;
    deadline = k_ticks() + k_ms_to_ticks(timeout_ms);
    /* The caller's buffer bounds the line too; a half-typed line that is
     * already longer is refused when it ends. */
    limit = size < sizeof line_buf ? size : sizeof line_buf;
    editor.size = limit;
    if (editor.len + 1u > limit && !editor.complete)
        editor.overflow = 1;
    for (;;) {
        uint8_t byte;
        while (ring_take(&byte)) {
            char echo[LINE_EDIT_ECHO_MAX];
            size_t echo_len;
            enum line_edit_result r = line_edit_feed(&editor, byte, echo, &echo_len);
            if (echo_on && echo_len > 0u)
                (void)k_console_write(echo, echo_len);
            if (r == LINE_EDIT_DONE) {
                k_memcpy(buf, line_buf, editor.len + 1u);
                stats.lines++;
                return (int)editor.len;
            }
            if (r == LINE_EDIT_TOO_LONG) {
                stats.too_long++;
                return DRV_ERR_RANGE;
            }
            if (r == LINE_EDIT_CANCELLED) {
                buf[0] = '\0';
                return 0;
            }
        }
        if (wait_bytes(deadline) != DRV_OK && k_ring_used(&rx_ring) == 0u)
            return DRV_ERR_TIMEOUT;
    }
}
