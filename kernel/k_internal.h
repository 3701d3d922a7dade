/* Kernel-internal interface between the scheduler and the services. All
 * functions here expect interrupts disabled (k_arch_irq_save). */
#ifndef K_INTERNAL_H
#define K_INTERNAL_H

#include "kernel.h"

#define K_MAGIC_SEM   0x53454D31u
#define K_MAGIC_MUTEX 0x4D545831u
#define K_MAGIC_MQ    0x4D515531u
#define K_MAGIC_EVENT 0x45564E31u
#define K_MAGIC_COND  0x434E4431u

struct k_kernel {
    /* First: the CPU32 interrupt entry (switch.S) reads it at k_kernel + 0. */
    volatile uint32_t isr_nesting;
    struct k_prioq ready;
    struct k_tlist timers;
    struct k_thread *current;
    struct k_thread idle;
    struct k_thread boot;          /* the context k_start was called from */
    volatile k_ticks_t ticks;
    uint32_t seconds;              /* whole seconds of uptime */
    uint32_t subticks;             /* ticks into the current second */
    struct k_thread *all;          /* every created thread */
    struct k_thread *overflowed;   /* first stack overflow found */
    int started;
};
extern struct k_kernel k_kernel;

/* For a port whose hardware catches a thread at its stack guard (the
 * ARMv7-M MPU): called in thread mode, on a fresh part of the running
 * thread's stack, it stops that thread as if its guard words had broken
 * (reported, K_ESTACK for its joiners) and switches away; never returns.
 * The idle thread, or a fault before k_start, halts the system instead. */
void k_stack_overflow_stop_current(void) __attribute__((noreturn));

void k_waitq_init(struct k_waitq *wq);
struct k_thread *k_waitq_first(const struct k_waitq *wq);
/* Blocks the current thread on wq (may be NULL: plain sleep) until woken or
 * the timeout (relative ticks, K_FOREVER for none) passes; returns the
 * thread's wait_result (K_ETIMEDOUT on timeout). */
int32_t k_block(struct k_waitq *wq, k_ticks_t timeout);
/* k_block in two steps, for callers that must act once the thread is queued
 * (priority inheritance) before it switches away. */
void k_block_prepare(struct k_waitq *wq, k_ticks_t timeout);
int32_t k_block_commit(void);
/* k_block with an absolute deadline tick. */
int32_t k_block_until(struct k_waitq *wq, k_ticks_t deadline);
/* The tail of a blocking call that found nothing to take: K_EAGAIN when it
 * may not wait (K_NO_WAIT), K_EISR in an interrupt handler, else k_block. */
int32_t k_block_or_refuse(struct k_waitq *wq, k_ticks_t timeout);
/* The POSIX timed form of a call with a timeout in ticks: `r` is what the
 * call returned with the timeout k_abs_to_timeout gave; its "would block"
 * code (the deadline had passed) becomes K_ETIMEDOUT. */
static inline int k_timed_result(int r, int would_block)
{
    return r == would_block ? K_ETIMEDOUT : r;
}
/* Makes a blocked thread ready with the given result. */
void k_wake(struct k_thread *t, int32_t result);
/* Switches to the most urgent ready thread if it is not the current one
 * (deferred to interrupt exit inside a handler). */
void k_resched(void);
/* Recomputes t's effective priority: base or the most urgent waiter of a
 * mutex it holds; follows the chain of mutex owners. */
void k_prio_update(struct k_thread *t);
/* Releases the mutexes a dying thread holds (k_sync.c). */
void k_mutex_release_all(struct k_thread *t);
/* The level k_irq_register stored for vector (0: none): for a port whose
 * interrupt controller takes each line's priority (ARMv7-M's NVIC). */
unsigned k_irq_level(unsigned vector);
/* Called when a thread blocked on a mutex stops waiting (timeout). */
void k_mutex_waiter_gone(struct k_mutex *m);

#endif /* K_INTERNAL_H */
