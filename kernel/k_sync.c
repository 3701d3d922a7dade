/*
 * Counting semaphores, mutexes with priority inheritance, condition
 * variables, event flags.
 *
 * Hand-off: a post or unlock gives the unit or the mutex straight to the most
 * urgent waiter (FIFO among equals) before it runs, so a thread that calls
 * again at once cannot overtake it.
 */
#include "k_internal.h"

/* ---- semaphores ---- */

int k_sem_init(struct k_sem *s, uint32_t initial, uint32_t max)
{
    if (s == NULL || max == 0u || initial > max)
        return K_EINVAL;
    s->count = initial;
    s->max = max;
    k_waitq_init(&s->wq);
    s->magic = K_MAGIC_SEM;
    return K_OK;
}

int k_sem_wait_ticks(struct k_sem *s, k_ticks_t timeout)
{
    uint32_t irq;
    int32_t r;
    if (s == NULL || s->magic != K_MAGIC_SEM)
        return K_EINVAL;
    irq = k_arch_irq_save();
    if (s->count > 0u) {
        s->count--;
        r = K_OK;
    } else {
        r = k_block_or_refuse(&s->wq, timeout);
    }
    k_arch_irq_restore(irq);
    return r;
}

int k_sem_wait(struct k_sem *s)
{
    return k_sem_wait_ticks(s, K_FOREVER);
}

int k_sem_trywait(struct k_sem *s)
{
    return k_sem_wait_ticks(s, K_NO_WAIT);
}

int k_sem_timedwait(struct k_sem *s, const struct k_timespec *abs_monotonic)
{
    k_ticks_t t;
    int r = k_abs_to_timeout(abs_monotonic, &t);
    return r != K_OK ? r : k_timed_result(k_sem_wait_ticks(s, t), K_EAGAIN);
}

int k_sem_post(struct k_sem *s)
{
    uint32_t irq;
    int r = K_OK;
    struct k_thread *w;
    if (s == NULL || s->magic != K_MAGIC_SEM)
        return K_EINVAL;
    irq = k_arch_irq_save();
    w = k_waitq_first(&s->wq);
    if (w != NULL) {
        k_wake(w, K_OK);
        k_resched();
    } else if (s->count < s->max) {
        s->count++;
    } else {
        r = K_EOVERFLOW;
    }
    k_arch_irq_restore(irq);
    return r;
}

int k_sem_getvalue(struct k_sem *s, int32_t *value)
{
    if (s == NULL || s->magic != K_MAGIC_SEM || value == NULL)
        return K_EINVAL;
    *value = (int32_t)s->count;
    return K_OK;
}

int k_sem_has_waiter(const struct k_sem *s)
{
    return s != NULL && k_waitq_first(&s->wq) != NULL;
}

/* ---- mutexes ---- */

int k_mutex_init(struct k_mutex *m)
{
    if (m == NULL)
        return K_EINVAL;
    m->owner = NULL;
    m->owner_died = 0;
    k_waitq_init(&m->wq);
    m->held_node.next = NULL;
    m->held_node.prev = NULL;
    m->magic = K_MAGIC_MUTEX;
    return K_OK;
}

static void k_mutex_take(struct k_mutex *m, struct k_thread *t)
{
    m->owner = t;
    k_list_append(&t->held, &m->held_node);
}

/* Passes m from its owner to the most urgent waiter (or frees it). */
static void k_mutex_pass(struct k_mutex *m, int32_t result)
{
    struct k_thread *old = m->owner;
    struct k_thread *w = k_waitq_first(&m->wq);
    k_list_remove(&m->held_node);
    m->owner = NULL;
    if (w != NULL) {
        w->wait_mutex = NULL; /* no longer waiting: k_wake must not undo a boost */
        k_wake(w, result);
        k_mutex_take(m, w);
        k_prio_update(w); /* inherits from the waiters that remain */
    } else if (result == K_EOWNERDEAD) {
        m->owner_died = 1; /* the next locker learns of it */
    }
    k_prio_update(old); /* drops what m's waiters lent it */
}

int k_mutex_lock_ticks(struct k_mutex *m, k_ticks_t timeout)
{
    uint32_t irq;
    int32_t r;
    struct k_thread *self = k_kernel.current;
    if (m == NULL || m->magic != K_MAGIC_MUTEX)
        return K_EINVAL;
    if (k_in_isr())
        return K_EISR; /* a handler can never own a mutex */
    irq = k_arch_irq_save();
    if (m->owner == NULL) {
        k_mutex_take(m, self);
        r = m->owner_died ? K_EOWNERDEAD : K_OK;
        m->owner_died = 0;
    } else if (m->owner == self) {
        r = K_EDEADLK;
    } else if (timeout == K_NO_WAIT) {
        r = K_EBUSY;
    } else {
        self->wait_mutex = m;
        k_block_prepare(&m->wq, timeout);
        k_prio_update(m->owner); /* lend our priority down the chain of owners */
        r = k_block_commit();
    }
    k_arch_irq_restore(irq);
    return r;
}

int k_mutex_lock(struct k_mutex *m)
{
    return k_mutex_lock_ticks(m, K_FOREVER);
}

int k_mutex_trylock(struct k_mutex *m)
{
    return k_mutex_lock_ticks(m, K_NO_WAIT);
}

int k_mutex_timedlock(struct k_mutex *m, const struct k_timespec *abs_monotonic)
{
    k_ticks_t t;
    int r = k_abs_to_timeout(abs_monotonic, &t);
    return r != K_OK ? r : k_timed_result(k_mutex_lock_ticks(m, t), K_EBUSY);
}

/* With interrupts masked: passes m on if the running thread owns it (K_OK),
 * else K_EPERM and m stays as it is. The release step of unlock and of a
 * condition wait. */
static int k_mutex_release_own(struct k_mutex *m)
{
    if (m->owner != k_kernel.current)
        return K_EPERM;
    k_mutex_pass(m, K_OK);
    return K_OK;
}

int k_mutex_unlock(struct k_mutex *m)
{
    uint32_t irq;
    int r;
    if (m == NULL || m->magic != K_MAGIC_MUTEX)
        return K_EINVAL;
    if (k_in_isr())
        return K_EISR;
    irq = k_arch_irq_save();
    r = k_mutex_release_own(m);
    if (r == K_OK)
        k_resched();
    k_arch_irq_restore(irq);
    return r;
}

void k_mutex_waiter_gone(struct k_mutex *m)
{
    if (m->owner != NULL)
        k_prio_update(m->owner);
}

void k_mutex_release_all(struct k_thread *t)
{
    struct k_list_node *n;
    while ((n = k_list_first(&t->held)) != NULL)
        k_mutex_pass(K_CONTAINER_OF(n, struct k_mutex, held_node), K_EOWNERDEAD);
}

/* ---- condition variables ---- */

int k_cond_init(struct k_cond *c)
{
    if (c == NULL)
        return K_EINVAL;
    k_waitq_init(&c->wq);
    c->magic = K_MAGIC_COND;
    return K_OK;
}

int k_cond_wait_ticks(struct k_cond *c, struct k_mutex *m, k_ticks_t timeout)
{
    uint32_t irq;
    int32_t r;
    int relock;
    if (c == NULL || c->magic != K_MAGIC_COND || m == NULL || m->magic != K_MAGIC_MUTEX)
        return K_EINVAL;
    if (k_in_isr())
        return K_EISR;
    irq = k_arch_irq_save();
    /* The unlock and the wait are one step with interrupts masked: a signal
     * can come only once this thread is in c's queue. */
    if (k_mutex_release_own(m) != K_OK) {
        k_arch_irq_restore(irq);
        return K_EPERM;
    }
    if (timeout == K_NO_WAIT) {
        k_resched(); /* a waiter the unlock woke may be more urgent */
        r = K_ETIMEDOUT;
    } else {
        r = k_block(&c->wq, timeout);
    }
    k_arch_irq_restore(irq);
    relock = k_mutex_lock_ticks(m, K_FOREVER);
    return relock == K_OK ? r : relock;
}

int k_cond_wait(struct k_cond *c, struct k_mutex *m)
{
    return k_cond_wait_ticks(c, m, K_FOREVER);
}

int k_cond_timedwait(struct k_cond *c, struct k_mutex *m, const struct k_timespec *abs_monotonic)
{
    k_ticks_t t;
    int r = k_abs_to_timeout(abs_monotonic, &t);
    return r != K_OK ? r : k_cond_wait_ticks(c, m, t);
}

static int k_cond_wake(struct k_cond *c, int all)
{
    uint32_t irq;
    struct k_thread *w;
    if (c == NULL || c->magic != K_MAGIC_COND)
        return K_EINVAL;
    irq = k_arch_irq_save();
    while ((w = k_waitq_first(&c->wq)) != NULL) {
        k_wake(w, K_OK);
        if (!all)
            break;
    }
    k_resched();
    k_arch_irq_restore(irq);
    return K_OK;
}

int k_cond_signal(struct k_cond *c)
{
    return k_cond_wake(c, 0);
}

int k_cond_broadcast(struct k_cond *c)
{
    return k_cond_wake(c, 1);
}

/* ---- event flags ---- */

int k_event_init(struct k_event *e)
{
    if (e == NULL)
        return K_EINVAL;
    e->bits = 0;
    k_waitq_init(&e->wq);
    e->magic = K_MAGIC_EVENT;
    return K_OK;
}

static uint32_t k_event_match(uint32_t bits, uint32_t mask, uint32_t flags)
{
    uint32_t hit = bits & mask;
    if ((flags & K_EVENT_ALL) != 0u)
        return hit == mask ? hit : 0u;
    return hit;
}

int k_event_set(struct k_event *e, uint32_t bits)
{
    uint32_t irq, consumed = 0;
    struct k_list_node *n, *next;
    if (e == NULL || e->magic != K_MAGIC_EVENT)
        return K_EINVAL;
    irq = k_arch_irq_save();
    e->bits |= bits;
    /* Every waiter is judged against the bits as set here (a broadcast);
     * the bits that clearing waiters consumed go only after all are judged. */
    for (n = e->wq.waiters.next; n != &e->wq.waiters; n = next) {
        struct k_thread *w = K_CONTAINER_OF(n, struct k_thread, node);
        uint32_t hit = k_event_match(e->bits, w->wait_value, w->wait_flags);
        next = n->next;
        if (hit != 0u) {
            w->wait_value = hit;
            if ((w->wait_flags & K_EVENT_CLEAR) != 0u)
                consumed |= hit;
            k_wake(w, K_OK);
        }
    }
    e->bits &= ~consumed;
    k_resched();
    k_arch_irq_restore(irq);
    return K_OK;
}

int k_event_clear(struct k_event *e, uint32_t bits)
{
    uint32_t irq;
    if (e == NULL || e->magic != K_MAGIC_EVENT)
        return K_EINVAL;
    irq = k_arch_irq_save();
    e->bits &= ~bits;
    k_arch_irq_restore(irq);
    return K_OK;
}

int k_event_wait(struct k_event *e, uint32_t mask, uint32_t flags, k_ticks_t timeout,
                 uint32_t *matched)
{
    uint32_t irq, hit;
    int32_t r;
    struct k_thread *self = k_kernel.current;
    if (e == NULL || e->magic != K_MAGIC_EVENT || mask == 0u ||
        (flags & ~(K_EVENT_ALL | K_EVENT_CLEAR)) != 0u)
        return K_EINVAL;
    irq = k_arch_irq_save();
    hit = k_event_match(e->bits, mask, flags);
    if (hit != 0u) {
        if ((flags & K_EVENT_CLEAR) != 0u)
            e->bits &= ~hit;
        r = K_OK;
    } else if (timeout == K_NO_WAIT) {
        r = K_EAGAIN;
    } else if (k_in_isr()) {
        r = K_EISR;
    } else {
        self->wait_value = mask;
        self->wait_flags = flags;
        r = k_block(&e->wq, timeout);
        hit = self->wait_value;
    }
    if (r == K_OK && matched != NULL)
        *matched = hit;
    k_arch_irq_restore(irq);
    return r;
}
