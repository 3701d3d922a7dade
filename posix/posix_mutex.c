/*
 * Mutexes and condition variables on the kernel's: every mutex inherits
 * priority (the kernel's mutexes all do), detects a relock and refuses an
 * unlock by a thread that does not own it; recursive mutexes count their
 * relocks here. The lock and unlock paths call the kernel's lock and unlock
 * directly, so that they cost a few checks more than the k_ calls.
 */
#include <pthread.h>
#include "posix_internal.h"

/* Makes the kernel objects of a statically initialised mutex or condition
 * variable at first use. */
static int posix_mutex_ready(pthread_mutex_t *m)
{
    uint32_t irq;
    int r = 0;
    if (m == NULL)
        return EINVAL;
    irq = k_arch_irq_save();
    if (m->__kind == POSIX_MUTEX_STATIC) {
        (void)k_mutex_init(&m->__m);
        m->__kind = POSIX_MUTEX_READY;
        m->__depth = 0;
    } else if (m->__kind != POSIX_MUTEX_READY && m->__kind != POSIX_MUTEX_RECURSIVE) {
        r = EINVAL;   /* never initialised, or destroyed */
    }
    k_arch_irq_restore(irq);
    return r;
}

static int posix_mutex_is_recursive(const pthread_mutex_t *m)
{
    return m->__kind == POSIX_MUTEX_RECURSIVE;
}

int pthread_mutex_init(pthread_mutex_t *mutex, const pthread_mutexattr_t *attr)
{
    int type = PTHREAD_MUTEX_DEFAULT;
    if (mutex == NULL || (attr != NULL && !attr->is_initialized))
        return EINVAL;
    if (attr != NULL)
        type = attr->type;
    (void)k_mutex_init(&mutex->__m);
    mutex->__kind = type == PTHREAD_MUTEX_RECURSIVE ? POSIX_MUTEX_RECURSIVE : POSIX_MUTEX_READY;
    mutex->__depth = 0;
    return 0;
}

int pthread_mutex_destroy(pthread_mutex_t *mutex)
{
    int r = posix_mutex_ready(mutex);
    uint32_t irq;
    if (r != 0)
        return r;
    irq = k_arch_irq_save();
    if (mutex->__m.owner != NULL)
        r = EBUSY;
    else
        mutex->__kind = 0;
    k_arch_irq_restore(irq);
    return r;
}

/* Lock with a timeout in ticks (K_FOREVER, K_NO_WAIT or a count). */
static int posix_mutex_lock(pthread_mutex_t *m, k_ticks_t timeout)
{
    int r = posix_mutex_ready(m);
    if (r != 0)
        return r;
    if (posix_mutex_is_recursive(m) && m->__m.owner == k_thread_self()) {
        if (m->__depth == 0xFFFFu)
            return EAGAIN;   /* the most relocks a recursive mutex counts */
        m->__depth++;
        return 0;
    }
    r = k_mutex_lock_ticks(&m->__m, timeout);
    return r == K_OK ? 0 : posix_errno(r);
}

int pthread_mutex_lock(pthread_mutex_t *mutex)
{
    /* The common case, a ready non-recursive mutex, straight to the kernel. */
    if (mutex != NULL && mutex->__kind == POSIX_MUTEX_READY) {
        int r = k_mutex_lock_ticks(&mutex->__m, K_FOREVER);
        return r == K_OK ? 0 : posix_errno(r);
    }
    return posix_mutex_lock(mutex, K_FOREVER);
}

int pthread_mutex_trylock(pthread_mutex_t *mutex)
{
    return posix_mutex_lock(mutex, K_NO_WAIT);
}

int pthread_mutex_timedlock(pthread_mutex_t *mutex, const struct timespec *abstime)
{
    struct k_timespec t;
    k_ticks_t ticks;
    int r;
    /* POSIX: the time is checked only when the mutex cannot be taken at once. */
    r = posix_mutex_lock(mutex, K_NO_WAIT);
    if (r != EBUSY)
        return r;
    if (posix_timespec(abstime, &t) != K_OK || k_abs_to_timeout(&t, &ticks) != K_OK)
        return EINVAL;
    r = posix_mutex_lock(mutex, ticks);
    return r == EBUSY ? ETIMEDOUT : r;
}

/* Not inlined: the registers it needs would be saved on the common path too. */
static __attribute__((noinline)) int posix_mutex_unlock(pthread_mutex_t *m)
{
    int r;
    if (m == NULL)
        return EINVAL;
    if (m->__kind == POSIX_MUTEX_STATIC)
        return EPERM;   /* never locked, so not the caller's */
    if (m->__kind != POSIX_MUTEX_RECURSIVE)
        return EINVAL;  /* never initialised, or destroyed */
    if (m->__depth > 0u && m->__m.owner == k_thread_self()) {
        m->__depth--;
        return 0;
    }
    r = k_mutex_unlock(&m->__m);
    return r == K_OK ? 0 : posix_errno(r);
}

int pthread_mutex_unlock(pthread_mutex_t *mutex)
{
    if (mutex != NULL && mutex->__kind == POSIX_MUTEX_READY) {
        int r = k_mutex_unlock(&mutex->__m);
        return r == K_OK ? 0 : posix_errno(r);
    }
    return posix_mutex_unlock(mutex);
}

/* ---- mutex attributes ---- */

int pthread_mutexattr_init(pthread_mutexattr_t *attr)
{
    if (attr == NULL)
        return EINVAL;
    attr->is_initialized = 1;
    attr->type = PTHREAD_MUTEX_DEFAULT;
    attr->protocol = PTHREAD_PRIO_INHERIT;
    attr->pshared = PTHREAD_PROCESS_PRIVATE;
    return 0;
}

int pthread_mutexattr_destroy(pthread_mutexattr_t *attr)
{
    if (attr == NULL || !attr->is_initialized)
        return EINVAL;
    attr->is_initialized = 0;
    return 0;
}

int pthread_mutexattr_settype(pthread_mutexattr_t *attr, int type)
{
    if (attr == NULL || !attr->is_initialized || type < PTHREAD_MUTEX_NORMAL ||
        type > PTHREAD_MUTEX_DEFAULT)
        return EINVAL;
    attr->type = type;
    return 0;
}

int pthread_mutexattr_gettype(const pthread_mutexattr_t *attr, int *type)
{
    if (attr == NULL || !attr->is_initialized || type == NULL)
        return EINVAL;
    *type = attr->type;
    return 0;
}

/* Every kernel mutex inherits priority: PTHREAD_PRIO_NONE is accepted and
 * gives an inheriting mutex too (posix/README.md); PROTECT is not offered. */
int pthread_mutexattr_setprotocol(pthread_mutexattr_t *attr, int protocol)
{
    if (attr == NULL || !attr->is_initialized)
        return EINVAL;
    if (protocol == PTHREAD_PRIO_PROTECT)
        return ENOTSUP;
    if (protocol != PTHREAD_PRIO_INHERIT && protocol != PTHREAD_PRIO_NONE)
        return EINVAL;
    attr->protocol = protocol;
    return 0;
}

int pthread_mutexattr_getprotocol(const pthread_mutexattr_t *attr, int *protocol)
{
    if (attr == NULL || !attr->is_initialized || protocol == NULL)
        return EINVAL;
    *protocol = attr->protocol;
    return 0;
}

int pthread_mutexattr_setpshared(pthread_mutexattr_t *attr, int pshared)
{
    if (attr == NULL || !attr->is_initialized)
        return EINVAL;
    if (pshared == PTHREAD_PROCESS_SHARED)
        return ENOTSUP;   /* one program, one address space */
    if (pshared != PTHREAD_PROCESS_PRIVATE)
        return EINVAL;
    attr->pshared = pshared;
    return 0;
}

int pthread_mutexattr_getpshared(const pthread_mutexattr_t *attr, int *pshared)
{
    if (attr == NULL || !attr->is_initialized || pshared == NULL)
        return EINVAL;
    *pshared = attr->pshared;
    return 0;
}

/* ---- condition variables ---- */

static int posix_cond_ready(pthread_cond_t *c)
{
    uint32_t irq;
    int r = 0;
    if (c == NULL)
        return EINVAL;
    irq = k_arch_irq_save();
    if (c->__state == POSIX_COND_STATIC) {
        (void)k_cond_init(&c->__c);
        c->__state = POSIX_COND_READY;
    } else if (c->__state != POSIX_COND_READY) {
        r = EINVAL;
    }
    k_arch_irq_restore(irq);
    return r;
}

int pthread_cond_init(pthread_cond_t *cond, const pthread_condattr_t *attr)
{
    if (cond == NULL || (attr != NULL && !attr->is_initialized))
        return EINVAL;
    (void)k_cond_init(&cond->__c);
    cond->__state = POSIX_COND_READY;
    return 0;
}

int pthread_cond_destroy(pthread_cond_t *cond)
{
    int r = posix_cond_ready(cond);
    uint32_t irq;
    if (r != 0)
        return r;
    irq = k_arch_irq_save();
    if (!k_list_empty(&cond->__c.wq.waiters))
        r = EBUSY;
    else
        cond->__state = 0;
    k_arch_irq_restore(irq);
    return r;
}

static int posix_cond_wait(pthread_cond_t *cond, pthread_mutex_t *mutex, k_ticks_t timeout)
{
    int r = posix_cond_ready(cond);
    if (r == 0)
        r = posix_mutex_ready(mutex);
    if (r != 0)
        return r;
    /* A recursive mutex locked more than once cannot be given up in one step. */
    if (posix_mutex_is_recursive(mutex) && mutex->__depth != 0u)
        return EPERM;
    r = k_cond_wait_ticks(&cond->__c, &mutex->__m, timeout);
    return r == K_OK ? 0 : posix_errno(r);
}

int pthread_cond_wait(pthread_cond_t *cond, pthread_mutex_t *mutex)
{
    return posix_cond_wait(cond, mutex, K_FOREVER);
}

int pthread_cond_timedwait(pthread_cond_t *cond, pthread_mutex_t *mutex,
                           const struct timespec *abstime)
{
    struct k_timespec t;
    k_ticks_t ticks;
    if (posix_timespec(abstime, &t) != K_OK || k_abs_to_timeout(&t, &ticks) != K_OK)
        return EINVAL;
    return posix_cond_wait(cond, mutex, ticks);
}

int pthread_cond_signal(pthread_cond_t *cond)
{
    int r = posix_cond_ready(cond);
    return r != 0 ? r : posix_errno(k_cond_signal(&cond->__c));
}

int pthread_cond_broadcast(pthread_cond_t *cond)
{
    int r = posix_cond_ready(cond);
    return r != 0 ? r : posix_errno(k_cond_broadcast(&cond->__c));
}

int pthread_condattr_init(pthread_condattr_t *attr)
{
    if (attr == NULL)
        return EINVAL;
    attr->is_initialized = 1;
    attr->clock = CLOCK_REALTIME;
    attr->pshared = PTHREAD_PROCESS_PRIVATE;
    return 0;
}

int pthread_condattr_destroy(pthread_condattr_t *attr)
{
    if (attr == NULL || !attr->is_initialized)
        return EINVAL;
    attr->is_initialized = 0;
    return 0;
}

int pthread_condattr_setclock(pthread_condattr_t *attr, clockid_t clock_id)
{
    if (attr == NULL || !attr->is_initialized || !posix_clock_valid(clock_id))
        return EINVAL;
    attr->clock = clock_id;
    return 0;
}

int pthread_condattr_getclock(const pthread_condattr_t *attr, clockid_t *clock_id)
{
    if (attr == NULL || !attr->is_initialized || clock_id == NULL)
        return EINVAL;
    *clock_id = attr->clock;
    return 0;
}
