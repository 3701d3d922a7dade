/*
 * Host port for the unit tests. Threads are ucontexts; "interrupts disabled"
 * is a flag that the tests can check; the idle thread simulates the passage
 * of time: while a timer is pending it delivers tick interrupts, and when
 * nothing can ever run again it returns to k_start's caller.
 */
#define _XOPEN_SOURCE 700
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "k_internal.h"
#include "host_port.h"

/* Under AddressSanitizer (make check-sanitize): a thread that never returns
 * leaves its frames' redzones poisoned on its stack, and the next test that
 * reuses that stack would trip over them. The stacks are handed back clean
 * when every thread has stopped (k_arch_idle below). */
#ifdef __SANITIZE_ADDRESS__
#include <sanitizer/asan_interface.h>
#define HOST_UNPOISON(p, n) ASAN_UNPOISON_MEMORY_REGION(p, n)
#else
#define HOST_UNPOISON(p, n) ((void)(p), (void)(n))
#endif

static int irq_disabled;

static void host_unpoison_stacks(void)
{
    for (struct k_thread *t = k_kernel.all; t != NULL; t = t->all_next)
        HOST_UNPOISON(t->stack_base, t->stack_words * sizeof(uint32_t));
}
static ucontext_t *boot_uc;
char host_console[HOST_CONSOLE_SIZE];
size_t host_console_len;
unsigned host_irq_routed[256];

uint32_t k_arch_irq_save(void)
{
    uint32_t was = (uint32_t)irq_disabled;
    irq_disabled = 1;
    return was;
}

void k_arch_irq_restore(uint32_t state)
{
    irq_disabled = state != 0u;
}

int host_irq_disabled(void)
{
    return irq_disabled;
}

static void host_thread_entry(void)
{
    k_thread_start();
}

void k_arch_thread_init(struct k_thread *t)
{
    /* The host keeps the guard words at the low end of the given stack and
     * runs the thread on the rest of it. */
    ucontext_t *uc = &t->ctx.uc;
    if (getcontext(uc) != 0)
        abort();
    uc->uc_stack.ss_sp = t->stack_base + K_STACK_GUARD_WORDS;
    uc->uc_stack.ss_size = (t->stack_words - K_STACK_GUARD_WORDS) * sizeof(uint32_t);
    uc->uc_link = NULL;
    makecontext(uc, host_thread_entry, 0);
}

void k_arch_switch(struct k_thread *from, struct k_thread *to)
{
    if (!irq_disabled) {
        fprintf(stderr, "k_arch_switch with interrupts enabled\n");
        abort();
    }
    if (from == &k_kernel.boot)
        boot_uc = &from->ctx.uc;
    if (swapcontext(&from->ctx.uc, &to->ctx.uc) != 0)
        abort();
}

void host_tick(void)
{
    k_isr_enter();
    k_tick();
    k_isr_exit();
}

void k_arch_idle(void)
{
    if (k_tlist_first(&k_kernel.timers) != NULL) {
        host_tick();
        return;
    }
    /* Nothing will ever be ready again: back to k_start's caller. */
    (void)k_arch_irq_save();
    host_unpoison_stacks();
    k_kernel.current = &k_kernel.boot;
    if (swapcontext(&k_kernel.idle.ctx.uc, boot_uc) != 0)
        abort();
}

const uint32_t *k_arch_irq_stack(size_t *words)
{
    *words = 0;
    return NULL; /* handlers run on the interrupted thread's stack */
}

/* The kernel stopped the system (a fatal report): the test gets control
 * back as if k_start had returned, and host_halted says why. */
int host_halted;
void k_arch_halt(void)
{
    (void)k_arch_irq_save();
    host_halted++;
    host_unpoison_stacks();
    k_kernel.current = &k_kernel.boot;
    k_kernel.started = 0;
    if (boot_uc != NULL)
        (void)setcontext(boot_uc);
    abort();
}

int k_arch_irq_route(unsigned vector)
{
    host_irq_routed[vector & 0xFFu]++;
    return K_OK;
}

/* The host port has no interrupt stack: the handler runs where it was called. */
void k_isr_call(void (*fn)(void *arg), void *arg)
{
    k_isr_enter();
    fn(arg);
    k_isr_exit();
}

void host_raise_irq(unsigned vector)
{
    k_isr_run(vector);
}

size_t host_console_writes_in_isr;

/* The host board's console writer: bytes go to host_console. */
static size_t host_console_write(const char *s, size_t len)
{
    size_t room = HOST_CONSOLE_SIZE - 1u - host_console_len;
    if (k_in_isr())
        host_console_writes_in_isr++;
    if (len > room)
        len = room;
    memcpy(host_console + host_console_len, s, len);
    host_console_len += len;
    host_console[host_console_len] = '\0';
    return len;
}

static void host_console_write_sync(const char *s, size_t len)
{
    (void)host_console_write(s, len);
}

void host_console_clear(void)
{
    k_console_register(host_console_write, host_console_write_sync);
    host_console_writes_in_isr = 0;
    host_console_len = 0;
    host_console[0] = '\0';
}
