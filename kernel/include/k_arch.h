/*
 * The architecture boundary: all the kernel needs from a CPU port.
 * Ports: kernel/arch/cpu32 (the 68332 target, switch.S), kernel/arch/armv7m
 * (Cortex-M3/M4: PendSV/SVC switch, the STM32F405 board) and
 * kernel/tests/host/arch (ucontext, for the host unit tests). Each port
 * provides k_arch_ctx.h with struct k_arch_context, found on the include path.
 */
#ifndef K_ARCH_H
#define K_ARCH_H

#include <stddef.h>
#include <stdint.h>
#include "k_arch_ctx.h"

struct k_thread;

#ifndef K_ARCH_INLINE_IRQ /* a port may define them inline in k_arch_ctx.h */
/* Disables interrupts (all levels) and returns the previous state; state 0
 * means enabled. */
uint32_t k_arch_irq_save(void);
/* Restores a state from k_arch_irq_save. */
void k_arch_irq_restore(uint32_t state);
#endif
/* Prepares t's stack (t->stack_base, t->stack_words) so that the first
 * k_arch_switch to t calls k_thread_start() with interrupts disabled. */
void k_arch_thread_init(struct k_thread *t);
/* Saves the caller's context in from and resumes to. Called with interrupts
 * disabled; returns (in from) when something switches back to from. */
void k_arch_switch(struct k_thread *from, struct k_thread *to);
/* The idle thread's body between checks: wait for an interrupt. */
void k_arch_idle(void);
/* Stops the system for good (interrupts masked): after a fatal report. */
void k_arch_halt(void) __attribute__((noreturn));
/* The port's interrupt stack (*words long, guard words at the low end), or
 * NULL when interrupts run on the thread stacks. */
const uint32_t *k_arch_irq_stack(size_t *words);
/* Routes exception vector `vector` through the kernel's interrupt entry
 * (which calls k_isr_enter, the registered handler, k_isr_exit). */
int k_arch_irq_route(unsigned vector);

/* Kernel side, called by the port. */
void k_thread_start(void);
/* Dispatches the handler registered for vector (from the interrupt entry). */
void k_irq_dispatch(unsigned vector);
/* k_isr_enter, k_irq_dispatch, k_isr_exit: the whole interrupt, for an entry
 * that runs handlers on the interrupted stack (the host port; the CPU32 entry
 * has its own interrupt stack and sequence, switch.S). */
void k_isr_run(unsigned vector);

#endif /* K_ARCH_H */
