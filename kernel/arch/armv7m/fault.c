/*
 * Fault reporter: HardFault, MemManage, BusFault and UsageFault end here
 * (armv7m_fault in switch.S). Prints one summary line that tests parse, the
 * fault status registers decoded, the stacked frame and R4-R11, then halts.
 *
 * Summary line (fixed format):
 *   EXCEPTION vector=<n> (<name>) pc=0x<8 hex> xpsr=0x<8 hex> lr=0x<8 hex> cfsr=0x<8 hex> hfsr=0x<8 hex>
 * pc is the stacked return address: for a precise fault the faulting
 * instruction itself.
 */
#include "k_internal.h"
#include "armv7m.h"
#include "kernel/lib/kprintf.h"

extern struct k_thread *volatile k_arch_running;

static const char *const exc_names[] = {
    "thread", "reset", "NMI", "HardFault", "MemManage", "BusFault", "UsageFault",
};

/* CFSR bits (ARMv7-M ARM B3.2.15): MMFSR 7..0, BFSR 15..8, UFSR 31..16. */
static const struct {
    uint32_t bit;
    const char *what;
} cfsr_bits[] = {
    {1u << 0, "instruction access violation (MPU)"},
    {1u << 1, "data access violation (MPU)"},
    {1u << 3, "MemManage on exception return unstacking"},
    {1u << 4, "MemManage on exception entry stacking (stack overflow)"},
    {1u << 8, "instruction bus error"},
    {1u << 9, "precise data bus error"},
    {1u << 10, "imprecise data bus error"},
    {1u << 11, "BusFault on unstacking"},
    {1u << 12, "BusFault on stacking"},
    {1u << 16, "undefined instruction"},
    {1u << 17, "invalid state (Thumb bit clear)"},
    {1u << 18, "invalid PC load on exception return"},
    {1u << 19, "no coprocessor"},
    {1u << 24, "unaligned access"},
    {1u << 25, "divide by zero"},
};

void armv7m_fault_report(const struct armv7m_frame *frame, const struct armv7m_fault_regs *regs)
{
    uint32_t ipsr, cfsr = SCB_CFSR, hfsr = SCB_HFSR;
    unsigned exc, i;
    static volatile int reporting;
    __asm__ __volatile__("mrs %0, ipsr" : "=r"(ipsr));
    exc = ipsr & 0x1FFu;
    /* A fault inside the reporter (a broken console, say) must not recurse. */
    if (reporting)
        armv7m_halt();
    reporting = 1;

    kprintf("\n*** EXCEPTION vector=%u (%s) pc=0x%08lx xpsr=0x%08lx lr=0x%08lx cfsr=0x%08lx "
            "hfsr=0x%08lx\n",
            exc, exc < sizeof exc_names / sizeof exc_names[0] ? exc_names[exc] : "unexpected",
            (unsigned long)frame->pc, (unsigned long)frame->xpsr, (unsigned long)frame->lr,
            (unsigned long)cfsr, (unsigned long)hfsr);
    if ((hfsr & (1u << 30)) != 0u)
        kprintf("  escalated to HardFault (forced)\n");
    for (i = 0; i < sizeof cfsr_bits / sizeof cfsr_bits[0]; i++)
        if ((cfsr & cfsr_bits[i].bit) != 0u)
            kprintf("  %s\n", cfsr_bits[i].what);
    if ((cfsr & (1u << 7)) != 0u)
        kprintf("  MemManage fault address 0x%08lx\n", (unsigned long)SCB_MMFAR);
    if ((cfsr & (CFSR_DACCVIOL | CFSR_MSTKERR)) != 0u) {
        /* a guard the thread could not be stopped at (a critical section,
         * an interrupt handler): which stack ran into it */
        uintptr_t at = (cfsr & CFSR_MMARVALID) != 0u ? SCB_MMFAR : (uintptr_t)frame;
        size_t words;
        const uint32_t *irq_stack = k_arch_irq_stack(&words);
        if (armv7m_in_guard(at, irq_stack) || armv7m_in_guard(at + 31u, irq_stack))
            kprintf("  stack overflow: the interrupt stack ran into its guard\n");
        else if (k_arch_running != NULL && (armv7m_in_guard(at, k_arch_running->stack_base) ||
                                            armv7m_in_guard(at + 31u, k_arch_running->stack_base)))
            kprintf("  stack overflow: thread '%s' ran into its guard\n",
                    k_arch_running->name != NULL ? k_arch_running->name : "?");
    }
    if ((cfsr & (1u << 15)) != 0u)
        kprintf("  BusFault address 0x%08lx\n", (unsigned long)SCB_BFAR);
    kprintf("  R0=%08lx  R1=%08lx  R2=%08lx  R3=%08lx\n", (unsigned long)frame->r0,
            (unsigned long)frame->r1, (unsigned long)frame->r2, (unsigned long)frame->r3);
    for (i = 0; i < 8u; i++)
        kprintf("  R%u=%08lx%s", i + 4u, (unsigned long)regs->r4_r11[i], i == 3u || i == 7u ? "\n" : "");
    kprintf("  R12=%08lx LR=%08lx (EXC_RETURN %08lx: %s stack)\n", (unsigned long)frame->r12,
            (unsigned long)frame->lr, (unsigned long)regs->exc_return,
            (regs->exc_return & 4u) != 0u ? "thread, process" : "main");
    /* The SP before the exception: just above the CPU's 8-word frame (plus
     * the alignment word when xPSR bit 9 says one was inserted). */
    kprintf("  SP=%08lx\n*** halted\n",
            (unsigned long)((uintptr_t)frame + 32u + ((frame->xpsr & (1u << 9)) != 0u ? 4u : 0u)));
    SCB_CFSR = cfsr; /* write-one-to-clear, for a debugger that resumes */
    armv7m_halt();
}
