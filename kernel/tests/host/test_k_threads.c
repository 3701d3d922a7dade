/*
 * Host unit tests of the kernel's thread services on the ucontext port.
 * Threads record what they see in globals; the assertions run after
 * k_start returns (when every thread is dead or blocked forever). Time
 * passes only through ticks: host_tick() in a busy thread is a tick
 * interrupt at that point, and the idle thread ticks while timers pend.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "kernel.h"
#include "k_bsched.h"
#include "host_port.h"

#define STACK_BYTES (64u * 1024u)
#define NTHREADS 6
static uint32_t stacks[NTHREADS][STACK_BYTES / 4u];
static struct k_thread th[NTHREADS];

/* Event log: which thread did what, in order. */
static char trace[256];
static size_t trace_len;
static void mark(char c)
{
    if (trace_len + 1u < sizeof trace) {
        trace[trace_len++] = c;
        trace[trace_len] = '\0';
    }
}

static int rc[8];
static k_ticks_t when[8];

static int setup(void **state)
{
    (void)state;
    memset(rc, 0, sizeof rc);
    memset(when, 0, sizeof when);
    k_init();
    memset(th, 0, sizeof th);
    trace_len = 0;
    trace[0] = '\0';
    host_console_clear();
    return 0;
}

static int spawn(int i, const char *name, k_thread_fn fn, void *arg, unsigned prio)
{
    return k_thread_create(&th[i], name, fn, arg, stacks[i], STACK_BYTES, prio);
}

/* ---- creation and argument checks ---- */

static void *noop(void *arg)
{
    return arg;
}

static void test_create_rejects_bad_arguments(void **state)
{
    (void)state;
    assert_int_equal(k_thread_create(NULL, "x", noop, NULL, stacks[0], STACK_BYTES, 5), K_EINVAL);
    assert_int_equal(k_thread_create(&th[0], "x", NULL, NULL, stacks[0], STACK_BYTES, 5), K_EINVAL);
    assert_int_equal(k_thread_create(&th[0], "x", noop, NULL, stacks[0], 16, 5), K_EINVAL);
    assert_int_equal(k_thread_create(&th[0], "x", noop, NULL, stacks[0], STACK_BYTES, 0), K_EINVAL);
    assert_int_equal(k_thread_create(&th[0], "x", noop, NULL, stacks[0], STACK_BYTES, 32), K_EINVAL);
    assert_int_equal(spawn(0, "x", noop, NULL, 5), K_OK);
    assert_int_equal(spawn(0, "x", noop, NULL, 5), K_EINVAL); /* still live */
}

/* ---- priority order ---- */

static void *tracer(void *arg)
{
    mark(*(const char *)arg);
    return NULL;
}

static void test_priority_order(void **state)
{
    (void)state;
    spawn(0, "low", tracer, "L", 3);
    spawn(1, "high", tracer, "H", 20);
    spawn(2, "mid", tracer, "M", 10);
    spawn(3, "mid2", tracer, "m", 10);
    k_start();
    assert_string_equal(trace, "HMmL");
}

/* A thread that creates a more urgent one is pre-empted at once. */
static void *creator(void *arg)
{
    (void)arg;
    mark('a');
    spawn(1, "urgent", tracer, "U", 25);
    mark('b');
    return NULL;
}

static void test_create_preempts(void **state)
{
    (void)state;
    spawn(0, "creator", creator, NULL, 5);
    k_start();
    assert_string_equal(trace, "aUb");
}

/* ---- pre-emption by the tick: round robin among busy threads ---- */

static volatile int spin_stop;
static uint32_t spin_count[3];

static void *busy(void *arg)
{
    int i = (int)(intptr_t)arg;
    while (!spin_stop) {
        spin_count[i]++;
        if (spin_count[i] % 10u == 0u)
            mark((char)('0' + i));
        host_tick(); /* a tick interrupt lands here */
        if (k_ticks() >= 95u)
            spin_stop = 1;
    }
    return NULL;
}

static void test_timeslice_round_robin(void **state)
{
    (void)state;
    spin_stop = 0;
    memset(spin_count, 0, sizeof spin_count);
    spawn(0, "busy0", busy, (void *)0, 5);
    spawn(1, "busy1", busy, (void *)1, 5);
    spawn(2, "busy2", busy, (void *)2, 5);
    k_start();
    /* slices of K_TIMESLICE_TICKS ticks, taken in turn */
    assert_true(spin_count[0] >= 30u && spin_count[1] >= 30u && spin_count[2] >= 30u);
    assert_memory_equal(trace, "012012012", 9);
    assert_true(k_stats.context_switches >= 9u);
}

/* With no slice (SCHED_FIFO), a busy thread keeps the CPU from equals. */
static void test_timeslice_none_is_fifo(void **state)
{
    (void)state;
    spin_stop = 0;
    memset(spin_count, 0, sizeof spin_count);
    spawn(0, "busy0", busy, (void *)0, 5);
    spawn(1, "busy1", busy, (void *)1, 5);
    assert_int_equal(k_thread_set_timeslice(&th[0], 0), K_OK);
    assert_int_equal(k_thread_set_timeslice(&th[1], 256), K_EINVAL);
    assert_int_equal(k_thread_set_timeslice(NULL, 1), K_EINVAL);
    assert_int_equal(k_thread_set_timeslice(&th[2], 1), K_ESRCH);
    k_start();
    /* busy0 spins until the stop at tick 95; busy1 runs only after that */
    assert_true(spin_count[0] >= 90u);
    assert_int_equal(spin_count[1], 0u);
    assert_memory_equal(trace, "000000000", 9);
}

/* A more urgent thread that wakes from sleep pre-empts a busy one at the tick. */
static uint32_t woke_at;
static void *sleeper(void *arg)
{
    (void)arg;
    k_sleep_ticks(7);
    woke_at = k_ticks();
    mark('S');
    return NULL;
}

static void *busy_until(void *arg)
{
    (void)arg;
    while (k_ticks() < 20u) {
        if (k_ticks() == 6u)
            mark('b');
        host_tick();
    }
    mark('B');
    return NULL;
}

static void test_preemption_of_busy_thread(void **state)
{
    (void)state;
    spawn(0, "busy", busy_until, NULL, 4);
    spawn(1, "sleeper", sleeper, NULL, 9);
    k_start();
    assert_int_equal(woke_at, 7);
    assert_string_equal(trace, "bSB");
}

/* ---- changing priorities ---- */
static void *raiser(void *arg)
{
    (void)arg;
    mark('b');
    rc[0] = k_thread_setprio(&th[0], 20); /* th[0] now outranks us: runs at once */
    mark('B');
    rc[1] = k_thread_setprio(&th[0], 0);
    rc[2] = k_thread_setprio(&th[0], 5);  /* th[0] has exited */
    return NULL;
}

static void test_setprio_preempts(void **state)
{
    (void)state;
    spawn(0, "a", tracer, "a", 5);
    spawn(1, "b", raiser, NULL, 10);
    k_start();
    assert_string_equal(trace, "baB");
    assert_int_equal(rc[0], K_OK);
    assert_int_equal(rc[1], K_EINVAL);
    assert_int_equal(rc[2], K_ESRCH);
}

/* ---- yield ---- */
static void *yielder(void *arg)
{
    int i;
    for (i = 0; i < 3; i++) {
        mark(*(const char *)arg);
        k_sched_yield();
    }
    return NULL;
}

static void test_yield_round_robin(void **state)
{
    (void)state;
    spawn(0, "a", yielder, "a", 5);
    spawn(1, "b", yielder, "b", 5);
    k_start();
    assert_string_equal(trace, "ababab");
}

/* ---- sleeping and time ---- */

static uint32_t drift_max;
static void *periodic(void *arg)
{
    k_ticks_t next = k_ticks();
    int i;
    (void)arg;
    for (i = 0; i < 10000; i++) {
        next += 3u;
        k_sleep_until(next);
        if (k_ticks() - next > drift_max)
            drift_max = k_ticks() - next;
        if (i % 7 == 0) /* work that takes up to 2 ticks must not add drift */
            host_tick(), host_tick();
    }
    return NULL;
}

static void test_sleep_until_no_drift(void **state)
{
    (void)state;
    drift_max = 0;
    spawn(0, "periodic", periodic, NULL, 10);
    k_start();
    assert_int_equal(drift_max, 0);
    assert_int_equal(k_ticks(), 30000);
}

static struct k_timespec ts_seen;
static uint32_t ms_seen;
static int nanosleep_rc;
static void *timekeeper(void *arg)
{
    struct k_timespec req = {1, 500000000};
    (void)arg;
    nanosleep_rc = k_nanosleep(&req);
    k_clock_gettime(K_CLOCK_MONOTONIC, &ts_seen);
    ms_seen = k_uptime_ms();
    return NULL;
}

static void test_nanosleep_and_clock(void **state)
{
    struct k_timespec bad = {0, 1000000000};
    (void)state;
    spawn(0, "time", timekeeper, NULL, 10);
    k_start();
    assert_int_equal(nanosleep_rc, K_OK);
    /* 1.5 s = 1536 ticks, +1 for the running tick */
    assert_int_equal(k_ticks(), 1537);
    assert_int_equal(ts_seen.tv_sec, 1);
    assert_int_equal(ts_seen.tv_nsec, 513 * 1953125 / 2); /* 513 ticks into the second */
    assert_int_equal(ms_seen, 1000u + 513u * 1000u / 1024u);
    assert_int_equal(k_nanosleep(&bad), K_EINVAL);
    assert_int_equal(k_clock_gettime(0, &ts_seen), K_EINVAL);
    assert_int_equal(k_ms_to_ticks(1000), 1024);
    assert_int_equal(k_ms_to_ticks(1), 2);
    assert_int_equal(k_ms_to_ticks(0), 0);
}

static k_ticks_t abs_woke;
static void *abs_sleeper(void *arg)
{
    struct k_timespec t = {2, 0};
    (void)arg;
    k_clock_nanosleep(K_CLOCK_MONOTONIC, K_TIMER_ABSTIME, &t);
    abs_woke = k_ticks();
    return NULL;
}

static void test_clock_nanosleep_absolute(void **state)
{
    (void)state;
    spawn(0, "abs", abs_sleeper, NULL, 10);
    k_start();
    assert_int_equal(abs_woke, 2048);
}

/* ---- semaphores ---- */

static struct k_sem sem;

static void *sem_waiter_timeout(void *arg)
{
    (void)arg;
    rc[0] = k_sem_wait_ticks(&sem, 50);
    when[0] = k_ticks();
    rc[1] = k_sem_trywait(&sem);
    return NULL;
}

static void test_sem_timeout(void **state)
{
    (void)state;
    k_sem_init(&sem, 0, 10);
    spawn(0, "w", sem_waiter_timeout, NULL, 10);
    k_start();
    assert_int_equal(rc[0], K_ETIMEDOUT);
    assert_int_equal(when[0], 50);
    assert_int_equal(rc[1], K_EAGAIN);
}

static void *sem_poster(void *arg)
{
    (void)arg;
    k_sleep_ticks(5);
    mark('p');
    rc[2] = k_sem_post(&sem);
    mark('q');
    return NULL;
}

static void *sem_waiter(void *arg)
{
    mark(*(const char *)arg);
    rc[*(const char *)arg == 'A' ? 0 : 1] = k_sem_wait(&sem);
    mark((char)(*(const char *)arg + 32));
    return NULL;
}

static void test_sem_handoff_order(void **state)
{
    (void)state;
    k_sem_init(&sem, 0, 10);
    spawn(0, "A", sem_waiter, "A", 8);
    spawn(1, "B", sem_waiter, "B", 12);
    spawn(2, "poster", sem_poster, NULL, 10);
    k_start();
    /* B (more urgent) gets the unit and pre-empts the poster; A waits forever */
    assert_string_equal(trace, "BApbq");
    assert_int_equal(rc[1], K_OK);
    assert_int_equal(rc[2], K_OK);
    assert_int_equal(th[0].state, K_THREAD_BLOCKED);
    assert_int_equal(sem.count, 0);
}

static void *sem_timed_abs(void *arg)
{
    struct k_timespec abs = {0, 100000000}; /* 0.1 s = 102.4 ticks -> 103 */
    (void)arg;
    rc[0] = k_sem_timedwait(&sem, &abs);
    when[0] = k_ticks();
    return NULL;
}

static void test_sem_timedwait_absolute(void **state)
{
    int32_t v = -1;
    (void)state;
    k_sem_init(&sem, 0, 1);
    spawn(0, "t", sem_timed_abs, NULL, 10);
    k_start();
    assert_int_equal(rc[0], K_ETIMEDOUT);
    assert_int_equal(when[0], 103);
    assert_int_equal(k_sem_post(&sem), K_OK);
    assert_int_equal(k_sem_post(&sem), K_EOVERFLOW);
    assert_int_equal(k_sem_getvalue(&sem, &v), K_OK);
    assert_int_equal(v, 1);
    assert_int_equal(k_sem_init(&sem, 2, 1), K_EINVAL);
    assert_int_equal(k_sem_post(NULL), K_EINVAL);
}

/* An absolute deadline read at tick 2 (1953125 ns, exact) with tick 3
 * passing before the wait (2929687.5 ns, which the clock truncates): the
 * wait must end at tick 2 + 1024, not one tick later (the difference of the
 * two readings, 1 s - 976562 ns, is a hair over 1023 ticks). */
static void *sem_timed_abs_after_a_tick(void *arg)
{
    struct k_timespec abs;
    (void)arg;
    k_sleep_ticks(2);                       /* tick 2 */
    k_clock_gettime(K_CLOCK_MONOTONIC, &abs);
    abs.tv_sec += 1;
    host_tick();                            /* tick 3 before the wait */
    rc[0] = k_sem_timedwait(&sem, &abs);
    when[0] = k_ticks();
    return NULL;
}

static void test_sem_timedwait_absolute_whole_ticks(void **state)
{
    (void)state;
    k_sem_init(&sem, 0, 1);
    spawn(0, "t", sem_timed_abs_after_a_tick, NULL, 10);
    k_start();
    assert_int_equal(rc[0], K_ETIMEDOUT);
    assert_int_equal(when[0], 2u + K_TICK_HZ);
}

/* ---- interrupts ---- */

static void isr_posts(void *arg)
{
    struct k_sem *s = arg;
    rc[4] = k_sem_wait_ticks(s, 10);       /* waiting in a handler: refused */
    rc[5] = k_sem_post(s);
    rc[6] = k_mutex_lock(NULL) == K_EINVAL && k_in_isr();
    mark('i');
}

static void *isr_waiter(void *arg)
{
    (void)arg;
    rc[0] = k_sem_wait(&sem);
    mark('w');
    return NULL;
}

static void *irq_raiser(void *arg)
{
    (void)arg;
    mark('r');
    host_raise_irq(70);
    mark('R');
    return NULL;
}

static void test_irq_wakes_thread(void **state)
{
    (void)state;
    k_sem_init(&sem, 0, 5);
    assert_int_equal(k_irq_register(70, 4, isr_posts, &sem), K_OK);
    assert_int_equal(host_irq_routed[70] > 0u, 1);
    assert_int_equal(k_irq_register(40, 4, isr_posts, &sem), K_EINVAL);
    assert_int_equal(k_irq_register(70, 8, isr_posts, &sem), K_EINVAL);
    spawn(0, "waiter", isr_waiter, NULL, 15);
    spawn(1, "raiser", irq_raiser, NULL, 5);
    k_start();
    /* the handler runs, and the woken thread pre-empts at handler exit */
    assert_string_equal(trace, "riwR");
    assert_int_equal(rc[4], K_EISR);
    assert_int_equal(rc[5], K_OK);
    assert_int_equal(rc[0], K_OK);
    host_raise_irq(99); /* nothing registered */
    assert_int_equal(k_stats.spurious_irqs, 1);
}

/* ---- mutexes ---- */

static struct k_mutex mtx, mtx2;

static void *mutex_misuser(void *arg)
{
    (void)arg;
    rc[0] = k_mutex_unlock(&mtx);      /* not locked by us */
    rc[1] = k_mutex_lock(&mtx);
    rc[2] = k_mutex_lock(&mtx);        /* relock */
    rc[3] = k_mutex_unlock(&mtx);
    return NULL;
}

static void *mutex_holder_forever(void *arg)
{
    (void)arg;
    k_mutex_lock(&mtx);
    k_sleep_ticks(1000);
    return NULL;
}

static void *mutex_stranger(void *arg)
{
    (void)arg;
    k_sleep_ticks(1);
    rc[4] = k_mutex_unlock(&mtx);      /* held by another thread */
    rc[5] = k_mutex_trylock(&mtx);
    rc[6] = k_mutex_lock_ticks(&mtx, 20);
    when[6] = k_ticks();
    return NULL;
}

static void test_mutex_owner_checks(void **state)
{
    (void)state;
    k_mutex_init(&mtx);
    spawn(0, "misuser", mutex_misuser, NULL, 10);
    k_start();
    assert_int_equal(rc[0], K_EPERM);
    assert_int_equal(rc[1], K_OK);
    assert_int_equal(rc[2], K_EDEADLK);
    assert_int_equal(rc[3], K_OK);
    setup(NULL);
    k_mutex_init(&mtx);
    spawn(0, "holder", mutex_holder_forever, NULL, 10);
    spawn(1, "stranger", mutex_stranger, NULL, 10);
    k_start();
    assert_int_equal(rc[4], K_EPERM);
    assert_int_equal(rc[5], K_EBUSY);
    assert_int_equal(rc[6], K_ETIMEDOUT);
    assert_int_equal(when[6], 21);
}

/* Classic inversion: low holds, high waits, medium is busy. With inheritance
 * low runs at high's priority and releases before medium gets the CPU. */
static uint8_t low_prio_seen;
static void *pi_low(void *arg)
{
    (void)arg;
    k_mutex_lock(&mtx);
    mark('l');
    k_sleep_ticks(2); /* high and medium wake meanwhile */
    low_prio_seen = th[0].prio;
    mark('L');
    k_mutex_unlock(&mtx);
    mark('u');
    return NULL;
}

static void *pi_high(void *arg)
{
    (void)arg;
    k_sleep_ticks(1);
    mark('h');
    rc[0] = k_mutex_lock(&mtx);
    mark('H');
    k_mutex_unlock(&mtx);
    return NULL;
}

static void *pi_medium(void *arg)
{
    (void)arg;
    k_sleep_ticks(1);
    mark('m');
    while (k_ticks() < 50u)
        host_tick();
    mark('M');
    return NULL;
}

static void test_priority_inheritance(void **state)
{
    (void)state;
    k_mutex_init(&mtx);
    spawn(0, "low", pi_low, NULL, 3);
    spawn(1, "high", pi_high, NULL, 20);
    spawn(2, "medium", pi_medium, NULL, 10);
    k_start();
    assert_int_equal(low_prio_seen, 20);
    assert_int_equal(rc[0], K_OK);
    /* h blocks, m spins, but l (boosted) pre-empts m at the tick of its
     * wake-up, releases, H runs, then m finishes, then l's tail. */
    assert_string_equal(trace, "lhmLHMu");
    assert_int_equal(th[0].prio, 3);
}

/* Inheritance through a chain: high waits on mtx2 held by mid, who waits on
 * mtx held by low. Low must run at high's priority. Then a timeout of
 * high's wait takes the boost away again. */
static uint8_t chain_seen[3];
static void *chain_low(void *arg)
{
    (void)arg;
    k_mutex_lock(&mtx);
    k_sleep_ticks(3);
    chain_seen[0] = th[0].prio;
    k_sleep_ticks(10);                 /* high's wait times out meanwhile */
    chain_seen[1] = th[0].prio;
    k_mutex_unlock(&mtx);
    chain_seen[2] = th[0].prio;
    return NULL;
}

static void *chain_mid(void *arg)
{
    (void)arg;
    k_sleep_ticks(1);
    k_mutex_lock(&mtx2);
    rc[1] = k_mutex_lock(&mtx);
    k_mutex_unlock(&mtx);
    k_mutex_unlock(&mtx2);
    return NULL;
}

static void *chain_high(void *arg)
{
    (void)arg;
    k_sleep_ticks(2);
    rc[2] = k_mutex_lock_ticks(&mtx2, 5);
    return NULL;
}

static void test_priority_inheritance_chain_and_timeout(void **state)
{
    (void)state;
    k_mutex_init(&mtx);
    k_mutex_init(&mtx2);
    spawn(0, "low", chain_low, NULL, 2);
    spawn(1, "mid", chain_mid, NULL, 8);
    spawn(2, "high", chain_high, NULL, 16);
    k_start();
    assert_int_equal(chain_seen[0], 16); /* through mid */
    assert_int_equal(chain_seen[1], 8);  /* high gave up: only mid's boost left */
    assert_int_equal(chain_seen[2], 2);
    assert_int_equal(rc[2], K_ETIMEDOUT);
    assert_int_equal(rc[1], K_OK);
    assert_int_equal(th[1].prio, 8);
}

static void *dies_holding(void *arg)
{
    (void)arg;
    k_mutex_lock(&mtx);
    return NULL;
}

static void *inherits_dead(void *arg)
{
    (void)arg;
    k_sleep_ticks(1);
    rc[0] = k_mutex_lock(&mtx);
    rc[1] = k_mutex_unlock(&mtx);
    return NULL;
}

static void *dies_holding_later(void *arg)
{
    (void)arg;
    k_mutex_lock(&mtx);
    k_sleep_ticks(3);
    return NULL;
}

static void test_mutex_owner_dies(void **state)
{
    (void)state;
    /* nobody waiting when the owner dies: the next locker is told */
    k_mutex_init(&mtx);
    spawn(0, "dies", dies_holding, NULL, 10);
    spawn(1, "next", inherits_dead, NULL, 5);
    k_start();
    assert_int_equal(rc[0], K_EOWNERDEAD);
    assert_int_equal(rc[1], K_OK);
    assert_null(mtx.owner);
    /* a waiter when the owner dies: it gets the mutex and the news */
    setup(NULL);
    k_mutex_init(&mtx);
    spawn(0, "dies", dies_holding_later, NULL, 10);
    spawn(1, "next", inherits_dead, NULL, 5);
    k_start();
    assert_int_equal(rc[0], K_EOWNERDEAD);
    assert_int_equal(rc[1], K_OK);
    assert_int_equal(mtx.owner_died, 0);
}

/* ---- message queues ---- */

static struct k_mq mq;
static uint32_t mq_storage[4];

static void *mq_producer(void *arg)
{
    uint32_t i;
    (void)arg;
    for (i = 0; i < 4; i++)
        rc[0] |= k_mq_send(&mq, &i);
    i = 4;
    rc[1] = k_mq_send_ticks(&mq, &i, K_NO_WAIT);     /* full */
    rc[2] = k_mq_send_ticks(&mq, &i, 10);            /* full: times out */
    when[2] = k_ticks();
    for (i = 10; i < 16; i++)                         /* blocks; consumer drains */
        rc[3] |= k_mq_send(&mq, &i);
    return NULL;
}

static uint32_t got[16];
static int ngot;
static void *mq_consumer(void *arg)
{
    uint32_t v;
    (void)arg;
    k_sleep_ticks(20);
    while (k_mq_receive_ticks(&mq, &v, 5) == K_OK)
        got[ngot++] = v;
    rc[4] = k_mq_receive_ticks(&mq, &v, K_NO_WAIT);  /* empty */
    return NULL;
}

/* ---- condition variables ---- */

static struct k_cond cnd;
static int cond_ready;

static void *cond_waiter(void *arg)
{
    k_mutex_lock(&mtx);
    mark(*(const char *)arg);
    while (!cond_ready)
        rc[*(const char *)arg - 'A'] = k_cond_wait(&cnd, &mtx);
    /* The mutex is held again on return. */
    rc[4 + (*(const char *)arg - 'A')] = mtx.owner == k_thread_self();
    mark((char)(*(const char *)arg + 32));
    k_mutex_unlock(&mtx);
    return NULL;
}

static void *cond_signaller(void *arg)
{
    (void)arg;
    k_sleep_ticks(5);
    k_mutex_lock(&mtx);
    cond_ready = 1;
    mark('s');
    rc[3] = arg == NULL ? k_cond_signal(&cnd) : k_cond_broadcast(&cnd);
    mark('u');
    k_mutex_unlock(&mtx);
    return NULL;
}

/* Waiters A (priority 8) and B (12) on cnd, then the signaller: one signal
 * (signaller_arg NULL) or a broadcast; returns when every thread is dead or
 * blocked forever (k_start on the host). */
static void run_cond_waiters(void *signaller_arg)
{
    cond_ready = 0;
    k_mutex_init(&mtx);
    k_cond_init(&cnd);
    spawn(0, "A", cond_waiter, "A", 8);
    spawn(1, "B", cond_waiter, "B", 12);
    spawn(2, "signaller", cond_signaller, signaller_arg, 10);
    k_start();
}

static void test_cond_signal_wakes_most_urgent(void **state)
{
    (void)state;
    run_cond_waiters(NULL);
    /* B (more urgent) is woken; it needs the mutex, so it runs when the
     * signaller unlocks; A waits on. */
    assert_string_equal(trace, "BAsub");
    assert_int_equal(rc[1], K_OK);
    assert_int_equal(rc[5], 1);
    assert_int_equal(rc[3], K_OK);
    assert_int_equal(th[0].state, K_THREAD_BLOCKED);
}

static void test_cond_broadcast_wakes_all(void **state)
{
    (void)state;
    run_cond_waiters("all");
    assert_string_equal(trace, "BAsuba");
    assert_int_equal(rc[0], K_OK);
    assert_int_equal(rc[1], K_OK);
    assert_int_equal(rc[4], 1);
    assert_int_equal(rc[5], 1);
}

static void *cond_misuser(void *arg)
{
    struct k_timespec past = {0, 0}, bad = {0, 1000000000};
    (void)arg;
    rc[0] = k_cond_wait(&cnd, &mtx);            /* mutex not held */
    rc[1] = k_cond_wait(NULL, &mtx);
    rc[2] = k_cond_signal(NULL);
    k_mutex_lock(&mtx);
    rc[3] = k_cond_wait_ticks(&cnd, &mtx, 7);   /* nobody signals */
    when[3] = k_ticks();
    rc[4] = mtx.owner == k_thread_self();
    rc[5] = k_cond_timedwait(&cnd, &mtx, &past);
    rc[6] = k_cond_timedwait(&cnd, &mtx, &bad);
    rc[7] = mtx.owner == k_thread_self();
    k_mutex_unlock(&mtx);
    return NULL;
}

static void test_cond_errors_and_timeout(void **state)
{
    (void)state;
    k_mutex_init(&mtx);
    k_cond_init(&cnd);
    spawn(0, "misuser", cond_misuser, NULL, 10);
    k_start();
    assert_int_equal(rc[0], K_EPERM);
    assert_int_equal(rc[1], K_EINVAL);
    assert_int_equal(rc[2], K_EINVAL);
    assert_int_equal(rc[3], K_ETIMEDOUT);
    assert_int_equal(when[3], 7);
    assert_int_equal(rc[4], 1);
    assert_int_equal(rc[5], K_ETIMEDOUT);
    assert_int_equal(rc[6], K_EINVAL);
    assert_int_equal(rc[7], 1);
}

static void test_mq_full_empty_blocking(void **state)
{
    const uint32_t want[] = {0, 1, 2, 3, 10, 11, 12, 13, 14, 15};
    (void)state;
    ngot = 0;
    assert_int_equal(k_mq_init(&mq, mq_storage, sizeof(uint32_t), 4), K_OK);
    spawn(0, "producer", mq_producer, NULL, 10);
    spawn(1, "consumer", mq_consumer, NULL, 9);
    k_start();
    assert_int_equal(rc[0], K_OK);
    assert_int_equal(rc[1], K_EAGAIN);
    assert_int_equal(rc[2], K_ETIMEDOUT);
    assert_int_equal(when[2], 10);
    assert_int_equal(rc[3], K_OK);
    assert_int_equal(rc[4], K_EAGAIN);
    assert_int_equal(ngot, 10);
    assert_memory_equal(got, want, sizeof want);
    assert_int_equal(k_mq_init(&mq, NULL, 4, 4), K_EINVAL);
}

static void *mq_receiver_first(void *arg)
{
    uint32_t v = 0;
    (void)arg;
    rc[0] = k_mq_receive(&mq, &v);
    got[0] = v;
    rc[1] = k_mq_count(&mq);
    return NULL;
}

static void isr_sends(void *arg)
{
    uint32_t v = 0xC0FFEEu;
    int i;
    (void)arg;
    rc[2] = k_mq_send_ticks(&mq, &v, K_NO_WAIT);
    for (i = 0; i < 5; i++)
        rc[3] = k_mq_send_ticks(&mq, &v, K_NO_WAIT); /* fills up: the last fails */
    rc[4] = k_mq_send_ticks(&mq, &v, 5);             /* would wait in a handler */
}

static void *isr_sender(void *arg)
{
    (void)arg;
    host_raise_irq(80);
    return NULL;
}

static void test_mq_direct_handoff_and_isr(void **state)
{
    (void)state;
    k_mq_init(&mq, mq_storage, sizeof(uint32_t), 4);
    k_irq_register(80, 3, isr_sends, NULL);
    spawn(0, "rx", mq_receiver_first, NULL, 10);
    spawn(1, "isr", isr_sender, NULL, 5);
    k_start();
    assert_int_equal(rc[0], K_OK);
    assert_int_equal(got[0], 0xC0FFEEu);
    assert_int_equal(rc[1], 4);       /* four more were queued by the handler */
    assert_int_equal(rc[2], K_OK);
    assert_int_equal(rc[3], K_EAGAIN);
    assert_int_equal(rc[4], K_EISR);
}

/* ---- events ---- */

static struct k_event ev;
static uint32_t matched[4];
static void *ev_all(void *arg)
{
    (void)arg;
    rc[0] = k_event_wait(&ev, 0x3u, K_EVENT_ALL | K_EVENT_CLEAR, K_FOREVER, &matched[0]);
    mark('A');
    return NULL;
}

static void *ev_any(void *arg)
{
    (void)arg;
    rc[1] = k_event_wait(&ev, 0x6u, K_EVENT_ANY, K_FOREVER, &matched[1]);
    mark('Y');
    rc[2] = k_event_wait(&ev, 0x80u, K_EVENT_ANY, 7, &matched[2]);
    when[2] = k_ticks();
    return NULL;
}

static void *ev_setter(void *arg)
{
    (void)arg;
    mark('1');
    k_event_set(&ev, 0x1u);
    mark('2');
    k_event_set(&ev, 0x2u);
    mark('3');
    return NULL;
}

static void test_events(void **state)
{
    (void)state;
    k_event_init(&ev);
    spawn(0, "all", ev_all, NULL, 10);
    spawn(1, "any", ev_any, NULL, 10);
    spawn(2, "set", ev_setter, NULL, 5);
    k_start();
    assert_string_equal(trace, "12AY3");
    assert_int_equal(rc[0], K_OK);
    assert_int_equal(matched[0], 0x3u);
    /* 'all' cleared 0x3 when it woke, but 'any' was matched in the same set */
    assert_int_equal(rc[1], K_OK);
    assert_int_equal(matched[1], 0x2u);
    assert_int_equal(rc[2], K_ETIMEDOUT);
    assert_int_equal(ev.bits, 0u);
    assert_int_equal(k_event_wait(&ev, 0, 0, 0, NULL), K_EINVAL);
}

/* ---- join and exit ---- */

static void *returns_value(void *arg)
{
    k_sleep_ticks(3);
    return arg;
}

static void *joiner(void *arg)
{
    void *v = NULL;
    (void)arg;
    rc[0] = k_thread_join(&th[0], &v, K_FOREVER);
    got[0] = (uint32_t)(uintptr_t)v;
    rc[1] = k_thread_join(&th[1], NULL, K_FOREVER); /* self */
    rc[2] = k_thread_join(&th[0], &v, K_NO_WAIT);  /* already dead */
    return NULL;
}

static void test_join(void **state)
{
    (void)state;
    spawn(0, "child", returns_value, (void *)(uintptr_t)1234u, 5);
    spawn(1, "parent", joiner, NULL, 10);
    k_start();
    assert_int_equal(rc[0], K_OK);
    assert_int_equal(got[0], 1234u);
    assert_int_equal(rc[1], K_EDEADLK);
    assert_int_equal(rc[2], K_OK);
    assert_int_equal(th[0].state, K_THREAD_DEAD);
    /* a dead thread's slot may be reused */
    assert_int_equal(spawn(0, "again", noop, NULL, 5), K_OK);
}

/* ---- stack guard ---- */

static void *overflows(void *arg)
{
    (void)arg;
    mark('o');
    th[0].stack_base[1] = 0x12345678u; /* what a deep call chain would do */
    k_sched_yield();
    mark('X'); /* never: the thread is stopped at the switch */
    return NULL;
}

static void *survivor(void *arg)
{
    (void)arg;
    mark('s');
    rc[0] = k_thread_join(&th[0], NULL, K_FOREVER);
    return NULL;
}

static void test_stack_guard(void **state)
{
    (void)state;
    spawn(0, "overflower", overflows, NULL, 5);
    spawn(1, "survivor", survivor, NULL, 5);
    k_start();
    assert_string_equal(trace, "os");
    assert_ptr_equal(k_stack_overflowed(), &th[0]);
    assert_int_equal(k_stats.stack_overflows, 1);
    assert_int_equal(rc[0], K_ESTACK);
    assert_non_null(strstr(host_console, "stack overflow in thread 'overflower'"));
    {
        struct k_thread_info info[3];
        assert_int_equal(k_thread_list(info, 3), 3); /* survivor, overflower, idle */
        assert_string_equal(info[1].name, "overflower");
        assert_int_equal(info[1].stack_intact, 0);
        assert_int_equal(info[0].stack_intact, 1);
    }
}

/* A control block right below its thread's stack (as in struct k_bsched):
 * an overflow two words past the guard words breaks its canary. The kernel
 * must not go on with that block: it reports it and halts at the switch. */
static struct {
    struct k_thread t;
    uint32_t stack[K_STACK_WORDS(16384u)];
} victim;

static void *overflows_into_its_tcb(void *arg)
{
    unsigned i;
    (void)arg;
    for (i = 0; i < K_STACK_GUARD_WORDS; i++)
        victim.stack[i] = 0x0BADF00Du;
    ((volatile uint32_t *)victim.stack)[-1] = 0x0BADF00Du; /* the canary */
    mark('o');
    (void)k_sched_yield();
    mark('!'); /* never: the kernel halted */
    return NULL;
}

static void *bystander(void *arg)
{
    (void)arg;
    mark('b'); /* never: halted before it could run */
    return NULL;
}

static void test_tcb_overwrite_halts(void **state)
{
    int halted = host_halted;
    char expect[64];
    (void)state;
    assert_int_equal(k_thread_create(&victim.t, "victim", overflows_into_its_tcb, NULL,
                                     victim.stack, sizeof victim.stack, 5), K_OK);
    spawn(1, "bystander", bystander, NULL, 5);
    k_start();
    assert_int_equal(host_halted, halted + 1);
    assert_string_equal(trace, "o");
    snprintf(expect, sizeof expect, "control block of the thread at 0x%08lx overwritten",
             (unsigned long)(uint32_t)(uintptr_t)&victim.t);
    assert_non_null(strstr(host_console, expect));
    assert_non_null(strstr(host_console, "halted"));
}

static int listed;
static void *lists_threads(void *arg)
{
    struct k_thread_info info[4];
    (void)arg;
    listed = k_thread_list(info, 4);
    mark('l'); /* never: the list runs through the broken block */
    return NULL;
}

/* The same breakage found by k_thread_list (the shell's ps). */
static void test_tcb_overwrite_found_by_thread_list(void **state)
{
    struct k_thread_info info[4];
    int halted = host_halted;
    (void)state;
    assert_int_equal(k_thread_create(&victim.t, "victim", noop, NULL, victim.stack,
                                     sizeof victim.stack, 5), K_OK);
    assert_int_equal(k_thread_list(info, 4), 2);
    victim.t.canary ^= 1u;
    spawn(0, "lister", lists_threads, NULL, 6);
    k_start();
    assert_int_equal(host_halted, halted + 1);
    assert_non_null(strstr(host_console, "overwritten"));
    assert_string_equal(trace, "");
}

/* ---- introspection: k_thread_list ---- */

#define DEEP_BYTES 8192u
static struct k_thread_info seen[4];
static int seen_count;

static void *deep_lister(void *arg)
{
    volatile uint8_t deep[DEEP_BYTES];   /* puts the high-water mark below 8 KiB */
    size_t i;
    (void)arg;
    for (i = 0; i < sizeof deep; i++)
        deep[i] = (uint8_t)i;
    seen_count = k_thread_list(seen, 4);
    return NULL;
}

static void *short_sleeper(void *arg)
{
    (void)arg;
    return (void *)(intptr_t)k_sleep_ticks(5);
}

static void test_thread_list(void **state)
{
    struct k_thread_info after[3], one;
    (void)state;
    assert_int_equal(k_thread_list(NULL, 0), 1); /* the idle thread alone */
    assert_int_equal(k_thread_list(NULL, 1), K_EINVAL);
    spawn(1, "sleeper", short_sleeper, NULL, 6);  /* runs first, then blocks */
    spawn(0, "lister", deep_lister, NULL, 5);
    k_start();
    assert_int_equal(seen_count, 3);
    /* most recently created first: lister, sleeper, idle */
    assert_string_equal(seen[0].name, "lister");
    assert_int_equal(seen[0].prio, 5);
    assert_int_equal(seen[0].base_prio, 5);
    assert_int_equal(seen[0].state, K_THREAD_READY);
    assert_int_equal(seen[0].is_current, 1);
    assert_int_equal(seen[0].stack_bytes, STACK_BYTES);
    assert_true(seen[0].stack_used >= DEEP_BYTES);
    assert_true(seen[0].stack_used < STACK_BYTES);
    assert_string_equal(seen[1].name, "sleeper");
    assert_int_equal(seen[1].state, K_THREAD_BLOCKED);
    assert_int_equal(seen[1].is_current, 0);
    assert_int_equal(seen[1].prio, 6);
    assert_true(seen[1].stack_used > 0u);
    assert_true(seen[1].stack_used < seen[0].stack_used);
    assert_string_equal(seen[2].name, "idle");
    assert_int_equal(seen[2].prio, K_PRIO_IDLE);
    assert_int_equal(seen[2].stack_bytes, K_IDLE_STACK_BYTES);
    /* after the run both have exited; max = 1 writes only the first entry */
    assert_int_equal(k_thread_list(after, 3), 3);
    assert_int_equal(after[0].state, K_THREAD_DEAD);
    assert_int_equal(after[1].state, K_THREAD_DEAD);
    assert_int_equal(after[1].switches_in, 2); /* started, then woken once */
    memset(&one, 0xA5, sizeof one);
    assert_int_equal(k_thread_list(&one, 1), 3);
    assert_string_equal(one.name, "lister");
}

/* ---- the B-scheduler thread's timing, on a fake counter ---- */

/* Every read of the fake counter advances it by one count; a process body
 * advances it by the work it stands for. So a call of a process that does
 * W counts of work measures exactly W + 1 (the end read), and a release
 * measures exactly 1: the tick hook's stamp, then the first process's start, with
 * nothing read between. */
static uint32_t fake_counter;
static uint32_t fake_reads;

static uint32_t fake_read(void)
{
    fake_reads++;
    return ++fake_counter;
}

/* ---- the B-scheduler thread ---- */

static struct bsched bs;
static struct k_bsched kb;
static uint32_t runs_of[4];
static k_ticks_t first_run_tick[4];

static void process(void *context, uint16_t index)
{
    (void)context;
    if (runs_of[index]++ == 0u)
        first_run_tick[index] = k_ticks();
    /* process 3 is slow once: it takes 9 ticks in its second run */
    if (index == 3u && runs_of[3] == 2u) {
        int i;
        for (i = 0; i < 9; i++)
            host_tick();
    }
}

static void test_bsched_thread_and_overrun(void **state)
{
    const uint8_t pv[] = {0, 1, 2, 3};
    (void)state;
    memset(runs_of, 0, sizeof runs_of);
    assert_int_equal(bsched_init(&bs, pv, 4), BSCHED_OK);
    kb.stop_after = 64;
    kb.measure = 0;
    assert_int_equal(k_bsched_start(&kb, &bs, process, NULL, 4, stacks[0], STACK_BYTES), K_OK);
    assert_int_equal(k_bsched_start(&kb, &bs, process, NULL, 0, stacks[0], STACK_BYTES), K_EINVAL);
    k_start();
    assert_int_equal(kb.cycles_run, 64);
    assert_int_equal(kb.thread.prio, K_PRIO_APP_MAX);
    /* pv 0 runs every cycle, pv 1 every 2nd ... */
    assert_int_equal(runs_of[0], 64);
    assert_int_equal(runs_of[1], 32);
    assert_int_equal(runs_of[2], 16);
    assert_int_equal(runs_of[3], 8);
    /* the 9-tick run overlapped the next two releases (period 4) */
    assert_int_equal(kb.overrun_events, 1);
    assert_int_equal(kb.overruns, 2);
    assert_true(kb.max_cycle_ticks >= 9u);
    assert_non_null(strstr(host_console, "bsched: overrun in minor cycle"));
    /* announced at the successor's release, while the slow cycle still ran,
     * by the reporter: nothing is written from the tick */
    assert_int_equal(kb.stuck_reports, 1);
    assert_non_null(strstr(host_console, "still running at its successor's release"));
    assert_int_equal(host_console_writes_in_isr, 0);
    assert_null(k_tick_hook); /* unhooked when the thread stopped */
    assert_int_equal(first_run_tick[0], 1);
}

/* Every cycle takes 2 ticks with a 1-tick period: continuous overrun. */
static void slow_process(void *context, uint16_t index)
{
    (void)context;
    runs_of[index]++;
    host_tick();
    host_tick();
}

static void test_bsched_reports_rate_limited(void **state)
{
    const uint8_t pv[] = {0};
    uint32_t bursts;
    (void)state;
    memset(runs_of, 0, sizeof runs_of);
    assert_int_equal(bsched_init(&bs, pv, 1), BSCHED_OK);
    kb.stop_after = 3000;
    kb.measure = 0;
    assert_int_equal(k_bsched_start(&kb, &bs, slow_process, NULL, 1, stacks[0], STACK_BYTES), K_OK);
    k_start();
    assert_int_equal(kb.cycles_run, 3000);
    assert_int_equal(kb.overrun_events, 3000);   /* every cycle overran */
    assert_int_equal(kb.stuck_reports, 3000);    /* and was noticed from the tick */
    /* one burst (at most two lines) per interval, plus the final one */
    bursts = k_ticks() / K_BSCHED_REPORT_INTERVAL_TICKS + 2u;
    assert_true(k_ticks() >= 3u * 3000u);
    assert_true(kb.report_lines >= 2u);
    assert_true(kb.report_lines <= 2u * bursts);
    /* the last line has the final totals: nothing was lost, only summed */
    assert_non_null(strstr(host_console, "overruns in 3000 cycles so far"));
    assert_int_equal(kb.reporter.base_prio, K_PRIO_APP_MAX - 1u); /* the loan ended */
    assert_int_equal(host_console_writes_in_isr, 0);
}

static void quick_process(void *context, uint16_t index)
{
    (void)context;
    runs_of[index]++;
}

static void test_bsched_thread_no_overrun_when_fast(void **state)
{
    const uint8_t pv[] = {1, 1};
    (void)state;
    memset(runs_of, 0, sizeof runs_of);
    assert_int_equal(bsched_init(&bs, pv, 2), BSCHED_OK);
    kb.stop_after = 100;
    kb.measure = 0; /* timing off: the counter is never read, nothing recorded */
    fake_reads = 0;
    k_timestamp_register(fake_read, 1000000u, NULL);
    assert_int_equal(k_bsched_start(&kb, &bs, quick_process, NULL, 1, stacks[0], STACK_BYTES), K_OK);
    k_start();
    assert_int_equal(fake_reads, 0);
    assert_int_equal(k_timestamp_hz(), K_TICK_HZ); /* nobody started the counter */
    assert_int_equal(kb.exec[0].runs, 0);
    assert_int_equal(kb.jitter_samples, 0);
    assert_int_equal(kb.cycles_run, 100);
    assert_int_equal(kb.overruns, 0);
    assert_int_equal(runs_of[0] + runs_of[1], 100); /* one of the two each cycle */
    assert_int_equal(runs_of[0], 50);
    assert_int_equal(k_ticks(), 100);
    assert_null(strstr(host_console, "overrun"));
    assert_null(strstr(host_console, "still running"));
    assert_int_equal(kb.stuck_reports, 0);
}

/* Work per call: process 0 does 10 counts, process 1 250 (700 in its 5th
 * call), process 2 3000, spread over two ticks. */
static void timed_process(void *context, uint16_t index)
{
    (void)context;
    runs_of[index]++;
    if (index == 0u) {
        fake_counter += 10u;
    } else if (index == 1u) {
        fake_counter += runs_of[1] == 5u ? 700u : 250u;
    } else {
        fake_counter += 1000u;
        host_tick();
        fake_counter += 2000u;
    }
}

static void test_bsched_records_execution_times_and_jitter(void **state)
{
    const uint8_t pv[] = {0, 1, 3};
    uint32_t worst = 0, runs = 0, jmin = 9, jmax = 9, jmean = 9, samples = 0;
    (void)state;
    memset(runs_of, 0, sizeof runs_of);
    fake_counter = 0xFFFFF000u; /* wraps during the run: differences still hold */
    fake_reads = 0;
    k_timestamp_register(fake_read, 1000000u, NULL);
    assert_int_equal(k_timestamp_hz(), K_TICK_HZ); /* registered, not started */
    assert_int_equal(fake_reads, 0);
    assert_int_equal(bsched_init(&bs, pv, 3), BSCHED_OK);
    kb.stop_after = 32;
    kb.measure = 1;
    assert_int_equal(k_bsched_start(&kb, &bs, timed_process, NULL, 4, stacks[0], STACK_BYTES), K_OK);
    assert_int_equal(k_timestamp_hz(), 1000000u); /* a measuring thread started it */
    /* before the first cycle: nothing measured, but readable */
    assert_int_equal(k_bsched_wcet(&kb, 1, &worst, &runs), K_OK);
    assert_int_equal(worst, 0);
    assert_int_equal(runs, 0);
    k_start();
    assert_int_equal(kb.cycles_run, 32);
    assert_int_equal(kb.overruns, 0);
    assert_int_equal(k_bsched_wcet(&kb, 0, &worst, &runs), K_OK);
    assert_int_equal(worst, 11);
    assert_int_equal(runs, 32);
    assert_int_equal(k_bsched_wcet(&kb, 1, &worst, &runs), K_OK);
    assert_int_equal(worst, 701);
    assert_int_equal(runs, 16);
    /* the tick inside process 2 reads nothing: only a release's tick is stamped */
    assert_int_equal(k_bsched_wcet(&kb, 2, &worst, &runs), K_OK);
    assert_int_equal(worst, 3001);
    assert_int_equal(runs, 4);
    assert_int_equal(runs_of[2], 4);
    /* every cycle runs process 0: one sample each, all exactly one read */
    assert_int_equal(k_bsched_jitter(&kb, &jmin, &jmax, &jmean, &samples), K_OK);
    assert_int_equal(samples, 32);
    assert_int_equal(jmin, 1);
    assert_int_equal(jmax, 1);
    assert_int_equal(jmean, 1);
    /* NULL pointers are allowed; bad index and instance are not */
    assert_int_equal(k_bsched_wcet(&kb, 2, NULL, NULL), K_OK);
    assert_int_equal(k_bsched_jitter(&kb, NULL, NULL, NULL, NULL), K_OK);
    assert_int_equal(k_bsched_wcet(&kb, 3, &worst, &runs), K_EINVAL);
    assert_int_equal(k_bsched_wcet(NULL, 0, &worst, &runs), K_EINVAL);
    assert_int_equal(k_bsched_jitter(NULL, &jmin, NULL, NULL, NULL), K_EINVAL);
    /* the stamping ended with the thread: ticks after it read nothing */
    assert_null(k_tick_hook);
    {
        uint32_t reads = fake_reads;
        host_tick();
        assert_int_equal(fake_reads, reads);
    }
}

/* A more urgent thread holds the CPU for 400 counts at the releases of
 * ticks 1, 9, 17 and 25: the jitter of those cycles is 401, the others' 1. */
static void *release_hog(void *arg)
{
    k_ticks_t next = 1u;
    int i;
    (void)arg;
    for (i = 0; i < 4; i++) {
        (void)k_sleep_until(next);
        fake_counter += 400u;
        next += 8u;
    }
    return NULL;
}

static void test_bsched_jitter_counts_a_late_start(void **state)
{
    const uint8_t pv[] = {0};
    uint32_t jmin = 0, jmax = 0, jmean = 0, samples = 0;
    (void)state;
    memset(runs_of, 0, sizeof runs_of);
    fake_counter = 0;
    k_timestamp_register(fake_read, 1000000u, NULL);
    assert_int_equal(bsched_init(&bs, pv, 1), BSCHED_OK);
    kb.stop_after = 32;
    kb.measure = 1;
    assert_int_equal(k_thread_create(&th[0], "hog", release_hog, NULL, stacks[1], STACK_BYTES,
                                     K_PRIO_APP_MAX + 2u), K_OK);
    assert_int_equal(k_bsched_start(&kb, &bs, quick_process, NULL, 1, stacks[0], STACK_BYTES), K_OK);
    k_start();
    assert_int_equal(kb.cycles_run, 32);
    assert_int_equal(runs_of[0], 32);
    assert_int_equal(k_bsched_jitter(&kb, &jmin, &jmax, &jmean, &samples), K_OK);
    assert_int_equal(samples, 32);
    assert_int_equal(jmin, 1);
    assert_int_equal(jmax, 401);
    /* releases at ticks 1..32, the hog at 4 of them: (4 x 401 + 28 x 1) / 32 */
    assert_int_equal(jmean, 51);
}

/* The mean over a sum beyond 32 bits (the division is the kernel's own). */
static void test_bsched_jitter_mean_of_a_large_sum(void **state)
{
    uint32_t jmean = 0, samples = 0;
    (void)state;
    memset(&kb, 0, sizeof kb);
    kb.jitter_samples = 3u;
    kb.jitter_sum_hi = 2u;          /* 0x2_0000_0001 = 8589934593 */
    kb.jitter_sum_lo = 1u;
    assert_int_equal(k_bsched_jitter(&kb, NULL, NULL, &jmean, &samples), K_OK);
    assert_int_equal(jmean, 2863311531u);
    assert_int_equal(samples, 3);
    kb.jitter_samples = 2u;         /* a quotient above 32 bits saturates */
    assert_int_equal(k_bsched_jitter(&kb, NULL, NULL, &jmean, NULL), K_OK);
    assert_int_equal(jmean, 0xFFFFFFFFu);
    kb.jitter_samples = 7u;
    kb.jitter_sum_hi = 6u;
    kb.jitter_sum_lo = 0xFFFFFFFFu; /* 0x6_FFFF_FFFF / 7 = 4294967295.86: the largest that fits */
    assert_int_equal(k_bsched_jitter(&kb, NULL, NULL, &jmean, NULL), K_OK);
    assert_int_equal(jmean, 0xFFFFFFFFu);
}

/* No counter registered: the same records come in whole ticks. */
static void three_tick_process(void *context, uint16_t index)
{
    (void)context;
    runs_of[index]++;
    if (index == 1u) {
        host_tick();
        host_tick();
        host_tick();
    }
}

static void test_bsched_timing_in_ticks_without_a_counter(void **state)
{
    const uint8_t pv[] = {0, 1};
    uint32_t worst = 9, runs = 0, jmax = 9, samples = 0;
    (void)state;
    memset(runs_of, 0, sizeof runs_of);
    k_timestamp_register(fake_read, 0u, NULL); /* no rate: not registered */
    assert_int_equal(k_timestamp_start(), K_EINVAL);
    assert_int_equal(k_timestamp_hz(), K_TICK_HZ);
    assert_int_equal(k_timestamp(), k_ticks());
    assert_int_equal(bsched_init(&bs, pv, 2), BSCHED_OK);
    kb.stop_after = 8;
    kb.measure = 1;
    assert_int_equal(k_bsched_start(&kb, &bs, three_tick_process, NULL, 4, stacks[0], STACK_BYTES), K_OK);
    k_start();
    assert_int_equal(k_bsched_wcet(&kb, 0, &worst, &runs), K_OK);
    assert_int_equal(worst, 0);
    assert_int_equal(runs, 8);
    assert_int_equal(k_bsched_wcet(&kb, 1, &worst, &runs), K_OK);
    assert_int_equal(worst, 3);
    assert_int_equal(runs, 4);
    assert_int_equal(k_bsched_jitter(&kb, NULL, &jmax, NULL, &samples), K_OK);
    assert_int_equal(samples, 8);
    assert_int_equal(jmax, 0);
}

/* A board's start that fails (its hardware is in use), then one that works. */
static int fake_start_result;
static unsigned fake_starts;

static int fake_start(void)
{
    fake_starts++;
    return fake_start_result;
}

static void test_timestamp_starts_once_and_only_when_asked(void **state)
{
    (void)state;
    fake_reads = 0;
    fake_starts = 0;
    fake_start_result = K_EBUSY;
    k_timestamp_register(fake_read, 1000000u, fake_start);
    assert_int_equal(fake_starts, 0); /* registering starts nothing */
    assert_int_equal(k_timestamp(), k_ticks());
    assert_int_equal(k_timestamp_start(), K_EBUSY);
    assert_int_equal(k_timestamp_start(), K_EBUSY); /* the first result, not a second try */
    assert_int_equal(fake_starts, 1);
    assert_int_equal(k_timestamp_hz(), K_TICK_HZ);
    assert_int_equal(k_timestamp(), k_ticks());
    assert_int_equal(fake_reads, 0);
    fake_start_result = K_OK;
    k_timestamp_register(fake_read, 1000000u, fake_start); /* registering again: unstarted */
    assert_int_equal(k_timestamp_hz(), K_TICK_HZ);
    assert_int_equal(k_timestamp_start(), K_OK);
    assert_int_equal(fake_starts, 2);
    assert_int_equal(k_timestamp_hz(), 1000000u);
    fake_counter = 41;
    assert_int_equal(k_timestamp(), 42);
    k_init(); /* forgets it */
    assert_int_equal(k_timestamp_hz(), K_TICK_HZ);
    assert_int_equal(k_timestamp_start(), K_EINVAL);
}

int main(void)
{
#define T(name) cmocka_unit_test_setup(name, setup)
    const struct CMUnitTest tests[] = {
        T(test_create_rejects_bad_arguments),
        T(test_priority_order),
        T(test_create_preempts),
        T(test_timeslice_round_robin),
        T(test_timeslice_none_is_fifo),
        T(test_preemption_of_busy_thread),
        T(test_setprio_preempts),
        T(test_yield_round_robin),
        T(test_sleep_until_no_drift),
        T(test_nanosleep_and_clock),
        T(test_clock_nanosleep_absolute),
        T(test_sem_timeout),
        T(test_sem_handoff_order),
        T(test_sem_timedwait_absolute),
        T(test_sem_timedwait_absolute_whole_ticks),
        T(test_irq_wakes_thread),
        T(test_mutex_owner_checks),
        T(test_priority_inheritance),
        T(test_priority_inheritance_chain_and_timeout),
        T(test_mutex_owner_dies),
        T(test_cond_signal_wakes_most_urgent),
        T(test_cond_broadcast_wakes_all),
        T(test_cond_errors_and_timeout),
        T(test_mq_full_empty_blocking),
        T(test_mq_direct_handoff_and_isr),
        T(test_events),
        T(test_join),
        T(test_stack_guard),
        T(test_tcb_overwrite_halts),
        T(test_tcb_overwrite_found_by_thread_list),
        T(test_thread_list),
        T(test_bsched_thread_and_overrun),
        T(test_bsched_thread_no_overrun_when_fast),
        T(test_bsched_records_execution_times_and_jitter),
        T(test_bsched_jitter_counts_a_late_start),
        T(test_bsched_jitter_mean_of_a_large_sum),
        T(test_bsched_timing_in_ticks_without_a_counter),
        T(test_timestamp_starts_once_and_only_when_asked),
        T(test_bsched_reports_rate_limited),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
