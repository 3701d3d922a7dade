/*
 * ARMv7-M port of the nanokernel (with switch.S): thread frames, the
 * interrupt entry and the interrupt stack, NVIC routing, the SysTick tick,
 * idle and halt, and the reset entry.
 *
 * Interrupts: every NVIC line's vector points at k_arch_irq_entry, which
 * runs the registered handler between k_isr_enter and k_isr_exit. The NVIC
 * nests by priority (kernel level L gets priority (8 - L) << 4, so a more
 * urgent level pre-empts a less urgent handler) on the main stack, which is
 * the port's interrupt stack: threads carry only the 32-byte frame the CPU
 * stacks on entry. A thread woken by a handler runs once the last nested
 * handler has returned (PendSV, switch.S).
 */
#include "k_internal.h"
#include "armv7m.h"

extern void k_arch_thread_trampoline(void);

/* The thread whose registers are in the CPU, and the one to run next (switch.S). */
struct k_thread *volatile k_arch_running;
struct k_thread *volatile k_arch_next;

/* The interrupt stack (MSP once the first thread runs). Guard words at its
 * low end like a thread stack's, the topmost checked whenever a handler
 * returns; the rest is filled too, for the high-water mark. 8-byte aligned
 * for the exception frames (AAPCS). */
static uint32_t k_irq_stack[K_STACK_WORDS(K_IRQ_STACK_BYTES)] __attribute__((aligned(8)));
#define K_IRQ_STACK_WORDS K_STACK_WORDS(K_IRQ_STACK_BYTES)
/* Read by the first switch (switch.S). */
extern uint32_t *const k_arch_irq_stack_top;
uint32_t *const k_arch_irq_stack_top = k_irq_stack + K_IRQ_STACK_WORDS;

static void (*volatile armv7m_tick_fn)(void);

/* Initial frame, from the lowest address: BASEPRI, R4-R11 (the software
 * frame switch.S pops), then R0-R3, R12, LR, PC, xPSR (the exception
 * frame). The thread starts in k_arch_thread_trampoline with BASEPRI at the
 * kernel mask: k_thread_start is entered with interrupts disabled. */
#define FRAME_WORDS (9u + 8u)
void k_arch_thread_init(struct k_thread *t)
{
    uintptr_t top = (uintptr_t)(t->stack_base + t->stack_words) & ~(uintptr_t)7u;
    uint32_t *sp = (uint32_t *)top - FRAME_WORDS;
    unsigned i;
    /* k_init creates the idle thread before any interrupt can be taken
     * (BASEPRI masks them from reset to the first thread): the interrupt
     * stack gets its guard and fill then, once. */
    if (k_irq_stack[0] != K_STACK_GUARD)
        for (i = 0; i < K_IRQ_STACK_WORDS; i++)
            k_irq_stack[i] = K_STACK_GUARD;
    for (i = 0; i < FRAME_WORDS; i++)
        sp[i] = 0;
    sp[0] = K_ARCH_BASEPRI_MASK;
    sp[9 + 5] = (uint32_t)(uintptr_t)armv7m_halt;                  /* LR */
    sp[9 + 6] = (uint32_t)(uintptr_t)k_arch_thread_trampoline & ~1u; /* PC */
    sp[9 + 7] = 0x01000000u;                                          /* xPSR: Thumb */
    t->ctx.sp = (uint32_t)(uintptr_t)sp;
}

/* The topmost guard word is the first one an overflowing interrupt path
 * writes: one compare at every handler's return. */
static void k_arch_irq_stack_check(void)
{
    if (k_irq_stack[K_STACK_GUARD_WORDS - 1u] != K_STACK_GUARD) {
        static const char msg[] = "kernel: interrupt stack overflow: halted\n";
        k_console_write_sync(msg, sizeof msg - 1u);
        k_arch_halt();
    }
}

void k_arch_irq_entry(void)
{
    uint32_t ipsr;
    __asm__ __volatile__("mrs %0, ipsr" : "=r"(ipsr));
    k_isr_run(ARMV7M_IRQ_VECTOR((ipsr & 0x1FFu) - ARMV7M_EXC_IRQ0));
    k_arch_irq_stack_check();
}

void k_isr_call(void (*fn)(void *arg), void *arg)
{
    k_isr_enter();
    fn(arg);
    k_isr_exit();
    k_arch_irq_stack_check();
}

void armv7m_systick(void)
{
    void (*fn)(void) = armv7m_tick_fn;
    k_isr_enter();
    if (fn != NULL)
        fn();
    k_isr_exit();
    k_arch_irq_stack_check();
}

int armv7m_systick_start(uint32_t cpu_hz, uint32_t tick_hz, void (*fn)(void))
{
    uint32_t reload;
    if (tick_hz == 0u || fn == NULL)
        return -1;
    /* The nearest whole count: 168 MHz / 1024 Hz is 164062.5, so the tick
     * runs at 1023.997 Hz there (-3 ppm, well inside a crystal's tolerance). */
    reload = (cpu_hz + tick_hz / 2u) / tick_hz - 1u;
    if (reload == 0u || reload > SYST_RVR_MAX)
        return -1;
    armv7m_tick_fn = fn;
    SCB_SHPR(ARMV7M_EXC_SYSTICK) = K_ARCH_LEVEL_PRIO(ARMV7M_TICK_LEVEL);
    SYST_CSR = 0;
    SYST_RVR = reload;
    SYST_CVR = 0;
    SYST_CSR = SYST_CSR_CLKSOURCE | SYST_CSR_TICKINT | SYST_CSR_ENABLE;
    return 0;
}

const uint32_t *k_arch_irq_stack(size_t *words)
{
    *words = K_IRQ_STACK_WORDS;
    return k_irq_stack;
}

void k_arch_halt(void)
{
    armv7m_halt();
}

void k_arch_idle(void)
{
    /* Called with interrupts enabled: WFI returns after the handler of the
     * interrupt that woke it, and a thread it made ready has already been
     * switched to by PendSV on the way out. */
    __asm__ __volatile__("dsb\n\twfi" : : : "memory");
}

/* k_irq_register has stored the handler and its level: the line gets the
 * level's priority and is enabled. */
int k_arch_irq_route(unsigned vector)
{
    unsigned irq = ARMV7M_VECTOR_IRQ(vector);
    if (vector < 64u || irq >= armv7m_irq_lines)
        return K_EINVAL;
    NVIC_IPR(irq) = K_ARCH_LEVEL_PRIO(k_irq_level(vector));
    NVIC_ISER(irq / 32u) = 1u << (irq % 32u);
    return K_OK;
}
