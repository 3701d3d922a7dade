/*
 * CPU32 port of the nanokernel (with switch.S): thread stacks, idle, the
 * interrupt stack, and routing vectors to the kernel's interrupt entry.
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

/* The interrupt stack: k_isr_entry moves there at the outermost interrupt
 * (the CPU32 has a single supervisor stack pointer). Guard words at its low
 * end like a thread stack's, the topmost checked whenever a handler returns;
 * the rest is filled too, for the high-water mark. */
K_STACK_DEFINE(k_irq_stack, K_IRQ_STACK_BYTES);
#define K_IRQ_STACK_WORDS K_STACK_WORDS(K_IRQ_STACK_BYTES)
/* Read by k_isr_entry (switch.S). */
extern uint32_t *const k_arch_irq_stack_top;
uint32_t *const k_arch_irq_stack_top = k_irq_stack + K_IRQ_STACK_WORDS;

void k_arch_isr_run(unsigned vector, uint32_t sr);

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

/* Called by k_isr_entry on the interrupt stack with the mask at 7 and
 * isr_nesting already counting this interrupt: runs the handler at the
 * interrupt's own level (sr: the SR the CPU set on entry), so that only more
 * urgent levels nest, and returns with the mask at 7 again. */
void k_arch_isr_run(unsigned vector, uint32_t sr)
{
    k_arch_irq_restore(sr);
    k_irq_dispatch(vector);
    (void)k_arch_irq_save();
    /* It runs at every interrupt, so one compare: the topmost guard word is
     * the first one an overflowing interrupt path writes. */
    if (k_irq_stack[K_STACK_GUARD_WORDS - 1u] != K_STACK_GUARD) {
        static const char msg[] = "kernel: interrupt stack overflow: halted\n";
        k_console_write_sync(msg, sizeof msg - 1u);
        k_arch_halt();
    }
}

const uint32_t *k_arch_irq_stack(size_t *words)
{
    *words = K_IRQ_STACK_WORDS;
    return k_irq_stack;
}

void k_arch_halt(void)
{
    cpu32_halt();
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
        /* Before the first routed interrupt can be taken. */
        for (i = 0; i < K_IRQ_STACK_WORDS; i++)
            k_irq_stack[i] = K_STACK_GUARD;
        __asm__ __volatile__("movec %%vbr,%0" : "=a"(flash));
        for (i = 0; i < 256u; i++)
            ram[i] = flash[i];
        __asm__ __volatile__("movec %0,%%vbr" : : "a"(ram) : "memory");
        k_vector_ram_active = 1;
    }
    ram[vector & 0xFFu] = k_isr_entry;
    return K_OK;
}
