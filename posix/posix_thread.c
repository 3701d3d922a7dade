/*
 * Threads: pthread_create and the calls on threads, thread attributes,
 * pthread_once and the sched_* calls; also newlib's malloc lock, so that the
 * heap (which pthread_create takes default stacks from) is safe from any
 * thread of a program that uses POSIX threads.
 *
 * A thread made here lives in a fixed pool of POSIX_THREADS_MAX control
 * blocks; its stack is the one its attributes name, or PTHREAD_STACK_DEFAULT
 * bytes from the heap, freed when the thread is joined or, detached, once it
 * has ended (at the next pthread_create or pthread_join).
 */
#include <pthread.h>
#include <sched.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/reent.h>
#include "posix_internal.h"

#ifndef POSIX_THREADS_MAX
#define POSIX_THREADS_MAX 8
#endif

struct posix_thread {
    struct k_thread kt;          /* first: a pthread_t points at it */
    void *(*start)(void *);
    void *arg;
    void *heap_stack;            /* freed when reaped; NULL for a stack of the caller's */
    uint8_t in_use;
    uint8_t detached;
    uint8_t timeslice;           /* 0 for SCHED_FIFO */
};

static struct posix_thread posix_threads[POSIX_THREADS_MAX];

/* The pool entry of t, or NULL for a thread made another way (main). */
static struct posix_thread *posix_thread_of(pthread_t t)
{
    uintptr_t a = (uintptr_t)t, lo = (uintptr_t)&posix_threads[0];
    if (a < lo || a >= (uintptr_t)&posix_threads[POSIX_THREADS_MAX] ||
        (a - lo) % sizeof(struct posix_thread) != 0u)
        return NULL;
    return (struct posix_thread *)(void *)t;
}

/* Gives back p's entry and stack (the thread has ended). */
static void posix_thread_release(struct posix_thread *p)
{
    void *stack;
    uint32_t irq = k_arch_irq_save();
    stack = p->heap_stack;
    p->heap_stack = NULL;
    p->in_use = 0;
    k_arch_irq_restore(irq);
    free(stack);
}

static void posix_reap_detached(void)
{
    unsigned i;
    for (i = 0; i < POSIX_THREADS_MAX; i++) {
        struct posix_thread *p = &posix_threads[i];
        if (p->in_use && p->detached && p->kt.state == K_THREAD_DEAD)
            posix_thread_release(p);
    }
}

static void *posix_thread_start(void *arg)
{
    struct posix_thread *p = arg;
    /* Before its first slice ends: the policy holds from the start. */
    (void)k_thread_set_timeslice(&p->kt, p->timeslice);
    return p->start(p->arg);
}

static int posix_policy_valid(int policy)
{
    return policy == SCHED_FIFO || policy == SCHED_RR;
}

static int posix_prio_valid(int prio)
{
    return prio >= (int)K_PRIO_APP_MIN && prio <= (int)K_PRIO_APP_MAX;
}

int pthread_create(pthread_t *thread, const pthread_attr_t *attr,
                   void *(*start_routine)(void *), void *arg)
{
    pthread_attr_t def;
    struct posix_thread *p = NULL;
    void *stack;
    size_t bytes;
    int prio, r;
    unsigned i;
    uint32_t irq;
    if (thread == NULL || start_routine == NULL)
        return EINVAL;
    if (attr == NULL) {
        (void)pthread_attr_init(&def);
        attr = &def;
    } else if (!attr->is_initialized) {
        return EINVAL;
    }
    if (k_in_isr())
        return EPERM;
    if (attr->inheritsched == PTHREAD_INHERIT_SCHED) {
        prio = (int)k_thread_self()->base_prio;
        if (!posix_prio_valid(prio))   /* before k_start: the boot context */
            prio = (int)K_PRIO_APP_MIN;
    } else {
        prio = attr->schedparam.sched_priority;
    }
    posix_reap_detached();
    irq = k_arch_irq_save();
    for (i = 0; i < POSIX_THREADS_MAX && p == NULL; i++)
        if (!posix_threads[i].in_use) {
            p = &posix_threads[i];
            p->in_use = 1;
        }
    k_arch_irq_restore(irq);
    if (p == NULL)
        return EAGAIN;
    bytes = attr->stacksize;
    if (attr->stackaddr != NULL) {
        stack = attr->stackaddr;
        p->heap_stack = NULL;
    } else {
        stack = malloc(bytes);
        p->heap_stack = stack;
        if (stack == NULL) {
            posix_thread_release(p);
            return EAGAIN;
        }
    }
    p->start = start_routine;
    p->arg = arg;
    p->detached = (uint8_t)(attr->detachstate == PTHREAD_CREATE_DETACHED);
    p->timeslice = (uint8_t)(attr->inheritsched == PTHREAD_INHERIT_SCHED
                                 ? k_thread_self()->timeslice
                                 : attr->schedpolicy == SCHED_FIFO ? 0u : K_TIMESLICE_TICKS);
    /* Stored first: a more urgent thread runs before k_thread_create returns. */
    *thread = &p->kt;
    r = k_thread_create(&p->kt, "pthread", posix_thread_start, p, stack, bytes, (unsigned)prio);
    if (r != K_OK) {
        posix_thread_release(p);
        return posix_errno(r);
    }
    /* The thread sets its policy when it starts; set here too, so that it
     * holds for a thread that has not run yet (it may have ended already). */
    (void)k_thread_set_timeslice(&p->kt, p->timeslice);
    return 0;
}

int pthread_join(pthread_t thread, void **value_ptr)
{
    struct posix_thread *p = posix_thread_of(thread);
    int r;
    if (thread == NULL || (p != NULL && !p->in_use))
        return ESRCH;
    if (p != NULL && p->detached)
        return EINVAL;
    if (thread == k_thread_self())
        return EDEADLK;
    r = k_thread_join(thread, value_ptr, K_FOREVER);
    if (r != K_OK && r != K_ESTACK)
        return posix_errno(r);
    if (p != NULL)
        posix_thread_release(p);
    /* A thread stopped for overflowing its stack has ended, without a value. */
    return r == K_ESTACK ? EFAULT : 0;
}

int pthread_detach(pthread_t thread)
{
    struct posix_thread *p = posix_thread_of(thread);
    if (thread == NULL || (p != NULL && !p->in_use) ||
        (p == NULL && thread->state == K_THREAD_UNUSED))
        return ESRCH;
    if (p == NULL)
        return 0;   /* a thread with a stack of its own: nothing to give back */
    if (p->detached)
        return EINVAL;
    p->detached = 1;
    return 0;
}

void pthread_exit(void *value_ptr)
{
    k_thread_exit(value_ptr);
    /* Only where no thread can end (an interrupt handler, before start-up). */
    for (;;)
        (void)k_sleep_ticks(0x7FFFFFFFu);
}

pthread_t pthread_self(void)
{
    return k_thread_self();
}

int pthread_equal(pthread_t t1, pthread_t t2)
{
    return t1 == t2;
}

int pthread_once(pthread_once_t *once_control, void (*init_routine)(void))
{
    uint32_t irq;
    int mine = 0;
    if (once_control == NULL || init_routine == NULL)
        return EINVAL;
    irq = k_arch_irq_save();
    if (once_control->__state == 0) {
        once_control->__state = 1;
        mine = 1;
    }
    k_arch_irq_restore(irq);
    if (mine) {
        init_routine();
        once_control->__state = 2;
    } else {
        while (once_control->__state != 2)   /* another thread runs it */
            (void)k_sleep_ticks(1);
    }
    return 0;
}

int pthread_getschedparam(pthread_t thread, int *policy, struct sched_param *param)
{
    if (thread == NULL || thread->state == K_THREAD_UNUSED)
        return ESRCH;
    if (policy == NULL || param == NULL)
        return EINVAL;
    *policy = thread->timeslice == 0u ? SCHED_FIFO : SCHED_RR;
    param->sched_priority = thread->base_prio;
    return 0;
}

int pthread_setschedparam(pthread_t thread, int policy, const struct sched_param *param)
{
    int r;
    if (thread == NULL)
        return ESRCH;
    if (param == NULL || !posix_policy_valid(policy) || !posix_prio_valid(param->sched_priority))
        return EINVAL;
    r = k_thread_set_timeslice(thread, policy == SCHED_FIFO ? 0u : K_TIMESLICE_TICKS);
    if (r == K_OK)
        r = k_thread_setprio(thread, (unsigned)param->sched_priority);
    return posix_errno(r);
}

int pthread_setschedprio(pthread_t thread, int prio)
{
    if (thread == NULL)
        return ESRCH;
    if (!posix_prio_valid(prio))
        return EINVAL;
    return posix_errno(k_thread_setprio(thread, (unsigned)prio));
}

/* ---- attributes ---- */

int pthread_attr_init(pthread_attr_t *attr)
{
    if (attr == NULL)
        return EINVAL;
    attr->is_initialized = 1;
    attr->stackaddr = NULL;
    attr->stacksize = PTHREAD_STACK_DEFAULT;
    attr->contentionscope = PTHREAD_SCOPE_SYSTEM;
    attr->inheritsched = PTHREAD_INHERIT_SCHED;
    attr->schedpolicy = SCHED_FIFO;
    attr->schedparam.sched_priority = (int)K_PRIO_APP_MIN;
    attr->detachstate = PTHREAD_CREATE_JOINABLE;
    return 0;
}

int pthread_attr_destroy(pthread_attr_t *attr)
{
    if (attr == NULL || !attr->is_initialized)
        return EINVAL;
    attr->is_initialized = 0;
    return 0;
}

#define ATTR_OK(a) ((a) != NULL && (a)->is_initialized)

int pthread_attr_setstacksize(pthread_attr_t *attr, size_t stacksize)
{
    if (!ATTR_OK(attr) || stacksize < PTHREAD_STACK_MIN)
        return EINVAL;
    attr->stacksize = stacksize;
    return 0;
}

int pthread_attr_getstacksize(const pthread_attr_t *attr, size_t *stacksize)
{
    if (!ATTR_OK(attr) || stacksize == NULL)
        return EINVAL;
    *stacksize = attr->stacksize;
    return 0;
}

int pthread_attr_setstack(pthread_attr_t *attr, void *stackaddr, size_t stacksize)
{
    /* The kernel keeps 32-bit words on a stack: it must be 4-byte aligned. */
    if (!ATTR_OK(attr) || stackaddr == NULL || stacksize < PTHREAD_STACK_MIN ||
        ((uintptr_t)stackaddr & 3u) != 0u)
        return EINVAL;
    attr->stackaddr = stackaddr;
    attr->stacksize = stacksize;
    return 0;
}

int pthread_attr_getstack(const pthread_attr_t *attr, void **stackaddr, size_t *stacksize)
{
    if (!ATTR_OK(attr) || stackaddr == NULL || stacksize == NULL)
        return EINVAL;
    *stackaddr = attr->stackaddr;
    *stacksize = attr->stacksize;
    return 0;
}

int pthread_attr_setdetachstate(pthread_attr_t *attr, int detachstate)
{
    if (!ATTR_OK(attr) ||
        (detachstate != PTHREAD_CREATE_JOINABLE && detachstate != PTHREAD_CREATE_DETACHED))
        return EINVAL;
    attr->detachstate = detachstate;
    return 0;
}

int pthread_attr_getdetachstate(const pthread_attr_t *attr, int *detachstate)
{
    if (!ATTR_OK(attr) || detachstate == NULL)
        return EINVAL;
    *detachstate = attr->detachstate;
    return 0;
}

int pthread_attr_setinheritsched(pthread_attr_t *attr, int inheritsched)
{
    if (!ATTR_OK(attr) ||
        (inheritsched != PTHREAD_INHERIT_SCHED && inheritsched != PTHREAD_EXPLICIT_SCHED))
        return EINVAL;
    attr->inheritsched = inheritsched;
    return 0;
}

int pthread_attr_getinheritsched(const pthread_attr_t *attr, int *inheritsched)
{
    if (!ATTR_OK(attr) || inheritsched == NULL)
        return EINVAL;
    *inheritsched = attr->inheritsched;
    return 0;
}

int pthread_attr_setschedpolicy(pthread_attr_t *attr, int policy)
{
    if (!ATTR_OK(attr))
        return EINVAL;
    if (!posix_policy_valid(policy))
        return policy == SCHED_OTHER ? ENOTSUP : EINVAL;
    attr->schedpolicy = policy;
    return 0;
}

int pthread_attr_getschedpolicy(const pthread_attr_t *attr, int *policy)
{
    if (!ATTR_OK(attr) || policy == NULL)
        return EINVAL;
    *policy = attr->schedpolicy;
    return 0;
}

int pthread_attr_setschedparam(pthread_attr_t *attr, const struct sched_param *param)
{
    if (!ATTR_OK(attr) || param == NULL)
        return EINVAL;
    if (!posix_prio_valid(param->sched_priority))
        return ENOTSUP;   /* as POSIX names a priority the system does not offer */
    attr->schedparam = *param;
    return 0;
}

int pthread_attr_getschedparam(const pthread_attr_t *attr, struct sched_param *param)
{
    if (!ATTR_OK(attr) || param == NULL)
        return EINVAL;
    *param = attr->schedparam;
    return 0;
}

int pthread_attr_setscope(pthread_attr_t *attr, int scope)
{
    if (!ATTR_OK(attr))
        return EINVAL;
    if (scope != PTHREAD_SCOPE_SYSTEM)
        return scope == PTHREAD_SCOPE_PROCESS ? ENOTSUP : EINVAL;
    attr->contentionscope = scope;
    return 0;
}

int pthread_attr_getscope(const pthread_attr_t *attr, int *scope)
{
    if (!ATTR_OK(attr) || scope == NULL)
        return EINVAL;
    *scope = attr->contentionscope;
    return 0;
}

/* ---- scheduling ---- */

int sched_yield(void)
{
    (void)k_sched_yield();
    return 0;
}

int sched_get_priority_min(int policy)
{
    if (!posix_policy_valid(policy)) {
        errno = EINVAL;
        return -1;
    }
    return (int)K_PRIO_APP_MIN;
}

int sched_get_priority_max(int policy)
{
    if (!posix_policy_valid(policy)) {
        errno = EINVAL;
        return -1;
    }
    return (int)K_PRIO_APP_MAX;
}

/* ---- newlib's malloc lock ---- */

/* A recursive lock on a kernel mutex (newlib may take it again while it holds
 * it). Not taken in an interrupt handler, where the heap must not be used. */
static struct k_mutex posix_heap_mutex;
static uint32_t posix_heap_depth;
static uint8_t posix_heap_ready;

void __malloc_lock(struct _reent *reent)
{
    uint32_t irq;
    (void)reent;
    if (k_in_isr())
        return;
    irq = k_arch_irq_save();
    if (!posix_heap_ready) {
        (void)k_mutex_init(&posix_heap_mutex);
        posix_heap_ready = 1;
    }
    k_arch_irq_restore(irq);
    if (posix_heap_mutex.owner == k_thread_self())
        posix_heap_depth++;
    else
        (void)k_mutex_lock(&posix_heap_mutex);
}

void __malloc_unlock(struct _reent *reent)
{
    (void)reent;
    if (k_in_isr() || !posix_heap_ready)
        return;
    if (posix_heap_depth > 0u)
        posix_heap_depth--;
    else
        (void)k_mutex_unlock(&posix_heap_mutex);
}
