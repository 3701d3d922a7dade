/* The console transmitter the boards share; see k_console_tx.h. */
#include "k_console_tx.h"

int k_console_tx_init(struct k_console_tx *tx, uint8_t *buf, size_t size, int (*ready)(void),
                      void (*put)(uint8_t byte), void (*start)(void))
{
    if (tx == NULL || ready == NULL || put == NULL || start == NULL ||
        k_ring_init(&tx->ring, buf, size) != K_OK)
        return K_EINVAL;
    (void)k_sem_init(&tx->space, 0, 1);
    tx->lf_held = 0;
    tx->drops = 0;
    tx->ready = ready;
    tx->put = put;
    tx->start = start;
    return K_OK;
}

/* Feeds the transmitter while it is ready and there is something to send.
 * Interrupts masked (handler or caller). Returns whether all is sent. */
static int k_console_tx_feed(struct k_console_tx *tx)
{
    while (tx->ready()) {
        uint8_t b;
        if (tx->lf_held) {
            tx->lf_held = 0;
            tx->put('\n');
            continue;
        }
        if (!k_ring_get(&tx->ring, &b))
            return 1;
        if (b == '\n') {
            tx->lf_held = 1;
            b = '\r';
        }
        tx->put(b);
    }
    return 0;
}

int k_console_tx_isr(struct k_console_tx *tx)
{
    int done = k_console_tx_feed(tx) && !tx->lf_held;
    /* Posted whether or not a writer waits yet (the semaphore keeps one
     * wake-up): a writer that found the ring full and has not reached its
     * wait when this drains the ring must not wait for an interrupt that
     * will not come. */
    (void)k_sem_post(&tx->space);
    return done;
}

size_t k_console_tx_write(struct k_console_tx *tx, const char *s, size_t len)
{
    size_t done = 0;
    int can_wait = k_can_block();
    while (done < len) {
        uint32_t irq = k_arch_irq_save();
        int put = k_ring_put(&tx->ring, (uint8_t)s[done]);
        tx->start();
        k_arch_irq_restore(irq);
        if (put) {
            done++;
        } else if (can_wait && irq == 0u) {
            (void)k_sem_wait(&tx->space);
        } else {
            tx->drops += (uint32_t)(len - done);
            break;
        }
    }
    return done;
}

void k_console_tx_drain(struct k_console_tx *tx)
{
    while (!k_console_tx_feed(tx) || tx->lf_held) {
        /* until the ring is empty and a held LF is out */
    }
}
