/*
 * Target test images of the nanokernel: one source, one image per test
 * mode (-DKTEST_MODE=<n>, see ktest_modes below), booted on the emulated
 * RoboCube by test_kernel_target.py. Each image prints
 *   KTEST <mode> START
 *   KTEST <key>=<value> ...        measured facts the pytest checks itself
 *   KTEST RESULT PASS | KTEST RESULT FAIL <why>
 * on the console (DUART B) and then idles.
 */
#include "kernel.h"
#include "k_bsched.h"
#include "k_board.h"
#include "bsched.h"

#ifndef KTEST_MODE
#error "build with -DKTEST_MODE=n"
#endif

#define KTEST_PREEMPT    1
#define KTEST_PRIORITY   2
#define KTEST_SEMAPHORE  3
#define KTEST_INHERIT    4
#define KTEST_QUEUE      5
#define KTEST_DRIFT      6
#define KTEST_OVERRUN    7
#define KTEST_STACKGUARD 8
#define KTEST_BADUSE     9
#define KTEST_MEASURE   10
#define KTEST_OVERLOAD  11
#define KTEST_TCBGUARD  12
#define KTEST_NESTING   13
#define KTEST_TIMING    14

#define STACK_BYTES 2048u
K_STACK_DEFINE(stack_main, STACK_BYTES);
/* Not every mode needs every thread. */
__attribute__((unused)) K_STACK_DEFINE(stack_a, STACK_BYTES);
__attribute__((unused)) K_STACK_DEFINE(stack_b, STACK_BYTES);
__attribute__((unused)) K_STACK_DEFINE(stack_c, STACK_BYTES);
__attribute__((unused)) static struct k_thread t_a, t_b, t_c;
static struct k_thread t_main;
static int failed;

__attribute__((unused)) static void check(int ok, const char *what)
{
    if (!ok && !failed) {
        failed = 1;
        k_printf("KTEST RESULT FAIL %s\n", what);
    }
}

__attribute__((unused)) static void finish(void)
{
    if (!failed)
        k_printf("KTEST RESULT PASS\n");
}

/* ------------------------------------------------------------------ */
/* Bytes of its stack the thread on `stack` has used (0 if none runs on it). */
__attribute__((unused)) static uint32_t stack_used_on(const void *stack)
{
    struct k_thread_info info[8];
    int i, n = k_thread_list(info, 8);
    for (i = 0; i < n && i < 8; i++)
        if (info[i].stack_base == stack)
            return info[i].stack_used;
    return 0;
}

#if KTEST_MODE == KTEST_PREEMPT
/* Two threads at one priority spin without ever yielding; a more urgent
 * thread sleeps. Only the PIT tick can take the CPU from a spinner. */
static volatile uint32_t spins[2];
static volatile int stop_spinning;

static void *spinner(void *arg)
{
    volatile uint32_t *count = arg;
    while (!stop_spinning)
        (*count)++;
    return NULL;
}

static void *controller(void *arg)
{
    k_ticks_t t0, woke;
    uint32_t s0, s1, switches;
    (void)arg;
    k_thread_create(&t_a, "spin-a", spinner, (void *)&spins[0], stack_a, STACK_BYTES, 5);
    k_thread_create(&t_b, "spin-b", spinner, (void *)&spins[1], stack_b, STACK_BYTES, 5);
    t0 = k_ticks();
    k_sleep_ticks(200);
    woke = k_ticks();
    s0 = spins[0];
    s1 = spins[1];
    switches = t_a.switches_in + t_b.switches_in;
    stop_spinning = 1;
    k_thread_join(&t_a, NULL, K_FOREVER);
    k_thread_join(&t_b, NULL, K_FOREVER);
    k_printf("KTEST slept=%lu spins_a=%lu spins_b=%lu spinner_switches=%lu\n",
             (unsigned long)(woke - t0), (unsigned long)s0, (unsigned long)s1,
             (unsigned long)switches);
    check(woke - t0 == 200u, "sleeper woke late although spinners never yield");
    check(s0 > 0u && s1 > 0u, "a spinner never ran: no round robin");
    /* 200 ticks / 10-tick slices: about 20 turns in all */
    check(switches >= 15u, "too few slice switches between the spinners");
    finish();
    return NULL;
}

/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_PRIORITY
static char order[8];
static unsigned norder;

static void *recorder(void *arg)
{
    order[norder++] = *(const char *)arg;
    return NULL;
}

static void *controller(void *arg)
{
    (void)arg;
    /* created from the most urgent thread: none runs until it blocks */
    k_thread_create(&t_a, "low", recorder, "L", stack_a, STACK_BYTES, 3);
    k_thread_create(&t_b, "high", recorder, "H", stack_b, STACK_BYTES, 20);
    k_thread_create(&t_c, "mid", recorder, "M", stack_c, STACK_BYTES, 10);
    check(norder == 0u, "a less urgent thread ran before the creator blocked");
    k_thread_join(&t_a, NULL, K_FOREVER);
    order[norder] = '\0';
    k_printf("KTEST order=%s\n", order);
    check(norder == 3u && order[0] == 'H' && order[1] == 'M' && order[2] == 'L',
          "threads ran out of priority order");
    finish();
    return NULL;
}

/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_SEMAPHORE
static struct k_sem sem;
static volatile k_ticks_t posted_at, got_at;

static void *poster(void *arg)
{
    (void)arg;
    k_sleep_ticks(30);
    posted_at = k_ticks();
    k_sem_post(&sem);
    return NULL;
}

static void *controller(void *arg)
{
    k_ticks_t t0, t1;
    int r1, r2, r3;
    struct k_timespec abs;
    (void)arg;
    k_sem_init(&sem, 0, 4);
    t0 = k_ticks();
    r1 = k_sem_wait_ticks(&sem, 100);
    t1 = k_ticks();
    k_printf("KTEST timeout_rc=%d timeout_waited=%lu\n", r1, (unsigned long)(t1 - t0));
    check(r1 == K_ETIMEDOUT && t1 - t0 == 100u, "relative timeout");
    k_clock_gettime(K_CLOCK_MONOTONIC, &abs);
    abs.tv_sec += 1;
    t0 = k_ticks();
    r2 = k_sem_timedwait(&sem, &abs);
    t1 = k_ticks();
    k_printf("KTEST timedwait_rc=%d timedwait_waited=%lu\n", r2, (unsigned long)(t1 - t0));
    /* the deadline is the tick of clock_gettime + 1024; a tick may fall
     * between clock_gettime and t0 */
    check(r2 == K_ETIMEDOUT && t1 - t0 >= 1023u && t1 - t0 <= 1024u, "absolute timeout");
    k_thread_create(&t_a, "poster", poster, NULL, stack_a, STACK_BYTES, 5);
    r3 = k_sem_wait_ticks(&sem, 1000);
    got_at = k_ticks();
    k_printf("KTEST post_rc=%d latency=%lu\n", r3, (unsigned long)(got_at - posted_at));
    check(r3 == K_OK && got_at == posted_at, "post did not wake the waiter in the same tick");
    check(k_sem_trywait(&sem) == K_EAGAIN, "trywait on zero");
    finish();
    return NULL;
}

/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_INHERIT
/* Priority inversion: low holds the mutex, high waits for it, medium
 * spins for 300 ticks. With inheritance low finishes its 5-tick critical
 * section at high's priority and high gets the mutex long before medium
 * lets go of the CPU. */
static struct k_mutex mtx;
static volatile k_ticks_t high_got, medium_done;
static volatile uint8_t low_prio_inside;

static void busy_ticks(k_ticks_t n)
{
    k_ticks_t end = k_ticks() + n;
    while (k_tick_before(k_ticks(), end)) {
    }
}

static void *low(void *arg)
{
    (void)arg;
    k_mutex_lock(&mtx);
    k_sleep_ticks(10);              /* let high and medium start */
    busy_ticks(5);
    low_prio_inside = t_a.prio;
    k_mutex_unlock(&mtx);
    return NULL;
}

static void *high(void *arg)
{
    (void)arg;
    k_sleep_ticks(2);
    k_mutex_lock(&mtx);
    high_got = k_ticks();
    k_mutex_unlock(&mtx);
    return NULL;
}

static void *medium(void *arg)
{
    (void)arg;
    k_sleep_ticks(5);
    busy_ticks(300);
    medium_done = k_ticks();
    return NULL;
}

static void *controller(void *arg)
{
    (void)arg;
    k_mutex_init(&mtx);
    k_thread_create(&t_a, "low", low, NULL, stack_a, STACK_BYTES, 3);
    k_thread_create(&t_b, "high", high, NULL, stack_b, STACK_BYTES, 20);
    k_thread_create(&t_c, "medium", medium, NULL, stack_c, STACK_BYTES, 10);
    k_thread_join(&t_b, NULL, K_FOREVER);
    k_thread_join(&t_c, NULL, K_FOREVER);
    k_thread_join(&t_a, NULL, K_FOREVER);
    k_printf("KTEST high_got=%lu medium_done=%lu low_prio_inside=%u low_prio_after=%u\n",
             (unsigned long)high_got, (unsigned long)medium_done, low_prio_inside, t_a.prio);
    check(low_prio_inside == 20u, "holder did not inherit the waiter's priority");
    check(k_tick_before(high_got, medium_done), "high waited for medium: inversion");
    check(t_a.prio == 3u, "holder kept the boost after unlocking");
    finish();
    return NULL;
}

/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_QUEUE
struct msg {
    uint32_t seq;
    uint32_t check;
};
static struct k_mq mq;
static struct msg mq_storage[8];
#define NMSG 2000u
static volatile uint32_t bad_msgs, received;

static void *producer(void *arg)
{
    uint32_t i;
    (void)arg;
    for (i = 0; i < NMSG; i++) {
        struct msg m;
        m.seq = i;
        m.check = ~i * 2654435761u;
        k_mq_send(&mq, &m);
        if (i % 97u == 0u)
            k_sleep_ticks(1); /* let the queue run empty now and then */
    }
    return NULL;
}

static void *consumer(void *arg)
{
    uint32_t i;
    (void)arg;
    for (i = 0; i < NMSG; i++) {
        struct msg m;
        if (k_mq_receive_ticks(&mq, &m, 1000) != K_OK)
            break;
        if (m.seq != i || m.check != ~i * 2654435761u)
            bad_msgs++;
        received++;
        if (i % 50u == 0u)
            k_sleep_ticks(1); /* and full now and then */
    }
    return NULL;
}

static void *controller(void *arg)
{
    struct msg m = {1, 2};
    int i, r_full, r_empty, r_timed;
    k_ticks_t t0, waited;
    (void)arg;
    k_mq_init(&mq, mq_storage, sizeof(struct msg), 8);
    r_empty = k_mq_receive_ticks(&mq, &m, K_NO_WAIT);
    for (i = 0; i < 8; i++)
        k_mq_send_ticks(&mq, &m, K_NO_WAIT);
    r_full = k_mq_send_ticks(&mq, &m, K_NO_WAIT);
    t0 = k_ticks();
    r_timed = k_mq_send_ticks(&mq, &m, 25);
    waited = k_ticks() - t0;
    k_printf("KTEST empty_rc=%d full_rc=%d timed_full_rc=%d waited=%lu count=%d\n", r_empty,
             r_full, r_timed, (unsigned long)waited, k_mq_count(&mq));
    check(r_empty == K_EAGAIN && r_full == K_EAGAIN, "non-blocking empty/full");
    check(r_timed == K_ETIMEDOUT && waited == 25u, "timed send on a full queue");
    while (k_mq_receive_ticks(&mq, &m, K_NO_WAIT) == K_OK) {
    }
    k_thread_create(&t_a, "producer", producer, NULL, stack_a, STACK_BYTES, 8);
    k_thread_create(&t_b, "consumer", consumer, NULL, stack_b, STACK_BYTES, 7);
    k_thread_join(&t_a, NULL, K_FOREVER);
    k_thread_join(&t_b, NULL, K_FOREVER);
    k_printf("KTEST received=%lu bad=%lu\n", (unsigned long)received, (unsigned long)bad_msgs);
    check(received == NMSG && bad_msgs == 0u, "messages lost, reordered or damaged");
    finish();
    return NULL;
}

/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_DRIFT
/* A periodic thread (period 1 tick) for 10 000 ticks with a busy thread
 * below it: every release must come at its exact tick. */
#define DRIFT_PERIODS 10000u
static volatile int stop_load;
static void *load(void *arg)
{
    volatile uint32_t n = 0;
    (void)arg;
    while (!stop_load)
        n++;
    return NULL;
}

static void *controller(void *arg)
{
    k_ticks_t start, end, next, late, max_late = 0;
    uint32_t i, late_count = 0;
    struct k_timespec t0, t1;
    (void)arg;
    k_thread_create(&t_a, "load", load, NULL, stack_a, STACK_BYTES, 5);
    k_sleep_ticks(1);
    start = k_ticks();
    k_clock_gettime(K_CLOCK_MONOTONIC, &t0);
    next = start;
    for (i = 0; i < DRIFT_PERIODS; i++) {
        next += 1u;
        k_sleep_until(next);
        late = k_ticks() - next;
        if (late != 0u)
            late_count++;
        if (late > max_late)
            max_late = late;
    }
    end = k_ticks();
    k_clock_gettime(K_CLOCK_MONOTONIC, &t1);
    stop_load = 1;
    k_printf("KTEST periods=%lu elapsed=%lu late=%lu max_late=%lu clock_us=%ld\n",
             (unsigned long)DRIFT_PERIODS, (unsigned long)(end - start),
             (unsigned long)late_count, (unsigned long)max_late,
             (long)((t1.tv_sec - t0.tv_sec) * 1000000L + (t1.tv_nsec - t0.tv_nsec) / 1000L));
    check(end - start == DRIFT_PERIODS, "drift: elapsed ticks differ from periods");
    check(max_late == 0u, "a release came late");
    finish();
    return NULL;
}

/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_OVERRUN
/* bsched with period 2 ticks; process 1 (pv 2) is slow in its 3rd run:
 * busy for 5 ticks, which overlaps the next releases. */
static struct bsched bs;
static struct k_bsched kb;
static uint32_t runs[2];

static void process(void *context, uint16_t index)
{
    (void)context;
    runs[index]++;
    if (index == 1u && runs[1] == 3u) {
        k_ticks_t end = k_ticks() + 5u;
        while (k_tick_before(k_ticks(), end)) {
        }
    }
}

static void *controller(void *arg)
{
    static const uint8_t pv[] = {0, 2};
    (void)arg;
    bsched_init(&bs, pv, 2);
    kb.stop_after = 40;
    k_bsched_start(&kb, &bs, process, NULL, 2, stack_a, STACK_BYTES);
    k_thread_join(&kb.thread, NULL, K_FOREVER);
    k_printf("KTEST cycles=%lu overruns=%lu overrun_events=%lu stuck_reports=%lu max_cycle_ticks=%lu runs0=%lu runs1=%lu\n",
             (unsigned long)kb.cycles_run, (unsigned long)kb.overruns,
             (unsigned long)kb.overrun_events, (unsigned long)kb.stuck_reports,
             (unsigned long)kb.max_cycle_ticks,
             (unsigned long)runs[0], (unsigned long)runs[1]);
    check(kb.overrun_events == 1u, "exactly one cycle overran");
    check(kb.stuck_reports == 1u, "the late cycle was not announced at its successor's release");
    check(kb.overruns >= 2u, "the 5-tick cycle must miss at least two 2-tick releases");
    check(kb.cycles_run == 40u && runs[0] == 40u && runs[1] == 10u, "cycle accounting");
    finish();
    return NULL;
}

/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_STACKGUARD
/* A thread recurses until its stack runs into the guard words; the check
 * at its next switch stops it and names it; the system carries on. The
 * check runs at switches, so the overflowing frame may reach a little
 * below the guard: a pad below the stack takes that in this test. With
 * the port's hardware guard (K_ARCH_STACK_GUARD_BYTES) the first write
 * stops it, no switch needed, and nothing below the stack is touched. */
static struct {
    uint32_t pad[128];
    uint32_t stack[K_STACK_WORDS(1024u)];
} guarded __attribute__((aligned(4)));
static volatile uint32_t depth;

static uint32_t recurse(uint32_t n)
{
    volatile uint32_t frame[8];
    frame[0] = n;
    depth = n;
#ifndef K_ARCH_STACK_GUARD_BYTES
    k_sleep_ticks(1); /* a switch per level: the guard is checked */
#endif
    /* (with the port's hardware guard the first write into it stops the
     * thread, which here is one of its own frames, not a kernel call's) */
    return n >= 100000u ? frame[0] : recurse(n + 1u) + frame[0];
}

static void *overflower(void *arg)
{
    (void)arg;
    return (void *)(uintptr_t)recurse(1);
}

static void *controller(void *arg)
{
    int r;
    (void)arg;
    k_thread_create(&t_a, "deep-recursion", overflower, NULL, guarded.stack,
                    sizeof guarded.stack, 5);
    r = k_thread_join(&t_a, NULL, 5000);
    k_printf("KTEST join_rc=%d depth=%lu overflows=%lu state=%u\n", r, (unsigned long)depth,
             (unsigned long)k_stats.stack_overflows, t_a.state);
    check(r == K_ESTACK, "join did not report the overflow");
    check(k_stack_overflowed() == &t_a, "wrong thread blamed");
    check(t_a.state == K_THREAD_DEAD, "the overflowing thread still runs");
    check(guarded.pad[0] == 0u, "the overflow ran far past the guard before it was caught");
    finish();
    return NULL;
}

/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_BADUSE
static struct k_mutex mtx;
static struct k_sem sem;
static struct k_mq mq;
static uint32_t mq_storage[2];
static volatile int isr_wait_rc = 1, isr_lock_rc = 1, isr_send_rc = 1, isr_ran;

static void in_tick_interrupt(void)
{
    uint32_t v = 7;
    if (isr_ran)
        return;
    isr_ran = 1;
    isr_wait_rc = k_sem_wait_ticks(&sem, 10);
    isr_lock_rc = k_mutex_lock(&mtx);
    isr_send_rc = k_mq_send_ticks(&mq, &v, 10); /* full and in a handler */
}

static void *holder(void *arg)
{
    (void)arg;
    k_mutex_lock(&mtx);
    k_sleep_ticks(50);
    k_mutex_unlock(&mtx);
    return NULL;
}

static void *controller(void *arg)
{
    uint32_t v = 1;
    int r_unlock, r_full, r_relock, r_null, r_join;
    (void)arg;
    k_mutex_init(&mtx);
    k_sem_init(&sem, 0, 1);
    k_mq_init(&mq, mq_storage, sizeof(uint32_t), 2);
    k_thread_create(&t_a, "holder", holder, NULL, stack_a, STACK_BYTES, 15);
    k_sleep_ticks(2);
    r_unlock = k_mutex_unlock(&mtx);   /* held by "holder" */
    k_mq_send_ticks(&mq, &v, K_NO_WAIT);
    k_mq_send_ticks(&mq, &v, K_NO_WAIT);
    r_full = k_mq_send_ticks(&mq, &v, K_NO_WAIT);
    k_board_tick_callback = in_tick_interrupt;
    k_sleep_ticks(3);
    k_board_tick_callback = NULL;
    k_thread_join(&t_a, NULL, K_FOREVER);
    k_mutex_lock(&mtx);
    r_relock = k_mutex_lock(&mtx);
    k_mutex_unlock(&mtx);
    r_null = k_sem_post(NULL);
    r_join = k_thread_join(&t_main, NULL, K_FOREVER);
    k_printf("KTEST unlock_not_owner=%d full_queue=%d isr_wait=%d isr_lock=%d isr_send=%d "
             "relock=%d null_sem=%d self_join=%d console_drops=%lu\n",
             r_unlock, r_full, isr_wait_rc, isr_lock_rc, isr_send_rc, r_relock, r_null, r_join,
             (unsigned long)k_board_console_dropped());
    check(r_unlock == K_EPERM, "unlock by a non-owner");
    check(r_full == K_EAGAIN, "send to a full queue");
    check(isr_wait_rc == K_EISR && isr_lock_rc == K_EISR && isr_send_rc == K_EISR,
          "waiting in an interrupt handler");
    check(r_relock == K_EDEADLK && r_null == K_EINVAL && r_join == K_EDEADLK, "misc misuse");
    finish();
    return NULL;
}

/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_MEASURE
/* Two scenarios for instruction counting with QEMU's exec trace (see
 * test_kernel_target.py / README): the global labels mark the points the
 * counter measures between. */
static struct k_sem sem;
static volatile int round_no;

/* (1) tick with a switch: "sleeper" (prio 20) sleeps one tick at a time;
 * "spinner" (prio 5) spins at ktest_spin_loop. The PIT interrupt that
 * ends the sleep switches from spinner to sleeper. */
static void *sleeper(void *arg)
{
    int i;
    (void)arg;
    for (i = 0; i < 20; i++) {
        k_sleep_ticks(1);
        __asm__ __volatile__(".globl ktest_after_sleep\nktest_after_sleep:");
    }
    return NULL;
}

static volatile int spinning = 1;
static void *spinner(void *arg)
{
    (void)arg;
    while (spinning)
        __asm__ __volatile__(".globl ktest_spin_loop\nktest_spin_loop: nop");
    return NULL;
}

/* (2) semaphore hand-off: "taker" (prio 20) waits, "giver" (prio 10) posts. */
static void *taker(void *arg)
{
    int i;
    (void)arg;
    for (i = 0; i < 20; i++) {
        k_sem_wait(&sem);
        __asm__ __volatile__(".globl ktest_after_wait\nktest_after_wait:");
    }
    return NULL;
}

static void *giver(void *arg)
{
    int i;
    (void)arg;
    for (i = 0; i < 20; i++) {
        __asm__ __volatile__(".globl ktest_before_post\nktest_before_post:");
        k_sem_post(&sem);
    }
    return NULL;
}

static void *controller(void *arg)
{
    (void)arg;
    k_sem_init(&sem, 0, 100);
    k_thread_create(&t_a, "sleeper", sleeper, NULL, stack_a, STACK_BYTES, 20);
    k_thread_create(&t_b, "spinner", spinner, NULL, stack_b, STACK_BYTES, 5);
    k_thread_join(&t_a, NULL, K_FOREVER);
    spinning = 0;
    k_thread_join(&t_b, NULL, K_FOREVER);
    k_thread_create(&t_a, "taker", taker, NULL, stack_a, STACK_BYTES, 20);
    k_thread_create(&t_b, "giver", giver, NULL, stack_b, STACK_BYTES, 10);
    k_thread_join(&t_a, NULL, K_FOREVER);
    k_printf("KTEST measured switches=%lu\n", (unsigned long)k_stats.context_switches);
    /* 20 tick switches there and back, 20 hand-offs there and back */
    check(k_stats.context_switches >= 80u, "the scenarios did not switch as planned");
    finish();
    return NULL;
}
/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_OVERLOAD
/* Continuous overrun: a B-scheduler cycle every tick whose process waits 2
 * ticks (as if for I/O), so every cycle overruns while the CPU stays mostly
 * free. A spinner at the lowest priority counts loops: it must keep nearly
 * the share it had before the overload (the reporter, just below the
 * B-scheduler thread, is rate-limited). Its stack holds nothing of the
 * interrupt handlers (they run on the interrupt stack): its high-water mark
 * stays near the entry frame and the switch frame. */
#define OVERLOAD_WINDOW 1024u
static struct bsched bs;
static struct k_bsched kb;
static volatile uint32_t spins;
static volatile int stop_spinning;

static void process(void *context, uint16_t index)
{
    (void)context;
    (void)index;
    k_sleep_ticks(2);
}

static void *spinner(void *arg)
{
    (void)arg;
    while (!stop_spinning)
        spins++;
    return NULL;
}

static uint32_t spins_over(k_ticks_t ticks)
{
    uint32_t s0 = spins;
    k_sleep_ticks(ticks);
    return spins - s0;
}

static void *controller(void *arg)
{
    static const uint8_t pv[] = {0};
    uint32_t alone, loaded, events0, events, lines0, lines, irq_bytes = 0, irq_used = 0;
    uint32_t spin_used = 0;
    (void)arg;
    k_thread_create(&t_a, "spinner", spinner, NULL, stack_a, 512u, K_PRIO_APP_MIN);
    k_sleep_ticks(2);
    alone = spins_over(OVERLOAD_WINDOW);
    bsched_init(&bs, pv, 1);
    k_bsched_start(&kb, &bs, process, NULL, 1, stack_b, STACK_BYTES);
    k_sleep_ticks(16); /* into the steady overload */
    events0 = kb.overrun_events;
    lines0 = kb.report_lines;
    loaded = spins_over(OVERLOAD_WINDOW);
    events = kb.overrun_events - events0;
    lines = kb.report_lines - lines0;
    kb.stop = 1;
    k_thread_join(&kb.thread, NULL, K_FOREVER);
    stop_spinning = 1;
    k_thread_join(&t_a, NULL, K_FOREVER);
    spin_used = stack_used_on(stack_a);
    (void)k_irq_stack_usage(&irq_bytes, &irq_used);
    k_printf("KTEST window=%lu spins_alone=%lu spins_overload=%lu share_permille=%lu "
             "overrun_events=%lu report_lines=%lu interval=%lu spinner_stack_used=%lu "
             "irq_stack_bytes=%lu irq_stack_used=%lu\n",
             (unsigned long)OVERLOAD_WINDOW, (unsigned long)alone, (unsigned long)loaded,
             (unsigned long)(loaded / 8u * 1000u / (alone / 8u ? alone / 8u : 1u)),
             (unsigned long)events, (unsigned long)lines,
             (unsigned long)K_BSCHED_REPORT_INTERVAL_TICKS, (unsigned long)spin_used,
             (unsigned long)irq_bytes, (unsigned long)irq_used);
    check(events >= OVERLOAD_WINDOW / 4u, "the overload did not overrun continuously");
    check(lines <= OVERLOAD_WINDOW / K_BSCHED_REPORT_INTERVAL_TICKS * 2u + 2u,
          "the reporter printed more than one burst per interval");
    check(loaded / 8u * 10u >= alone / 8u * 8u,
          "the lowest thread got less than 80 % of its share under overrun");
    check(spin_used < 256u, "interrupt frames beyond the entry's landed on a thread stack");
    check(irq_used > 0u && irq_used < irq_bytes, "interrupt stack unused or full");
    finish();
    return NULL;
}

/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_TCBGUARD
/* A thread's control block right below its stack (as in struct k_bsched):
 * the thread overflows its stack by two words, past the guard words into
 * the control block's last word (its canary). At its next switch the kernel
 * must notice, report the block and halt: nothing else may run after it.
 * On a port whose hardware guards stacks (K_ARCH_STACK_GUARD_BYTES) the first
 * write into the guard stops the thread: the block stays intact and the
 * system goes on. */
static struct {
    struct k_thread t;
    uint32_t stack[K_STACK_WORDS(512u)];
} victim __attribute__((aligned(4)));

static void *overflower(void *arg)
{
    volatile uint32_t *below = victim.t.stack_base; /* the stack as the kernel placed it */
    unsigned i;
    (void)arg;
    /* What a frame two words too deep writes: the guard words, then the
     * two words under the stack. */
    for (i = 0; i < K_STACK_GUARD_WORDS; i++)
        below[i] = 0x0BADF00Du;
    below[-1] = 0x0BADF00Du;
    below[-2] = 0x0BADF00Du;
    k_sleep_ticks(1);
    k_printf("KTEST RESULT FAIL the overflowing thread ran on\n");
    return NULL;
}

static void *controller(void *arg)
{
    (void)arg;
    k_printf("KTEST victim=0x%lx\n", (unsigned long)(uintptr_t)&victim.t);
    k_thread_create(&victim.t, "victim", overflower, NULL, victim.stack,
                    sizeof victim.stack, 5);
    k_sleep_ticks(50);
#ifdef K_ARCH_STACK_GUARD_BYTES
    check(victim.t.state == K_THREAD_DEAD, "the overflowing thread still runs");
    check(k_stack_overflowed() == &victim.t, "wrong thread blamed");
    check(victim.t.canary == (K_THREAD_CANARY ^ (uintptr_t)&victim.t), "control block overwritten");
    finish();
#else
    k_printf("KTEST RESULT FAIL the system went on after the overflow\n");
#endif
    return NULL;
}
/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_NESTING
/* Interrupt nesting on the interrupt stack. Inside the tick handler (level
 * 4), with all levels masked, a line goes into the console ring, which
 * enables the DUART's transmit interrupt (level 5): it is pending. The free
 * part of the interrupt stack below the handler is refilled, then the mask
 * goes back to level 4 and the DUART interrupt nests at once, on the
 * interrupt stack below the tick handler: the high-water mark afterwards
 * shows how deep it went. The thread that was interrupted must not see any
 * of it on its own stack. */
#define NEST_SLACK 64u  /* bytes below the handler's frame left for its own calls */
static volatile uint32_t depth_here, used_before, used_after;
static volatile int armed;
static const char nest_line[] = "KTEST nesting: this line leaves from inside the tick interrupt\n";

static void refill_below(uint32_t *base, const volatile uint8_t *frame)
{
    size_t i;
#ifdef K_ARCH_STACK_GUARD_BYTES
    for (i = K_ARCH_STACK_GUARD_BYTES / 4u; (uintptr_t)&base[i] + NEST_SLACK < (uintptr_t)frame; i++)
#else
    for (i = K_STACK_GUARD_WORDS; (uintptr_t)&base[i] + NEST_SLACK < (uintptr_t)frame; i++)
#endif
        base[i] = K_STACK_GUARD;
}

static void tick_prints(void)
{
    size_t words;
    uint32_t irq, size, used;
    uint32_t *base = (uint32_t *)(uintptr_t)k_arch_irq_stack(&words);
    volatile uint8_t here = 0;
    if (!armed)
        return;
    armed = 0;
    depth_here = (uint32_t)((uintptr_t)(base + words) - (uintptr_t)&here);
    irq = k_arch_irq_save();
    (void)k_console_write(nest_line, sizeof nest_line - 1u);
    refill_below(base, &here);
    (void)k_irq_stack_usage(&size, &used);
    used_before = used;
    k_arch_irq_restore(irq);      /* the DUART's level 5 nests here */
    (void)k_irq_stack_usage(&size, &used);
    used_after = used;
}

static volatile uint32_t spins;
static volatile int stop_spinning;
static void *spinner(void *arg)
{
    (void)arg;
    while (!stop_spinning)
        spins++;
    return NULL;
}

static void *controller(void *arg)
{
    uint32_t spin_used = 0, size = 0, used = 0;
    (void)arg;
    k_thread_create(&t_a, "spinner", spinner, NULL, stack_a, 512u, K_PRIO_APP_MIN);
    k_sleep_ticks(20);                /* the console is idle again */
    k_board_tick_callback = tick_prints;
    armed = 1;
    k_sleep_ticks(10);                /* the spinner runs when the tick comes */
    k_board_tick_callback = NULL;
    stop_spinning = 1;
    k_thread_join(&t_a, NULL, K_FOREVER);
    spin_used = stack_used_on(stack_a);
    (void)k_irq_stack_usage(&size, &used);
    k_printf("KTEST tick_depth=%lu used_before=%lu used_after=%lu "
             "spinner_stack_used=%lu irq_stack_bytes=%lu\n",
             (unsigned long)depth_here, (unsigned long)used_before, (unsigned long)used_after,
             (unsigned long)spin_used, (unsigned long)size);
    check(armed == 0, "the tick callback never ran");
    check(used_before <= depth_here + NEST_SLACK, "the refill below the tick handler did not take");
    check(used_after >= depth_here + NEST_SLACK + 32u,
          "no interrupt nested below the tick handler on the interrupt stack");
    check(used_after < size, "the interrupt stack overflowed");
    check(spin_used < 256u, "the nested interrupt landed on the thread's stack");
    finish();
    return NULL;
}
/* ------------------------------------------------------------------ */
#elif KTEST_MODE == KTEST_TIMING
/* The B-scheduler thread's timing records on the board's fine counter.
 * Four processes of known, different work (busy loops): 0 and 1 the same
 * short loop, 2 twenty times as long, 3 five times; a cycle every 4 ticks,
 * a spinner below. The worst execution times must order and scale as the
 * work does (bounds below: the call and a counter read add a constant to
 * each, which pulls the ratios down; a tick interrupt inside a short one
 * pulls them down further), and every release's jitter must stay under a
 * quarter tick. The board's stated rate is checked against the tick. */
#define TIMING_CYCLES 64u
#define TIMING_PERIOD 4u
#define TIMING_SHORT  50u    /* loop rounds of processes 0 and 1 */
static struct bsched bs;
static struct k_bsched kb;
static volatile uint32_t work_done;
static volatile int stop_spinning;
static const uint32_t work_of[4] = {TIMING_SHORT, TIMING_SHORT, 20u * TIMING_SHORT, 5u * TIMING_SHORT};

static void busy(uint32_t rounds)
{
    volatile uint32_t i;
    for (i = 0; i < rounds; i++)
        work_done++;
}

static void process(void *context, uint16_t index)
{
    (void)context;
    busy(work_of[index]);
}

static void *spinner(void *arg)
{
    (void)arg;
    while (!stop_spinning) {
    }
    return NULL;
}

static void *controller(void *arg)
{
    static const uint8_t pv[] = {0, 0, 1, 2};
    uint32_t worst[4], runs[4], jmin = 0, jmax = 0, jmean = 0, samples = 0;
    uint32_t hz, per_tick, t0, slept;
    uint16_t i;
    (void)arg;
    check(k_timestamp_hz() == K_TICK_HZ, "the fine counter ran before anyone started it");
    check(k_timestamp_start() == K_OK, "the board's fine counter did not start");
    hz = k_timestamp_hz();
    per_tick = hz / K_TICK_HZ;
    /* the counter's rate against the tick: 100 ticks of sleep */
    k_sleep_ticks(1);
    t0 = k_timestamp();
    k_sleep_ticks(100);
    slept = k_timestamp() - t0;
    k_thread_create(&t_a, "spinner", spinner, NULL, stack_a, 512u, K_PRIO_APP_MIN);
    bsched_init(&bs, pv, 4);
    kb.stop_after = TIMING_CYCLES;
    kb.measure = 1;
    k_bsched_start(&kb, &bs, process, NULL, TIMING_PERIOD, stack_b, STACK_BYTES);
    k_thread_join(&kb.thread, NULL, K_FOREVER);
    stop_spinning = 1;
    k_thread_join(&t_a, NULL, K_FOREVER);
    for (i = 0; i < 4u; i++)
        check(k_bsched_wcet(&kb, i, &worst[i], &runs[i]) == K_OK, "k_bsched_wcet refused a process of the set");
    check(k_bsched_wcet(&kb, 4, NULL, NULL) == K_EINVAL, "k_bsched_wcet took an index outside the set");
    (void)k_bsched_jitter(&kb, &jmin, &jmax, &jmean, &samples);
    k_printf("KTEST hz=%lu tick_hz=%lu slept_100_ticks=%lu\n", (unsigned long)hz,
             (unsigned long)K_TICK_HZ, (unsigned long)slept);
    k_printf("KTEST worst0=%lu worst1=%lu worst2=%lu worst3=%lu runs0=%lu runs1=%lu runs2=%lu runs3=%lu\n",
             (unsigned long)worst[0], (unsigned long)worst[1], (unsigned long)worst[2],
             (unsigned long)worst[3], (unsigned long)runs[0], (unsigned long)runs[1],
             (unsigned long)runs[2], (unsigned long)runs[3]);
    k_printf("KTEST jitter_min=%lu jitter_max=%lu jitter_mean=%lu jitter_samples=%lu cycles=%lu overruns=%lu\n",
             (unsigned long)jmin, (unsigned long)jmax, (unsigned long)jmean,
             (unsigned long)samples, (unsigned long)kb.cycles_run, (unsigned long)kb.overruns);
    check(hz > 32u * K_TICK_HZ, "no fine counter registered (or one coarser than 1/32 tick)");
    /* both ends are taken just after a tick's wake-up: 100 ticks apart */
    check(slept + per_tick / 8u >= 100u * per_tick && slept <= 100u * per_tick + per_tick / 8u,
          "the counter's stated rate disagrees with the tick");
    check(kb.cycles_run == TIMING_CYCLES && kb.overruns == 0u, "cycle accounting");
    check(runs[0] == 64u && runs[1] == 64u && runs[2] == 32u && runs[3] == 16u, "runs per process");
    check(worst[0] > 0u && worst[1] > 0u, "a short process measured 0");
    check(worst[0] * 2u > worst[1] && worst[1] * 2u > worst[0], "the two equal processes differ by 2x");
    check(worst[2] > 10u * worst[0] && worst[2] > 10u * worst[1] &&
          worst[2] <= 21u * worst[0] && worst[2] <= 21u * worst[1],
          "the 20x process is not 10..21 times the short ones");
    check(worst[3] * 2u > 5u * worst[0] && worst[3] <= 6u * worst[0] && worst[2] > 3u * worst[3],
          "the 5x process is not 2.5..6 times the short one, or not below the 20x one");
    check(samples == TIMING_CYCLES, "not one jitter sample per cycle");
    check(jmin > 0u && jmin <= jmean && jmean <= jmax && jmax < per_tick / 4u,
          "release jitter zero, out of order or not under a quarter tick");
    finish();
    return NULL;
}
#else
#error "unknown KTEST_MODE"
#endif

int main(void);
int main(void)
{
    k_init();
    if (k_board_init() != 0) {
        k_console_write_sync("KTEST RESULT FAIL board\n", 24);
        for (;;) {
        }
    }
    k_printf("KTEST %d START\n", KTEST_MODE);
    if (k_thread_create(&t_main, "controller", controller, NULL, stack_main, STACK_BYTES, 26) != K_OK)
        k_printf("KTEST RESULT FAIL creating the controller thread\n");
    k_start();
    return 0;
}
