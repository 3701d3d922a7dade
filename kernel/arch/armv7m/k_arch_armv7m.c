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
 * returns, and write-protected by the MPU (armv7m_mpu_start); the rest is
 * filled too, for the high-water mark. Aligned for the MPU region (and so
 * for the exception frames' 8 bytes). */
static uint32_t k_irq_stack[K_STACK_WORDS(K_IRQ_STACK_BYTES)] __attribute__((aligned(ARMV7M_GUARD_BYTES)));
#define K_IRQ_STACK_WORDS K_STACK_WORDS(K_IRQ_STACK_BYTES)
/* Read by the first switch (switch.S). */
extern uint32_t *const k_arch_irq_stack_top;
uint32_t *const k_arch_irq_stack_top = k_irq_stack + K_IRQ_STACK_WORDS;

static void (*volatile armv7m_tick_fn)(void);
/* SysTick wraps served, and clocks per wrap (reload + 1): armv7m_systick_cycles. */
static volatile uint32_t armv7m_systick_wraps;
static uint32_t armv7m_systick_period;

/* Initial frame, from the lowest address: BASEPRI, R4-R11 (the software
 * frame switch.S pops), then R0-R3, R12, LR, PC, xPSR (the exception
 * frame). The thread starts in k_arch_thread_trampoline with BASEPRI at the
 * kernel mask: k_thread_start is entered with interrupts disabled. */
#define FRAME_WORDS (9u + 8u)

/* ---- the MPU's stack guards ----
 * Two regions of 32 bytes, read-only: the interrupt stack's lowest bytes
 * (region 6) and the running thread's (region 7, moved by every switch:
 * switch.S writes the thread's guard_rbar). The kernel still reads the
 * guard words (its own check, the high-water mark); a push into them faults
 * at once (MemManage), before anything below the stack is touched. Stacks
 * start on a 32-byte boundary (K_ARCH_STACK_ALIGN), so a thread's region
 * is its 16 bytes of guard words and the 16 above them. Everything else
 * keeps the default memory map (PRIVDEFENA). */
static uintptr_t guard_base(const uint32_t *stack_base)
{
    return ((uintptr_t)stack_base + ARMV7M_GUARD_BYTES - 1u) & ~(uintptr_t)(ARMV7M_GUARD_BYTES - 1u);
}

static uint32_t guard_rbar(const uint32_t *stack_base, unsigned region)
{
    return (uint32_t)guard_base(stack_base) | MPU_RBAR_VALID | region;
}

int armv7m_in_guard(uintptr_t addr, const uint32_t *stack_base)
{
    uintptr_t g = guard_base(stack_base);
    return stack_base != NULL && addr >= g && addr < g + ARMV7M_GUARD_BYTES;
}

/* Whether the CPU's 8-word frame, stacked at sp or below it (a failed
 * stacking may or may not have moved SP), meets the guard. */
static int frame_meets_guard(uintptr_t sp, const uint32_t *stack_base)
{
    uintptr_t g = guard_base(stack_base);
    return stack_base != NULL && sp + 32u > g && sp < g + 2u * ARMV7M_GUARD_BYTES;
}

void armv7m_mpu_start(void)
{
    const uint32_t rasr = MPU_RASR_ENABLE | MPU_RASR_SIZE(ARMV7M_GUARD_LOG2) | MPU_RASR_AP_RO |
                          MPU_RASR_XN;
    if ((MPU_TYPE >> 8 & 0xFFu) < 8u)
        return; /* no MPU with regions 6 and 7: the guard words alone */
    MPU_RBAR = guard_rbar(k_irq_stack, ARMV7M_MPU_REGION_IRQ);
    MPU_RASR = rasr;
    /* the thread region guards the interrupt stack too until the first switch */
    MPU_RBAR = guard_rbar(k_irq_stack, ARMV7M_MPU_REGION_THREAD);
    MPU_RASR = rasr;
    MPU_CTRL = MPU_CTRL_ENABLE | MPU_CTRL_PRIVDEFENA;
    __asm__ __volatile__("dsb\n\tisb" : : : "memory");
}

/* A fault from thread mode (armv7m_fault): a write into the running
 * thread's guard, or the CPU's failed stacking of its frame there, outside
 * a critical section, stops that thread. Its stack is given up, so the
 * frame it returns to is built at its top: k_stack_overflow_stop_current,
 * in thread mode, stops it the kernel's way and switches away. */
int armv7m_guard_fault(uint32_t exc_return, uint32_t cfsr)
{
    struct k_thread *t = k_arch_running;
    uint32_t basepri, psp, *frame;
    int hit;
    __asm__ __volatile__("mrs %0, basepri\n\tmrs %1, psp" : "=r"(basepri), "=r"(psp));
    if ((exc_return & 4u) == 0u || t == NULL || basepri != 0u)
        return 0;
    hit = ((cfsr & (CFSR_DACCVIOL | CFSR_MMARVALID)) == (CFSR_DACCVIOL | CFSR_MMARVALID) &&
           armv7m_in_guard(SCB_MMFAR, t->stack_base)) ||
          ((cfsr & CFSR_MSTKERR) != 0u && frame_meets_guard(psp, t->stack_base));
    if (!hit)
        return 0;
    SCB_CFSR = cfsr & 0xFFu; /* the MemManage bits: taken care of */
    frame = (uint32_t *)((uintptr_t)(t->stack_base + t->stack_words) & ~(uintptr_t)7u) - 8u;
    frame[0] = frame[1] = frame[2] = frame[3] = frame[4] = 0u;         /* R0-R3, R12 */
    frame[5] = (uint32_t)(uintptr_t)armv7m_halt;                         /* LR */
    frame[6] = (uint32_t)(uintptr_t)k_stack_overflow_stop_current & ~1u; /* PC */
    frame[7] = 0x01000000u;                                              /* xPSR: Thumb */
    __asm__ __volatile__("msr psp, %0" : : "r"(frame) : "memory");
    return 1;
}
void k_arch_thread_init(struct k_thread *t)
{
    uintptr_t top = (uintptr_t)(t->stack_base + t->stack_words) & ~(uintptr_t)7u;
    uint32_t *sp = (uint32_t *)top - FRAME_WORDS;
    unsigned i;
    /* k_init creates the idle thread before any interrupt can be taken
     * (BASEPRI masks them from reset to the first thread): the interrupt
     * stack gets its guard and fill then, once. */
    if (k_irq_stack[0] != K_STACK_GUARD) {
        for (i = 0; i < K_IRQ_STACK_WORDS; i++)
            k_irq_stack[i] = K_STACK_GUARD;
        armv7m_mpu_start();
    }
    t->ctx.guard_rbar = guard_rbar(t->stack_base, ARMV7M_MPU_REGION_THREAD);
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
    armv7m_systick_wraps++; /* before fn: the kernel's tick may read the time */
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
    armv7m_systick_wraps = 0;
    armv7m_systick_period = reload + 1u;
    SCB_SHPR(ARMV7M_EXC_SYSTICK) = K_ARCH_LEVEL_PRIO(ARMV7M_TICK_LEVEL);
    SYST_CSR = 0;
    SYST_RVR = reload;
    SYST_CVR = 0;
    SYST_CSR = SYST_CSR_CLKSOURCE | SYST_CSR_TICKINT | SYST_CSR_ENABLE;
    return 0;
}

uint32_t armv7m_systick_cycles(void)
{
    uint32_t irq = k_arch_irq_save(); /* masks SysTick (level 4) */
    uint32_t wraps = armv7m_systick_wraps;
    uint32_t count = SYST_CVR;
    /* A wrap whose interrupt waits (pending, masked): the count read may be
     * from before it or after; the one read now is after it. A wrap after
     * the pending bit was read leaves the first count from before it. */
    if ((SCB_ICSR & ICSR_PENDSTSET) != 0u) {
        count = SYST_CVR;
        wraps++;
    }
    k_arch_irq_restore(irq);
    return wraps * armv7m_systick_period + (armv7m_systick_period - 1u - count);
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
