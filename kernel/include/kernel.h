/*
 * The bsched nanokernel: threads with static stacks, a pre-emptive
 * priority scheduler with round robin within a priority, counting
 * semaphores, owner-checked mutexes with priority inheritance, condition
 * variables, message queues of fixed-size messages, event flags, monotonic
 * time and sleeps.
 *
 * Names follow POSIX where POSIX has the service (k_ + the POSIX name:
 * k_sem_timedwait, k_clock_gettime, k_clock_nanosleep ...); additions take
 * timeouts in ticks (K_NO_WAIT, K_FOREVER or a count).
 *
 * Every call returns K_OK (0) or a value >= 0 on success and a negative
 * K_E* code on misuse or failure: nothing asserts or halts on bad use.
 * Blocking calls made from an interrupt handler return K_EISR instead of
 * blocking (with K_NO_WAIT they work, as a try).
 *
 * Priorities: 0 (idle) .. 31; a larger number is more urgent (as in POSIX
 * SCHED_FIFO). K_PRIO_APP_MAX is the highest application priority (the
 * B-scheduler thread); K_PRIO_SERVICE_MIN.. are internal service threads.
 */
#ifndef KERNEL_H
#define KERNEL_H

#include <stddef.h>
#include <stdint.h>
#include "k_config.h"
#include "k_struct.h"
#include "k_arch.h"

/* ---- status codes (negated POSIX errno values where one fits) ---- */
#define K_OK          0
#define K_EPERM     (-1)   /* not the owner (mutex unlock) */
#define K_ESRCH     (-3)   /* no such thread (not created) */
#define K_EAGAIN   (-11)   /* would block and K_NO_WAIT was given (empty/full) */
#define K_EBUSY    (-16)   /* mutex held, K_NO_WAIT */
#define K_EINVAL   (-22)   /* bad argument (NULL, out of range, not initialised) */
#define K_EDEADLK  (-35)   /* would wait on itself (relock, self join) */
#define K_EOVERFLOW (-75)  /* semaphore at its maximum */
#define K_ETIMEDOUT (-110) /* the timeout expired */
#define K_EOWNERDEAD (-130)/* mutex acquired, the previous owner exited holding it */
#define K_EISR    (-200)   /* a blocking call from an interrupt handler */
#define K_ESTACK  (-201)   /* the thread was stopped for overflowing its stack */

/* ---- time ---- */
typedef uint32_t k_ticks_t;
#define K_NO_WAIT ((k_ticks_t)0)
#define K_FOREVER ((k_ticks_t)0xFFFFFFFFu)

struct k_timespec {
    int32_t tv_sec;
    int32_t tv_nsec;
};
#define K_CLOCK_MONOTONIC 1
#define K_TIMER_ABSTIME   1

/* Ticks since k_init (wraps after 2^32 ticks: 48.5 days at 1024 Hz). */
k_ticks_t k_ticks(void);
/* Milliseconds since k_init (wraps after 2^32 ms = 49.7 days). */
uint32_t k_uptime_ms(void);
/* Fine time stamps, for measuring what takes less than a tick: a
 * free-running counter the board registers at init (k_board_init), as it
 * registers the console; the kernel calls no board. read returns the count,
 * which must run through all 32 bits (a board whose counter is narrower
 * extends it) and may be called in any context, interrupts masked or not;
 * hz is its rate. Differences of two stamps are valid up to 2^32 counts.
 * start (may be NULL: nothing to start) is called once, by the first
 * k_timestamp_start: a board whose counter needs hardware of its own takes
 * it only then, so an image that measures nothing loses nothing to it (the
 * RoboCube's takes TPU channel 15, and its tick does the extension's reads
 * only from then on); it returns K_OK, or an error (K_EBUSY: the hardware
 * is in use) and the counter stays off.
 * Until a counter is registered (k_init forgets it) and started, or when
 * read is NULL or hz 0, k_timestamp is k_ticks() and k_timestamp_hz
 * K_TICK_HZ: what is measured with it comes in whole ticks. */
typedef uint32_t (*k_timestamp_fn)(void);
typedef int (*k_timestamp_start_fn)(void);
void k_timestamp_register(k_timestamp_fn read, uint32_t hz, k_timestamp_start_fn start);
/* Starts the registered counter; later calls return the first call's
 * result. K_OK: k_timestamp counts it from now on. K_EINVAL (none
 * registered) or the board's error: k_timestamp stays k_ticks(). Threads
 * only (the board's start may take a while). */
int k_timestamp_start(void);
/* The counter now, in counts of k_timestamp_hz(). */
uint32_t k_timestamp(void);
uint32_t k_timestamp_hz(void);
/* Monotonic time since k_init, resolution one tick. Only K_CLOCK_MONOTONIC. */
int k_clock_gettime(int clock_id, struct k_timespec *ts);
/* Sleeps at least *req (rounded up to whole ticks, plus the running tick). */
int k_nanosleep(const struct k_timespec *req);
/* Relative (flags 0) or absolute (K_TIMER_ABSTIME, monotonic time) sleep. */
int k_clock_nanosleep(int clock_id, int flags, const struct k_timespec *t);
/* Additions in ticks. */
int k_sleep_ticks(k_ticks_t ticks);
/* Sleeps until the absolute tick `deadline` (returns at once if it passed):
 * periodic threads add their period to the deadline, so they never drift. */
int k_sleep_until(k_ticks_t deadline);
/* Converts, rounding up. */
k_ticks_t k_ms_to_ticks(uint32_t ms);
/* An absolute monotonic time as a timeout in ticks from now, for the calls
 * that take ticks: K_NO_WAIT once it has passed. K_EINVAL for a bad timespec. */
int k_abs_to_timeout(const struct k_timespec *abs, k_ticks_t *timeout);

/* ---- threads ---- */
enum k_thread_state {
    K_THREAD_UNUSED = 0,
    K_THREAD_READY,    /* in the ready queue (includes the running thread) */
    K_THREAD_BLOCKED,  /* waiting: a wait queue and/or a timeout */
    K_THREAD_DEAD      /* exited (or stopped on stack overflow), joinable */
};

struct k_mutex;
struct k_waitq {
    struct k_list_node waiters; /* by priority, FIFO within a priority */
};

typedef void *(*k_thread_fn)(void *arg);

struct k_thread {
    struct k_arch_context ctx;   /* first: the context switch finds it at offset 0 */
    struct k_list_node node;     /* ready queue or wait queue */
    struct k_timer_node timer;   /* sleep / timeout */
    const char *name;
    uint32_t *stack_base;        /* lowest word: the guard words live here */
    size_t stack_words;
    k_thread_fn entry;
    void *arg;
    void *exit_value;
    uint8_t base_prio;           /* as created / set */
    uint8_t prio;                /* effective: base or inherited */
    uint8_t state;               /* enum k_thread_state */
    uint8_t slice_left;          /* ticks left in the round-robin slice */
    uint8_t timeslice;           /* ticks per round-robin slice; 0: none (FIFO) */
    uint8_t reserved[3];         /* keeps the block a multiple of 4 bytes long, so a
                                  * stack placed right after it stays aligned */
    struct k_waitq *waitq;       /* queue blocked on, or NULL */
    struct k_mutex *wait_mutex;  /* mutex blocked on (priority inheritance) */
    struct k_list_node held;     /* mutexes held, for priority inheritance */
    int32_t wait_result;         /* set by whoever wakes the thread */
    uint32_t wait_value;         /* event masks in, matched bits out */
    uint32_t wait_flags;
    const void *wait_src;        /* message to send while blocked */
    void *wait_dst;              /* message buffer while blocked in receive */
    struct k_waitq joiners;
    uint32_t switches_in;        /* times this thread was switched to */
    struct k_thread *all_next;   /* every created thread, for reports */
    /* Last, so that a stack overflowing into this struct from above breaks it
     * first: K_THREAD_CANARY ^ the struct's address while the struct is sound.
     * Pointer-sized, so that no tail padding lies between it and what follows. */
    uintptr_t canary;
};

/* Stack storage: K_STACK_DEFINE(name, bytes) gives an array aligned to
 * K_ARCH_STACK_ALIGN: 4 bytes (the m68k ABI aligns uint32_t to 2 bytes only;
 * k_thread_create wants 4), or what the port's stack guard needs (32 on
 * ARMv7-M, its MPU region; k_thread_create moves a less aligned base up). */
#ifndef K_ARCH_STACK_ALIGN
#define K_ARCH_STACK_ALIGN 4u
#endif
#define K_STACK_WORDS(bytes) (((bytes) + 3u) / 4u)
#define K_STACK_DEFINE(name, bytes) \
    static uint32_t name[K_STACK_WORDS(bytes)] __attribute__((aligned(K_ARCH_STACK_ALIGN)))

/* pthread_create-like, static: t and the stack belong to the caller.
 * prio 1..31 (0 is the idle thread's). The thread starts when the scheduler
 * next runs (immediately if it is more urgent than the caller). */
int k_thread_create(struct k_thread *t, const char *name, k_thread_fn entry, void *arg,
                    uint32_t *stack, size_t stack_bytes, unsigned prio);
/* Ends the calling thread (also happens when entry returns). */
void k_thread_exit(void *value);
/* Waits until t has exited; *value gets its exit value (may be NULL). */
int k_thread_join(struct k_thread *t, void **value, k_ticks_t timeout);
struct k_thread *k_thread_self(void);
int k_sched_yield(void);
/* Sets the base priority (inherited boosts stay in force). */
int k_thread_setprio(struct k_thread *t, unsigned prio);
/* Sets t's round-robin slice among threads of its priority: 1..255 ticks
 * (K_TIMESLICE_TICKS is every thread's at creation), or 0 for none, so that t
 * runs until it blocks or yields or a more urgent thread is ready (POSIX
 * SCHED_FIFO). Takes effect at t's next slice. */
int k_thread_set_timeslice(struct k_thread *t, unsigned ticks);
/* The first thread whose stack guard was found broken, or NULL. */
struct k_thread *k_stack_overflowed(void);

/* ---- introspection (for a shell's ps and for reports) ---- */
/* One thread as k_thread_list saw it. */
struct k_thread_info {
    const char *name;
    uint8_t prio;           /* effective priority (base or inherited) */
    uint8_t base_prio;
    uint8_t state;          /* enum k_thread_state */
    uint8_t is_current;     /* 1 for the thread that called k_thread_list */
    const uint32_t *stack_base; /* lowest word of its stack */
    uint32_t stack_bytes;   /* size given to k_thread_create (guard words included) */
    uint32_t stack_used;    /* high-water mark, bytes: the deepest word ever written */
    uint32_t switches_in;   /* times the scheduler switched to it */
    uint8_t stack_intact;   /* 1 while its stack guard words are unbroken */
};
/* Snapshot of every created thread (the idle thread included, most recently
 * created first) into out[0 .. max-1]. Returns the number of threads that
 * exist, which may exceed max (only max are written); K_EINVAL if out is NULL
 * and max > 0. A control block found overwritten (its canary broken) halts
 * the system with a report, as at a switch (the list runs through it).
 * The list is copied with interrupts masked; the stack
 * high-water marks are measured afterwards with interrupts enabled, from
 * the fill k_thread_create writes (so the mark is a lower bound: a stack
 * word written with the fill value itself is not counted). */
int k_thread_list(struct k_thread_info *out, unsigned max);
/* The interrupt stack of the port (CPU32: K_IRQ_STACK_BYTES): its size and
 * high-water mark in bytes. K_ESRCH on a port whose handlers run on the
 * thread stacks; K_EINVAL for NULL. */
int k_irq_stack_usage(uint32_t *bytes, uint32_t *used);

/* ---- counting semaphores ---- */
struct k_sem {
    uint32_t count;
    uint32_t max;
    struct k_waitq wq;
    uint32_t magic;
};
int k_sem_init(struct k_sem *s, uint32_t initial, uint32_t max);
int k_sem_wait(struct k_sem *s);                 /* forever */
int k_sem_trywait(struct k_sem *s);              /* K_EAGAIN when zero */
int k_sem_timedwait(struct k_sem *s, const struct k_timespec *abs_monotonic);
int k_sem_wait_ticks(struct k_sem *s, k_ticks_t timeout);
int k_sem_post(struct k_sem *s);                 /* also from interrupt handlers */
int k_sem_getvalue(struct k_sem *s, int32_t *value);
/* Non-zero when a thread waits on s (a driver's handler posts only then). */
int k_sem_has_waiter(const struct k_sem *s);

/* ---- mutexes: owner-checked, not recursive, priority inheritance ---- */
struct k_mutex {
    struct k_thread *owner;
    struct k_waitq wq;
    struct k_list_node held_node; /* in the owner's held list */
    uint32_t owner_died;          /* released by a thread's death, not yet reported */
    uint32_t magic;
};
int k_mutex_init(struct k_mutex *m);
int k_mutex_lock(struct k_mutex *m);
int k_mutex_trylock(struct k_mutex *m);
int k_mutex_timedlock(struct k_mutex *m, const struct k_timespec *abs_monotonic);
int k_mutex_lock_ticks(struct k_mutex *m, k_ticks_t timeout);
int k_mutex_unlock(struct k_mutex *m);

/* ---- condition variables (for a mutex of the caller's) ---- */
struct k_cond {
    struct k_waitq wq;
    uint32_t magic;
};
int k_cond_init(struct k_cond *c);
/* Unlocks m (which the caller must own: K_EPERM otherwise) and waits on c as
 * one step, so no signal sent after the unlock is missed; takes m again
 * before it returns, whatever the outcome. Returns K_OK when signalled,
 * K_ETIMEDOUT when the timeout (ticks; K_NO_WAIT times out at once) passed.
 * Waiters are woken most urgent first, FIFO among equals. */
int k_cond_wait_ticks(struct k_cond *c, struct k_mutex *m, k_ticks_t timeout);
int k_cond_wait(struct k_cond *c, struct k_mutex *m);
int k_cond_timedwait(struct k_cond *c, struct k_mutex *m, const struct k_timespec *abs_monotonic);
/* Wakes the most urgent waiter / every waiter (none: nothing happens). */
int k_cond_signal(struct k_cond *c);
int k_cond_broadcast(struct k_cond *c);

/* ---- message queues of fixed-size messages ---- */
struct k_mq {
    struct k_msgbuf buf;
    struct k_waitq senders;
    struct k_waitq receivers;
    uint32_t magic;
};
/* storage: capacity * msg_size bytes owned by the caller. */
int k_mq_init(struct k_mq *q, void *storage, size_t msg_size, size_t capacity);
int k_mq_send_ticks(struct k_mq *q, const void *msg, k_ticks_t timeout);
int k_mq_receive_ticks(struct k_mq *q, void *msg, k_ticks_t timeout);
int k_mq_send(struct k_mq *q, const void *msg);          /* blocks while full */
int k_mq_receive(struct k_mq *q, void *msg);             /* blocks while empty */
int k_mq_timedsend(struct k_mq *q, const void *msg, const struct k_timespec *abs_monotonic);
int k_mq_timedreceive(struct k_mq *q, void *msg, const struct k_timespec *abs_monotonic);
/* Messages waiting. */
int k_mq_count(struct k_mq *q);

/* ---- event flags (signals for the network stack and drivers) ---- */
#define K_EVENT_ANY   0x0u  /* wake when any requested bit is set */
#define K_EVENT_ALL   0x1u  /* wake when all requested bits are set */
#define K_EVENT_CLEAR 0x2u  /* clear the matched bits on wake-up */
struct k_event {
    uint32_t bits;
    struct k_waitq wq;
    uint32_t magic;
};
int k_event_init(struct k_event *e);
/* Sets bits (also from interrupt handlers), waking every satisfied waiter. */
int k_event_set(struct k_event *e, uint32_t bits);
int k_event_clear(struct k_event *e, uint32_t bits);
/* Waits for mask per flags; *matched gets the bits that satisfied it. */
int k_event_wait(struct k_event *e, uint32_t mask, uint32_t flags, k_ticks_t timeout,
                 uint32_t *matched);

/* ---- interrupts ---- */
/* Handlers run in interrupt context at their level; they may post
 * semaphores, set events and send with K_NO_WAIT, which wakes threads. */
typedef void (*k_irq_handler)(void *arg);
/* Registers handler for exception vector `vector` (24..255) of interrupt level
 * `level` (1..7); the architecture routes the vector through the kernel's
 * interrupt entry so a woken thread runs as soon as the handler returns. */
int k_irq_register(unsigned vector, unsigned level, k_irq_handler handler, void *arg);
/* Non-zero inside an interrupt handler. */
int k_in_isr(void);
/* Non-zero when the caller may wait: a thread of the started kernel, not a
 * handler, not the start-up code before k_start. */
int k_can_block(void);
/* For a driver's own interrupt handler (claimed in the vector table, not
 * through k_irq_register) once it has masked all interrupt levels: runs
 * fn(arg) as the kernel runs a registered handler (on the interrupt stack
 * where the port has one; fn may post, set events, send with K_NO_WAIT) and
 * switches to a thread it woke on the way out. */
void k_isr_call(void (*fn)(void *arg), void *arg);
/* Called by the interrupt entry around every handler. */
void k_isr_enter(void);
void k_isr_exit(void);
/* The tick: called by the tick interrupt handler (the PIT on the 68332). */
void k_tick(void);
/* Called at the end of every tick, in the interrupt handler with the
 * interrupt mask back at the tick's level (the B-scheduler thread's
 * watchdog uses it). NULL when unused. */
extern void (*volatile k_tick_hook)(k_ticks_t now);

/* ---- start-up ---- */
/* Resets the kernel (no thread runs yet). */
void k_init(void);
/* Starts scheduling; does not return on the target. On the host port it
 * returns once every thread is blocked forever or dead. */
void k_start(void);

/* ---- console output (formatting without libc) ---- */
/* Writes through the registered console writer (k_console_write). */
int k_printf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* Formats into buf (always NUL-terminated when size > 0); returns the length
 * the full output would have. Supports %d %i %u %x %X %c %s %p %% with
 * flags '-' '0', a width, and the l and h length modifiers. */
int k_snprintf(char *buf, size_t size, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
#include <stdarg.h>
int k_vsnprintf(char *buf, size_t size, const char *fmt, va_list ap);
typedef void (*k_putc_fn)(void *ctx, char c);
int k_vformat(k_putc_fn out, void *ctx, const char *fmt, va_list ap);
/* The console is a writer the board registers (as a printk hook is): the
 * kernel calls no driver. Two functions:
 *   write       takes what it can of s[0..len) and returns the count; in a
 *               thread of the started kernel (k_can_block) it may wait for
 *               room, elsewhere it must not (it drops what does not fit)
 *   write_sync  sends every byte by polling before it returns, in any
 *               context, interrupts masked or not (fault reports)
 * write may be NULL: then write_sync serves both, the polled early writer a
 * board registers as soon as its console can send (and keeps, if it has no
 * interrupt-driven one). Registering again replaces both. Until a board
 * registers a writer, console bytes are dropped. */
typedef size_t (*k_console_write_fn)(const char *s, size_t len);
typedef void (*k_console_sync_fn)(const char *s, size_t len);
void k_console_register(k_console_write_fn write, k_console_sync_fn write_sync);
/* Through the registered writer: returns the bytes taken. */
size_t k_console_write(const char *s, size_t len);
/* Through the registered polled writer (fault reports, any context). */
void k_console_write_sync(const char *s, size_t len);

/* ---- statistics ---- */
struct k_stats {
    uint32_t context_switches;
    uint32_t ticks_isr;          /* tick interrupts seen */
    uint32_t stack_overflows;
    uint32_t spurious_irqs;      /* vectors with no handler */
};
extern struct k_stats k_stats;

#endif /* KERNEL_H */
