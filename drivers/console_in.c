/* Interrupt-driven console input; see console_in.h. */
#include "console_in.h"

#include "kernel.h"
#include "boards/include/board.h"
#include "drivers/drv_err.h"
#include "drivers/line_edit.h"

static uint8_t rx_buf[CONSOLE_IN_RING];
static struct k_ring rx_ring;
static struct k_sem rx_ready;      /* posted by the interrupt when bytes arrive */
static volatile int rx_paused;     /* the ring filled: the board holds the bytes */
static int initialised;
static int echo_on = 1;
static char line_buf[CONSOLE_IN_LINE_MAX + 1u];
static struct line_edit editor;
static struct console_in_stats stats;

/* The board's receive interrupt, one byte at a time: into the ring; 0 (the
 * board then pauses) when that filled it. */
static int console_rx_byte(uint8_t byte, unsigned flags)
{
    if ((flags & BOARD_RX_OVERRUN) != 0u)
        stats.overruns++;
    else if ((flags & BOARD_RX_ERROR) != 0u)
        stats.errors++;
    (void)k_ring_put(&rx_ring, byte);
    stats.bytes++;
    (void)k_sem_post(&rx_ready); /* a binary semaphore: at most one wake-up kept */
    if (k_ring_free(&rx_ring) > 0u)
        return 1;
    rx_paused = 1;
    stats.ring_full++;
    return 0;
}

int console_in_init(void)
{
    if (initialised)
        return DRV_ERR_STATE;
    (void)k_ring_init(&rx_ring, rx_buf, sizeof rx_buf);
    (void)k_sem_init(&rx_ready, 0, 1);
    line_edit_init(&editor, line_buf, sizeof line_buf);
    rx_paused = 0;
    if (board_console_rx_start(console_rx_byte) != 0)
        return DRV_ERR_STATE;
    initialised = 1;
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
    int got;
    uint32_t s = k_arch_irq_save();
    got = k_ring_get(&rx_ring, byte);
    if (got && rx_paused && k_ring_free(&rx_ring) >= CONSOLE_IN_RING / 2u) {
        rx_paused = 0;
        board_console_rx_resume();
    }
    k_arch_irq_restore(s);
    return got;
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
