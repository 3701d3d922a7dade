/*
 * Vector table of the STM32F405 (RM0090 table 61): the system handlers of
 * the ARMv7-M port and all 82 NVIC lines through the kernel's interrupt
 * entry (a line nobody registered counts as spurious: k_irq_dispatch).
 * In flash at 0x08000000, which the chip aliases at 0 for the reset fetch.
 */
#include <stdint.h>

#include "armv7m.h"
#include "stm32f405.h"

extern uint32_t __stack_top[];

const unsigned armv7m_irq_lines = STM32F405_IRQ_LINES;



/* __extension__: the GNU range designator fills the 82 NVIC entries. */
__extension__ __attribute__((section(".vectors"), used))
void (*const armv7m_vectors[16u + STM32F405_IRQ_LINES])(void) = {
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
    [16 ... 16u + STM32F405_IRQ_LINES - 1u] = k_arch_irq_entry,
};
