/*
 * Vector table of the MPS2 AN385 (Cortex-M3): the system handlers of the
 * ARMv7-M port and the 32 NVIC lines through the kernel's interrupt entry (a
 * line nobody registered counts as spurious: k_irq_dispatch). At 0, the
 * start of ZBT SSRAM1, where the core fetches the reset vector.
 */
#include <stdint.h>

#include "armv7m.h"
#include "mps2_an385.h"

extern uint32_t __stack_top[];

const unsigned armv7m_irq_lines = MPS2_AN385_IRQ_LINES;

/* __extension__: the GNU range designator fills the NVIC entries. */
__extension__ __attribute__((section(".vectors"), used))
void (*const armv7m_vectors[16u + MPS2_AN385_IRQ_LINES])(void) = {
    [0] = (void (*)(void))(uintptr_t)__stack_top,
    [1] = armv7m_reset,
    [2] = armv7m_fault,             /* NMI: nothing raises it; reported if it comes */
    [ARMV7M_EXC_HARDFAULT] = armv7m_fault,
    [ARMV7M_EXC_MEMMANAGE] = armv7m_fault,
    [ARMV7M_EXC_BUSFAULT] = armv7m_fault,
    [ARMV7M_EXC_USAGEFAULT] = armv7m_fault,
    [7] = armv7m_fault, [8] = armv7m_fault, [9] = armv7m_fault, [10] = armv7m_fault,
    [ARMV7M_EXC_SVC] = armv7m_svc,
    [12] = armv7m_fault, [13] = armv7m_fault,
    [ARMV7M_EXC_PENDSV] = armv7m_pendsv,
    [ARMV7M_EXC_SYSTICK] = armv7m_systick,
    [16 ... 16u + MPS2_AN385_IRQ_LINES - 1u] = k_arch_irq_entry,
};
