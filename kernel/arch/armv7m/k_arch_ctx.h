/*
 * ARMv7-M (Cortex-M3/M4) port of the nanokernel: the per-thread context and
 * the interrupt mask primitives, inline because every kernel call uses them.
 *
 * Threads run in privileged thread mode on the process stack (PSP); every
 * exception runs on the main stack (MSP), the port's interrupt stack. A
 * switched-out thread's stack holds, from its saved SP upwards: the BASEPRI
 * it resumes with, R4-R11 (the software frame, switch.S), then the frame the
 * CPU stacked on exception entry (R0-R3, R12, LR, PC, xPSR).
 *
 * Critical sections use BASEPRI, not PRIMASK: it masks every interrupt the
 * kernel routes (levels 1..7) and PendSV, while faults and SVC (priority 0)
 * still get through, so a thread can switch with SVC inside one.
 */
#ifndef K_ARCH_CTX_H
#define K_ARCH_CTX_H

#include <stdint.h>

struct k_arch_context {
    uint32_t sp;         /* offset 0: switch.S relies on it */
    uint32_t guard_rbar; /* offset 4: the MPU's RBAR for this stack's guard (switch.S) */
};

/* Stacks start on a 32-byte boundary: the MPU's smallest region, which
 * covers a running thread's guard words (k_arch_armv7m.c). */
#define K_ARCH_STACK_ALIGN 32u
/* The lowest bytes of every stack the port's hardware write-protects (the
 * MPU): a thread is stopped at its first write there, so an overflow never
 * reaches what lies below a stack. */
#define K_ARCH_STACK_GUARD_BYTES 32u

/* The NVIC priority of kernel interrupt level L (1..7, 7 most urgent), in the
 * upper four bits the STM32F4 implements: (8 - L) << 4, so level 7 is 0x10
 * and level 1 is 0x70. 0x00 stays above every kernel level (SVC); PendSV
 * gets 0xF0, below them all. */
#define K_ARCH_PRIO_BITS 4u
#define K_ARCH_LEVEL_PRIO(level) ((uint8_t)((8u - (level)) << (8u - K_ARCH_PRIO_BITS)))
/* BASEPRI while the kernel masks interrupts: everything from level 7 down. */
#define K_ARCH_BASEPRI_MASK K_ARCH_LEVEL_PRIO(7u)

#define K_ARCH_INLINE_IRQ 1

/* Raises BASEPRI to mask every kernel level; returns the previous BASEPRI
 * (0: all enabled). */
static inline uint32_t k_arch_irq_save(void)
{
    uint32_t old, mask = K_ARCH_BASEPRI_MASK;
    __asm__ __volatile__("mrs %0, basepri\n\tmsr basepri, %1\n\tisb"
                         : "=&r"(old) : "r"(mask) : "memory");
    return old;
}

static inline void k_arch_irq_restore(uint32_t state)
{
    __asm__ __volatile__("msr basepri, %0\n\tisb" : : "r"(state) : "memory");
}

#endif /* K_ARCH_CTX_H */
