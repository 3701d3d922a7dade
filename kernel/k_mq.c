/*
 * Message queues of fixed-size messages. A sender that finds a receiver
 * waiting copies straight into the receiver's buffer; a receiver that frees a
 * slot moves the most urgent blocked sender's message in, so the order of
 * messages is the order in which senders got their turn.
 */
#include "k_internal.h"

int k_mq_init(struct k_mq *q, void *storage, size_t msg_size, size_t capacity)
{
    if (q == NULL || k_msgbuf_init(&q->buf, storage, msg_size, capacity) != 0)
        return K_EINVAL;
    k_waitq_init(&q->senders);
    k_waitq_init(&q->receivers);
    q->magic = K_MAGIC_MQ;
    return K_OK;
}

/* An initialised queue and a message buffer: what send and receive require. */
static int k_mq_args_ok(const struct k_mq *q, const void *msg)
{
    return q != NULL && q->magic == K_MAGIC_MQ && msg != NULL;
}

int k_mq_send_ticks(struct k_mq *q, const void *msg, k_ticks_t timeout)
{
    uint32_t irq;
    int32_t r = K_OK;
    struct k_thread *w;
    if (!k_mq_args_ok(q, msg))
        return K_EINVAL;
    irq = k_arch_irq_save();
    w = k_waitq_first(&q->receivers);
    if (w != NULL) {
        k_memcpy(w->wait_dst, msg, q->buf.msg_size);
        k_wake(w, K_OK);
        k_resched();
    } else if (k_msgbuf_put(&q->buf, msg) == 0) {
        r = K_OK;
    } else {
        k_kernel.current->wait_src = msg; /* read only while it waits */
        r = k_block_or_refuse(&q->senders, timeout);
    }
    k_arch_irq_restore(irq);
    return r;
}

int k_mq_receive_ticks(struct k_mq *q, void *msg, k_ticks_t timeout)
{
    uint32_t irq;
    int32_t r = K_OK;
    if (!k_mq_args_ok(q, msg))
        return K_EINVAL;
    irq = k_arch_irq_save();
    if (k_msgbuf_get(&q->buf, msg) == 0) {
        struct k_thread *w = k_waitq_first(&q->senders);
        if (w != NULL) {
            (void)k_msgbuf_put(&q->buf, w->wait_src);
            k_wake(w, K_OK);
            k_resched();
        }
    } else {
        k_kernel.current->wait_dst = msg; /* written only while it waits */
        r = k_block_or_refuse(&q->receivers, timeout);
    }
    k_arch_irq_restore(irq);
    return r;
}

int k_mq_send(struct k_mq *q, const void *msg)
{
    return k_mq_send_ticks(q, msg, K_FOREVER);
}

int k_mq_receive(struct k_mq *q, void *msg)
{
    return k_mq_receive_ticks(q, msg, K_FOREVER);
}

int k_mq_timedsend(struct k_mq *q, const void *msg, const struct k_timespec *abs_monotonic)
{
    k_ticks_t t;
    int r = k_abs_to_timeout(abs_monotonic, &t);
    return r != K_OK ? r : k_timed_result(k_mq_send_ticks(q, msg, t), K_EAGAIN);
}

int k_mq_timedreceive(struct k_mq *q, void *msg, const struct k_timespec *abs_monotonic)
{
    k_ticks_t t;
    int r = k_abs_to_timeout(abs_monotonic, &t);
    return r != K_OK ? r : k_timed_result(k_mq_receive_ticks(q, msg, t), K_EAGAIN);
}

int k_mq_count(struct k_mq *q)
{
    if (q == NULL || q->magic != K_MAGIC_MQ)
        return K_EINVAL;
    return (int)q->buf.count;
}
