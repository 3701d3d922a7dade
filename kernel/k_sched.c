/*
 * Threads, the scheduler, the tick and time.
 *
 * The running thread stays at the head of its ready level; the most urgent
 * ready thread is the head of the highest non-empty level. A thread that is
 * pre-empted keeps its place; one that yields or uses up its slice goes to
 * the tail of its level (round robin). Blocking takes a thread out of the
 * ready queue into a wait queue (ordered by priority) and/or the timer list.
 */
#include "k_internal.h"

struct k_kernel k_kernel;
struct k_stats k_stats;
void (*volatile k_tick_hook)(k_ticks_t now);
/* The registered fine counter (k_timestamp_register; none after k_init),
 * what starts it, and k_timestamp_start's result once it has run
 * (K_TIMESTAMP_UNSTARTED before). k_timestamp reads k_timestamp_read only
 * once it has started. */
#define K_TIMESTAMP_UNSTARTED 1
static k_timestamp_fn k_timestamp_registered;
static k_timestamp_start_fn k_timestamp_starter;
static uint32_t k_timestamp_rate;
static k_timestamp_fn k_timestamp_read;
static int k_timestamp_started = K_TIMESTAMP_UNSTARTED;

K_STACK_DEFINE(k_idle_stack, K_IDLE_STACK_BYTES);

#define K_NS_PER_TICK_X2 (2000000000u / K_TICK_HZ)
#if (2000000000u % K_TICK_HZ) != 0
#error "K_TICK_HZ must divide 2 000 000 000"
#endif

/* ---- wait queues ---- */

void k_waitq_init(struct k_waitq *wq)
{
    k_list_init(&wq->waiters);
}

struct k_thread *k_waitq_first(const struct k_waitq *wq)
{
    struct k_list_node *n = k_list_first(&wq->waiters);
    return n == NULL ? NULL : K_CONTAINER_OF(n, struct k_thread, node);
}

/* Inserts after every waiter of the same or higher priority. */
static void k_waitq_insert(struct k_waitq *wq, struct k_thread *t)
{
    struct k_list_node *pos = wq->waiters.next;
    while (pos != &wq->waiters && K_CONTAINER_OF(pos, struct k_thread, node)->prio >= t->prio)
        pos = pos->next;
    k_list_insert_before(pos, &t->node);
}

/* ---- ready queue ---- */

static void k_ready_append(struct k_thread *t)
{
    k_prioq_append(&k_kernel.ready, &t->node, t->prio);
}

static void k_ready_remove(struct k_thread *t)
{
    k_prioq_remove(&k_kernel.ready, &t->node, t->prio);
}

static struct k_thread *k_ready_best(void)
{
    return K_CONTAINER_OF(k_prioq_highest(&k_kernel.ready), struct k_thread, node);
}

/* ---- stack guard ---- */

#if K_STACK_GUARD_WORDS != 4u
#error "k_stack_intact checks exactly four guard words"
#endif
/* Unrolled: it runs on every switch. */
static int k_stack_intact(const struct k_thread *t)
{
    const uint32_t *g = t->stack_base;
    return g == NULL || (g[0] == K_STACK_GUARD && g[1] == K_STACK_GUARD &&
                         g[2] == K_STACK_GUARD && g[3] == K_STACK_GUARD);
}

/* Reports are written piece by piece, without the formatter: they run in
 * k_resched, on every stack and in the interrupt exit, where a formatting
 * frame would cost every thread its depth. */
static void k_write_str(const char *s)
{
    k_console_write_sync(s, k_strlen(s));
}

static uintptr_t k_canary_of(const struct k_thread *t)
{
    return (uintptr_t)K_THREAD_CANARY ^ (uintptr_t)t;
}

/* A stack placed right after a control block (struct k_bsched does so) must
 * stay 4-byte aligned, which k_thread_create requires. */
typedef char k_thread_size_is_a_multiple_of_4[sizeof(struct k_thread) % 4u == 0u ? 1 : -1];

static int k_tcb_intact(const struct k_thread *t)
{
    return t->canary == k_canary_of(t);
}

/* A control block whose canary is broken cannot be trusted (its links,
 * priority and name may be anything), so nothing can stop just that thread
 * safely: the system stops, saying where the block is. */
static void k_fatal_tcb(const struct k_thread *t)
{
    static const char hex[] = "0123456789abcdef";
    char addr[8];
    uint32_t a = (uint32_t)(uintptr_t)t;
    unsigned i;
    for (i = 0; i < 8u; i++)
        addr[i] = hex[(a >> (28u - 4u * i)) & 0xFu];
    k_write_str("kernel: control block of the thread at 0x");
    k_console_write_sync(addr, sizeof addr);
    k_write_str(" overwritten (a stack overflowed into it): halted\n");
    k_arch_halt();
}

static void k_report(const char *what, const struct k_thread *t)
{
    k_write_str("kernel: ");
    k_write_str(what);
    k_write_str(" in thread '");
    k_write_str(t->name != NULL ? t->name : "?");
    k_write_str("'\n");
}

static void k_wake_joiners(struct k_thread *t)
{
    struct k_thread *j;
    while ((j = k_waitq_first(&t->joiners)) != NULL)
        k_wake(j, K_OK);
}

/* A thread whose guard is broken is stopped for good: its stack has run into
 * whatever lies below it, so resuming it could only spread the damage. */
static void k_stop_overflowed(struct k_thread *t)
{
    k_stats.stack_overflows++;
    if (k_kernel.overflowed == NULL)
        k_kernel.overflowed = t;
    k_report("stack overflow", t);
    if (t->state == K_THREAD_BLOCKED)
        k_wake(t, K_ESTACK); /* out of its wait queue and timer list */
    if (t->state == K_THREAD_READY)
        k_ready_remove(t);
    t->state = K_THREAD_DEAD;
    t->exit_value = NULL;
    t->wait_result = K_ESTACK;
    k_mutex_release_all(t);
    k_wake_joiners(t);
}

void k_stack_overflow_stop_current(void)
{
    struct k_thread *t = k_kernel.current;
    (void)k_arch_irq_save();
    if (!k_kernel.started || t == &k_kernel.idle) {
        k_report("stack overflow (the system cannot go on without it: halted)", t);
        k_arch_halt();
    }
    k_stop_overflowed(t);
    k_resched();
    for (;;) /* not reached: nothing switches back to a dead thread */
        k_arch_idle();
}

/* ---- switching ---- */

void k_resched(void)
{
    struct k_thread *prev = k_kernel.current;
    struct k_thread *next;

    if (!k_kernel.started || k_kernel.isr_nesting != 0)
        return; /* k_isr_exit does it */
    if (!k_tcb_intact(prev))
        k_fatal_tcb(prev);
    if (prev->state != K_THREAD_DEAD && !k_stack_intact(prev))
        k_stop_overflowed(prev);
    next = k_ready_best();
    if (next == prev)
        return;
    if (!k_tcb_intact(next)) /* overwritten by another thread's stack */
        k_fatal_tcb(next);
    next->slice_left = K_TIMESLICE_TICKS;
    next->switches_in++;
    k_stats.context_switches++;
    k_kernel.current = next;
    k_arch_switch(prev, next);
}

int k_in_isr(void)
{
    return k_kernel.isr_nesting != 0;
}

int k_can_block(void)
{
    return k_kernel.started && k_kernel.isr_nesting == 0;
}

void k_isr_enter(void)
{
    k_kernel.isr_nesting++;
}

void k_isr_exit(void)
{
    uint32_t s = k_arch_irq_save();
    if (k_kernel.isr_nesting > 0)
        k_kernel.isr_nesting--;
    if (k_kernel.isr_nesting == 0)
        k_resched();
    k_arch_irq_restore(s);
}

/* ---- blocking and waking ---- */

static void k_block_prepare_at(struct k_waitq *wq, int has_deadline, k_ticks_t deadline)
{
    struct k_thread *t = k_kernel.current;
    k_ready_remove(t);
    t->state = K_THREAD_BLOCKED;
    t->waitq = wq;
    t->wait_result = K_ETIMEDOUT;
    if (wq != NULL)
        k_waitq_insert(wq, t);
    if (has_deadline)
        k_tlist_insert(&k_kernel.timers, &t->timer, deadline);
}

void k_block_prepare(struct k_waitq *wq, k_ticks_t timeout)
{
    k_block_prepare_at(wq, timeout != K_FOREVER, k_kernel.ticks + timeout);
}

int32_t k_block_commit(void)
{
    struct k_thread *t = k_kernel.current;
    k_resched();
    return t->wait_result;
}

int32_t k_block_until(struct k_waitq *wq, k_ticks_t deadline)
{
    k_block_prepare_at(wq, 1, deadline);
    return k_block_commit();
}

int32_t k_block(struct k_waitq *wq, k_ticks_t timeout)
{
    k_block_prepare(wq, timeout);
    return k_block_commit();
}

int32_t k_block_or_refuse(struct k_waitq *wq, k_ticks_t timeout)
{
    if (timeout == K_NO_WAIT)
        return K_EAGAIN;
    if (k_in_isr())
        return K_EISR;
    return k_block(wq, timeout);
}

void k_wake(struct k_thread *t, int32_t result)
{
    if (t->state != K_THREAD_BLOCKED)
        return;
    if (t->waitq != NULL) {
        k_list_remove(&t->node);
        t->waitq = NULL;
    }
    k_tlist_remove(&t->timer);
    t->wait_result = result;
    t->state = K_THREAD_READY;
    k_ready_append(t);
    if (t->wait_mutex != NULL) {
        struct k_mutex *m = t->wait_mutex;
        t->wait_mutex = NULL;
        if (result != K_OK)
            k_mutex_waiter_gone(m); /* the owner may lose what t lent it */
    }
}

/* ---- priorities ---- */

static void k_set_effective_prio(struct k_thread *t, uint8_t prio)
{
    if (t->prio == prio)
        return;
    if (t->state == K_THREAD_READY) {
        k_ready_remove(t);
        t->prio = prio;
        /* A boosted running thread keeps running: it is the head. */
        if (t == k_kernel.current)
            k_prioq_prepend(&k_kernel.ready, &t->node, prio);
        else
            k_ready_append(t);
    } else if (t->state == K_THREAD_BLOCKED && t->waitq != NULL) {
        k_list_remove(&t->node);
        t->prio = prio;
        k_waitq_insert(t->waitq, t);
    } else {
        t->prio = prio;
    }
}

void k_prio_update(struct k_thread *t)
{
    /* Each step changes a priority; a cycle of owners settles because the
     * boost is a maximum. The bound guards against anything else. */
    unsigned steps;
    for (steps = 0; t != NULL && steps < 64u; steps++) {
        uint8_t want = t->base_prio;
        struct k_list_node *n;
        for (n = t->held.next; n != &t->held; n = n->next) {
            struct k_mutex *m = K_CONTAINER_OF(n, struct k_mutex, held_node);
            struct k_thread *w = k_waitq_first(&m->wq);
            if (w != NULL && w->prio > want)
                want = w->prio;
        }
        if (want == t->prio)
            return;
        k_set_effective_prio(t, want);
        t = (t->state == K_THREAD_BLOCKED && t->wait_mutex != NULL) ? t->wait_mutex->owner : NULL;
    }
}

int k_thread_set_timeslice(struct k_thread *t, unsigned ticks)
{
    uint32_t s;
    if (t == NULL || ticks > 255u)
        return K_EINVAL;
    s = k_arch_irq_save();
    if (t->state == K_THREAD_UNUSED || t->state == K_THREAD_DEAD) {
        k_arch_irq_restore(s);
        return K_ESRCH;
    }
    t->timeslice = (uint8_t)ticks;
    if (ticks != 0u && t->slice_left > ticks)
        t->slice_left = (uint8_t)ticks;
    k_arch_irq_restore(s);
    return K_OK;
}

int k_thread_setprio(struct k_thread *t, unsigned prio)
{
    uint32_t s;
    if (t == NULL || prio < K_PRIO_APP_MIN || prio > K_PRIO_MAX)
        return K_EINVAL;
    s = k_arch_irq_save();
    if (t->state == K_THREAD_UNUSED || t->state == K_THREAD_DEAD) {
        k_arch_irq_restore(s);
        return K_ESRCH;
    }
    t->base_prio = (uint8_t)prio;
    k_prio_update(t); /* keeps any inherited boost */
    k_resched();
    k_arch_irq_restore(s);
    return K_OK;
}

/* ---- threads ---- */

static void k_thread_setup(struct k_thread *t, const char *name, k_thread_fn entry, void *arg,
                           uint32_t *stack, size_t words, uint8_t prio)
{
    size_t i;
    k_memset(t, 0, sizeof *t);
    t->name = name;
    t->entry = entry;
    t->arg = arg;
    t->stack_base = stack;
    t->stack_words = words;
    t->base_prio = prio;
    t->prio = prio;
    t->slice_left = K_TIMESLICE_TICKS;
    t->timeslice = K_TIMESLICE_TICKS;
    k_list_init(&t->held);
    k_waitq_init(&t->joiners);
    for (i = 0; i < words; i++) /* guard words, and a fill that shows the high-water mark */
        stack[i] = K_STACK_GUARD;
    k_arch_thread_init(t);
    t->canary = k_canary_of(t);
    t->state = K_THREAD_READY;
    t->all_next = k_kernel.all;
    k_kernel.all = t;
    k_ready_append(t);
}

int k_thread_create(struct k_thread *t, const char *name, k_thread_fn entry, void *arg,
                    uint32_t *stack, size_t stack_bytes, unsigned prio)
{
    uint32_t s;
    struct k_thread *o;
    if (t == NULL || entry == NULL || stack == NULL || stack_bytes < K_STACK_MIN_BYTES ||
        prio < K_PRIO_APP_MIN || prio > K_PRIO_MAX || ((uintptr_t)stack & 3u) != 0u)
        return K_EINVAL;
    s = k_arch_irq_save();
    for (o = k_kernel.all; o != NULL; o = o->all_next) {
        if (o == t && o->state != K_THREAD_DEAD) { /* still in use */
            k_arch_irq_restore(s);
            return K_EINVAL;
        }
    }
    if (k_kernel.all == t) /* re-creating a dead thread: unlink it first */
        k_kernel.all = t->all_next;
    else
        for (o = k_kernel.all; o != NULL; o = o->all_next)
            if (o->all_next == t) {
                o->all_next = t->all_next;
                break;
            }
#if K_ARCH_STACK_ALIGN > 4u
    {
        /* The port guards a stack from its K_ARCH_STACK_ALIGN-aligned base
         * up (an MPU region): a base below that boundary is moved up to it. */
        size_t skip = (size_t)(-(uintptr_t)stack & (K_ARCH_STACK_ALIGN - 1u));
        stack += skip / 4u;
        stack_bytes -= skip;
    }
#endif
    k_thread_setup(t, name, entry, arg, stack, stack_bytes / 4u, (uint8_t)prio);
    k_resched();
    k_arch_irq_restore(s);
    return K_OK;
}

void k_thread_start(void)
{
    struct k_thread *t = k_kernel.current;
    void *value;
    k_arch_irq_restore(0); /* threads start with interrupts enabled */
    value = t->entry(t->arg);
    k_thread_exit(value);
}

void k_thread_exit(void *value)
{
    struct k_thread *t = k_kernel.current;
    uint32_t s = k_arch_irq_save();
    if (k_kernel.isr_nesting != 0 || t == &k_kernel.idle || !k_kernel.started) {
        /* Not a thread that can end: nothing sensible to do but keep going. */
        k_arch_irq_restore(s);
        return;
    }
    t->exit_value = value;
    t->wait_result = K_OK;
    k_ready_remove(t);
    t->state = K_THREAD_DEAD;
    k_mutex_release_all(t);
    k_wake_joiners(t);
    k_resched();
    /* not reached: nothing switches back to a dead thread */
    for (;;)
        k_arch_idle();
}

int k_thread_join(struct k_thread *t, void **value, k_ticks_t timeout)
{
    uint32_t s;
    int32_t r;
    if (t == NULL)
        return K_EINVAL;
    if (k_in_isr() && timeout != K_NO_WAIT)
        return K_EISR;
    s = k_arch_irq_save();
    if (t->state == K_THREAD_UNUSED) {
        r = K_ESRCH;
    } else if (t == k_kernel.current) {
        r = K_EDEADLK;
    } else if (t->state == K_THREAD_DEAD) {
        r = K_OK;
    } else if (timeout == K_NO_WAIT) {
        r = K_EAGAIN;
    } else {
        r = k_block(&t->joiners, timeout);
    }
    if (r == K_OK) {
        if (value != NULL)
            *value = t->exit_value;
        if (t->wait_result == K_ESTACK)
            r = K_ESTACK;
    }
    k_arch_irq_restore(s);
    return r;
}

struct k_thread *k_thread_self(void)
{
    return k_kernel.current;
}

struct k_thread *k_stack_overflowed(void)
{
    return k_kernel.overflowed;
}

int k_sched_yield(void)
{
    uint32_t s;
    struct k_thread *t;
    if (k_in_isr())
        return K_EISR;
    s = k_arch_irq_save();
    t = k_kernel.current;
    (void)k_prioq_rotate(&k_kernel.ready, t->prio);
    k_resched();
    k_arch_irq_restore(s);
    return K_OK;
}

/* ---- the tick ---- */

void k_tick(void)
{
    uint32_t s = k_arch_irq_save();
    struct k_timer_node *tn;
    struct k_thread *cur = k_kernel.current;
    k_ticks_t now = k_kernel.ticks + 1u;

    k_kernel.ticks = now;
    k_stats.ticks_isr++;
    if (++k_kernel.subticks == K_TICK_HZ) {
        k_kernel.subticks = 0;
        k_kernel.seconds++;
    }
    while ((tn = k_tlist_pop_expired(&k_kernel.timers, now)) != NULL)
        k_wake(K_CONTAINER_OF(tn, struct k_thread, timer), K_ETIMEDOUT);
    if (k_kernel.started && cur->state == K_THREAD_READY && cur != &k_kernel.idle &&
        cur->timeslice != 0u) {
        if (cur->slice_left > 1u) {
            cur->slice_left--;
        } else {
            cur->slice_left = cur->timeslice;
            (void)k_prioq_rotate(&k_kernel.ready, cur->prio);
        }
    }
    k_resched(); /* deferred to k_isr_exit when called from the handler */
    k_arch_irq_restore(s);
    {
        void (*hook)(k_ticks_t) = k_tick_hook;
        if (hook != NULL)
            hook(now);
    }
}

/* ---- time ---- */

k_ticks_t k_ticks(void)
{
    return k_kernel.ticks;
}

void k_timestamp_register(k_timestamp_fn read, uint32_t hz, k_timestamp_start_fn start)
{
    uint32_t s = k_arch_irq_save();
    /* Both or neither: a read without its rate would give counts of no known unit. */
    k_timestamp_registered = hz != 0u ? read : NULL;
    k_timestamp_rate = read != NULL ? hz : 0u;
    k_timestamp_starter = start;
    k_timestamp_read = NULL;
    k_timestamp_started = K_TIMESTAMP_UNSTARTED;
    k_arch_irq_restore(s);
}

int k_timestamp_start(void)
{
    int r;
    if (k_timestamp_started != K_TIMESTAMP_UNSTARTED)
        return k_timestamp_started;
    if (k_timestamp_registered == NULL)
        r = K_EINVAL;
    else if (k_timestamp_starter != NULL)
        r = k_timestamp_starter();
    else
        r = K_OK;
    if (r == K_OK)
        k_timestamp_read = k_timestamp_registered;
    k_timestamp_started = r;
    return r;
}

uint32_t k_timestamp(void)
{
    k_timestamp_fn read = k_timestamp_read;
    return read != NULL ? read() : k_kernel.ticks;
}

uint32_t k_timestamp_hz(void)
{
    return k_timestamp_read != NULL ? k_timestamp_rate : (uint32_t)K_TICK_HZ;
}

uint32_t k_uptime_ms(void)
{
    uint32_t s = k_arch_irq_save();
    uint32_t sec = k_kernel.seconds, sub = k_kernel.subticks;
    k_arch_irq_restore(s);
    return sec * 1000u + sub * 1000u / K_TICK_HZ;
}

int k_clock_gettime(int clock_id, struct k_timespec *ts)
{
    uint32_t s, sec, sub;
    if (clock_id != K_CLOCK_MONOTONIC || ts == NULL)
        return K_EINVAL;
    s = k_arch_irq_save();
    sec = k_kernel.seconds;
    sub = k_kernel.subticks;
    k_arch_irq_restore(s);
    ts->tv_sec = (int32_t)sec;
    ts->tv_nsec = (int32_t)(sub * K_NS_PER_TICK_X2 / 2u);
    return K_OK;
}

k_ticks_t k_ms_to_ticks(uint32_t ms)
{
    /* ms * HZ / 1000 rounded up, without overflow for any ms */
    uint32_t whole = ms / 1000u, rest = ms % 1000u;
    return whole * K_TICK_HZ + (rest * K_TICK_HZ + 999u) / 1000u;
}

static int k_timespec_valid(const struct k_timespec *t)
{
    return t != NULL && t->tv_sec >= 0 && t->tv_nsec >= 0 && t->tv_nsec < 1000000000;
}

/* Ticks covering a duration, rounded up; saturates below K_FOREVER. */
static k_ticks_t k_timespec_to_ticks(const struct k_timespec *t)
{
    uint32_t sec = (uint32_t)t->tv_sec;
    uint32_t part = ((uint32_t)t->tv_nsec * 2u + K_NS_PER_TICK_X2 - 1u) / K_NS_PER_TICK_X2;
    if (sec >= (0x7FFFFFFFu - part) / K_TICK_HZ)
        return 0x7FFFFFFFu;
    return sec * K_TICK_HZ + part;
}

int k_abs_to_timeout(const struct k_timespec *abs, k_ticks_t *timeout)
{
    uint32_t s, sec, sub, part, abs_sec;
    if (!k_timespec_valid(abs))
        return K_EINVAL;
    s = k_arch_irq_save();
    sec = k_kernel.seconds;
    sub = k_kernel.subticks;
    k_arch_irq_restore(s);
    /* In whole ticks: the deadline is the first tick at or after abs. (The
     * clock reads a tick's start with its nanoseconds truncated, so
     * subtracting timespecs left up to a nanosecond that rounded up to one
     * tick too many when a tick fell between the two clock reads.) */
    abs_sec = (uint32_t)abs->tv_sec;
    part = ((uint32_t)abs->tv_nsec * 2u + K_NS_PER_TICK_X2 - 1u) / K_NS_PER_TICK_X2;
    if (abs_sec < sec || (abs_sec == sec && part <= sub)) {
        *timeout = K_NO_WAIT;
        return K_OK;
    }
    if (abs_sec - sec >= 0x7FFFFFFFu / K_TICK_HZ - 1u) {
        *timeout = 0x7FFFFFFFu;
        return K_OK;
    }
    *timeout = (abs_sec - sec) * K_TICK_HZ + part - sub;
    return K_OK;
}

int k_sleep_until(k_ticks_t deadline)
{
    uint32_t s;
    if (k_in_isr())
        return K_EISR;
    s = k_arch_irq_save();
    if (k_tick_before(k_kernel.ticks, deadline))
        (void)k_block_until(NULL, deadline);
    k_arch_irq_restore(s);
    return K_OK;
}

int k_sleep_ticks(k_ticks_t ticks)
{
    uint32_t s;
    if (k_in_isr())
        return K_EISR;
    if (ticks == K_FOREVER)
        return K_EINVAL;
    s = k_arch_irq_save();
    if (ticks == 0u) { /* like a yield */
        (void)k_prioq_rotate(&k_kernel.ready, k_kernel.current->prio);
        k_resched();
    } else {
        (void)k_block_until(NULL, k_kernel.ticks + ticks);
    }
    k_arch_irq_restore(s);
    return K_OK;
}

int k_nanosleep(const struct k_timespec *req)
{
    if (!k_timespec_valid(req))
        return K_EINVAL;
    /* +1: the current tick is already partly over */
    return k_sleep_ticks(k_timespec_to_ticks(req) + 1u);
}

int k_clock_nanosleep(int clock_id, int flags, const struct k_timespec *t)
{
    k_ticks_t ticks;
    int r;
    if (clock_id != K_CLOCK_MONOTONIC || !k_timespec_valid(t))
        return K_EINVAL;
    if (flags != K_TIMER_ABSTIME)
        return k_nanosleep(t);
    if (k_in_isr())
        return K_EISR;
    r = k_abs_to_timeout(t, &ticks);
    if (r != K_OK)
        return r;
    return ticks == 0u ? K_OK : k_sleep_ticks(ticks);
}

/* ---- introspection ---- */

/* Bytes of the stack that were ever written: it grows down from the top, so
 * the untouched words still holding the fill are the lowest ones. */
static uint32_t k_stack_high_water(const uint32_t *base, size_t words)
{
    size_t untouched = 0;
    if (base == NULL)
        return 0;
    while (untouched < words && base[untouched] == K_STACK_GUARD)
        untouched++;
    return (uint32_t)((words - untouched) * 4u);
}

int k_thread_list(struct k_thread_info *out, unsigned max)
{
    const struct k_thread *t;
    unsigned count = 0, i;
    uint32_t s;
    if (out == NULL && max > 0u)
        return K_EINVAL;
    s = k_arch_irq_save();
    for (t = k_kernel.all; t != NULL; t = t->all_next, count++) {
        if (!k_tcb_intact(t))
            k_fatal_tcb(t);
        if (count < max) {
            struct k_thread_info *info = &out[count];
            info->name = t->name != NULL ? t->name : "?";
            info->prio = t->prio;
            info->base_prio = t->base_prio;
            info->state = t->state;
            info->is_current = (uint8_t)(t == k_kernel.current);
            info->stack_base = t->stack_base;
            info->stack_bytes = (uint32_t)(t->stack_words * 4u);
            info->stack_used = 0;
            info->switches_in = t->switches_in;
            info->stack_intact = (uint8_t)k_stack_intact(t);
        }
    }
    k_arch_irq_restore(s);
    /* Stacks are static storage: scanning one whose thread changes meanwhile
     * only gives a figure that is slightly out of date. */
    for (i = 0; i < count && i < max; i++)
        out[i].stack_used = k_stack_high_water(out[i].stack_base, out[i].stack_bytes / 4u);
    return (int)count;
}

int k_irq_stack_usage(uint32_t *bytes, uint32_t *used)
{
    size_t words;
    const uint32_t *base;
    if (bytes == NULL || used == NULL)
        return K_EINVAL;
    base = k_arch_irq_stack(&words);
    if (base == NULL)
        return K_ESRCH;
    *bytes = (uint32_t)(words * 4u);
    *used = k_stack_high_water(base, words);
    return K_OK;
}

/* ---- start-up ---- */

static void *k_idle_main(void *arg)
{
    (void)arg;
    for (;;)
        k_arch_idle();
    return NULL;
}

void k_init(void)
{
    k_memset(&k_kernel, 0, sizeof k_kernel);
    k_memset(&k_stats, 0, sizeof k_stats);
    k_tick_hook = NULL;
    k_timestamp_registered = NULL;
    k_timestamp_starter = NULL;
    k_timestamp_rate = 0;
    k_timestamp_read = NULL;
    k_timestamp_started = K_TIMESTAMP_UNSTARTED;
    k_prioq_init(&k_kernel.ready);
    k_tlist_init(&k_kernel.timers);
    k_thread_setup(&k_kernel.idle, "idle", k_idle_main, NULL, k_idle_stack,
                   K_STACK_WORDS(K_IDLE_STACK_BYTES), (uint8_t)K_PRIO_IDLE);
    /* The boot context: a pseudo-thread so k_start has somewhere to save. */
    k_kernel.boot.name = "boot";
    k_kernel.boot.canary = k_canary_of(&k_kernel.boot);
    k_kernel.boot.state = K_THREAD_DEAD;
    k_list_init(&k_kernel.boot.held);
    k_waitq_init(&k_kernel.boot.joiners);
    k_kernel.current = &k_kernel.boot;
}

void k_start(void)
{
    uint32_t s = k_arch_irq_save();
    struct k_thread *next = k_ready_best();
    k_kernel.started = 1;
    next->slice_left = K_TIMESLICE_TICKS;
    next->switches_in++;
    k_kernel.current = next;
    k_arch_switch(&k_kernel.boot, next);
    /* Host port only: the idle thread switches back here when nothing is left. */
    k_kernel.started = 0;
    k_kernel.current = &k_kernel.boot;
    k_arch_irq_restore(s);
}
