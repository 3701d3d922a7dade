/*
 * CPU32 port of the nanokernel: the per-thread context and the interrupt
 * mask primitives, inline because every kernel call uses them.
 *
 * All threads run in supervisor mode on their own stacks (the CPU32 has no
 * separate interrupt stack: exception frames land on the running thread's
 * stack). A switched-out thread's stack holds, from its saved SP upwards:
 * D2-D7/A2-A6 (44 bytes), SR (2 bytes), the return address into whoever
 * called k_arch_switch; see switch.S.
 */
#ifndef K_ARCH_CTX_H
#define K_ARCH_CTX_H

#include <stdint.h>

struct k_arch_context {
    uint32_t sp; /* offset 0: switch.S relies on it */
};

#define K_ARCH_INLINE_IRQ 1

/* Raises the mask to 7 and returns the old mask bits (SR & 0x0700). */
static inline uint32_t k_arch_irq_save(void)
{
    uint16_t sr;
    __asm__ __volatile__("move.w %%sr,%0\n\tori.w #0x0700,%%sr" : "=d"(sr) : : "memory", "cc");
    return (uint32_t)(sr & 0x0700u);
}

/* Restores only the mask bits, so 0 means "all interrupts enabled" and the
 * supervisor bit can never be dropped by a bad argument. */
static inline void k_arch_irq_restore(uint32_t state)
{
    uint16_t sr;
    __asm__ __volatile__("move.w %%sr,%0" : "=d"(sr));
    sr = (uint16_t)((sr & 0xF8FFu) | (state & 0x0700u));
    __asm__ __volatile__("move.w %0,%%sr" : : "d"(sr) : "memory", "cc");
}

#endif /* K_ARCH_CTX_H */
