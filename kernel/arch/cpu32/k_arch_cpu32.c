/*
 * CPU32 port of the nanokernel (with switch.S): thread stacks, idle, and
 * routing vectors to the kernel's interrupt entry.
 *
 * The firmware's vector table lives in flash (start.S), where drivers claim
 * vectors at link time. The kernel needs to route vectors at run time
 * (k_irq_register), so on the first registration it copies the table to
 * RAM, points VBR at the copy and patches the copy: every vector nobody
 * registers keeps its original flash handler (the fault reporter, the PIT).
 */
#include "k_internal.h"
#include "cpu.h"

extern void k_arch_thread_trampoline(void);
extern void k_isr_entry(void);

/* The 68k requires the table on a word boundary; 4 keeps the longs aligned. */
static void (*k_vector_ram[256])(void) __attribute__((aligned(4)));
static int k_vector_ram_active;

void k_arch_thread_init(struct k_thread *t)
{
    uint32_t *top = t->stack_base + t->stack_words;
    uint16_t *sp16;
    uint32_t *sp32;
    unsigned i;

    *--top = (uint32_t)(uintptr_t)k_arch_thread_trampoline; /* rts target */
    sp16 = (uint16_t *)(void *)top;
    *--sp16 = 0x2700u;                                    /* SR: supervisor, mask 7 */
    sp32 = (uint32_t *)(void *)sp16;
    for (i = 0; i < 11u; i++)                             /* D2-D7, A2-A6 */
        *--sp32 = 0;
    t->ctx.sp = (uint32_t)(uintptr_t)sp32;
}

void k_arch_idle(void)
{
    /* STOP lowers the mask to 0 and waits; an interrupt that made a thread
     * ready switches away from the idle thread in k_isr_exit. */
    cpu32_wait_for_interrupt();
}

int k_arch_irq_route(unsigned vector)
{
    /* The table's address goes through an address register (the empty asm)
     * so GCC indexes it as (0,An,Dn*4), a brief extension word, instead of
     * (table,Dn*4) with a suppressed base: the CPU32 has that full format
     * too, but the QEMU model did not accept it when this was written. */
    void (**ram)(void) = k_vector_ram;
    __asm__("" : "+a"(ram));
    if (!k_vector_ram_active) {
        void (**flash)(void);
        unsigned i;
        __asm__ __volatile__("movec %%vbr,%0" : "=a"(flash));
        for (i = 0; i < 256u; i++)
            ram[i] = flash[i];
        __asm__ __volatile__("movec %0,%%vbr" : : "a"(ram) : "memory");
        k_vector_ram_active = 1;
    }
    ram[vector & 0xFFu] = k_isr_entry;
    return K_OK;
}
