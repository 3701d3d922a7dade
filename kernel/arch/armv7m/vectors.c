/*
 * The vector table of every ARMv7-M board: the port's system handlers and
 * every NVIC line through the kernel's interrupt entry (a line nobody
 * registered counts as spurious: k_irq_dispatch). The board gives its number
 * of lines, ARMV7M_IRQ_LINES, in its compile flags (boards/NAME/board.mk),
 * and its linker script puts the .vectors section where its reset fetch
 * finds it (address 0, or memory the chip aliases there).
 */
#include <stdint.h>

#include "armv7m.h"

#ifndef ARMV7M_IRQ_LINES
#error "ARMV7M_IRQ_LINES: the board's number of NVIC lines (BOARD_NAME_CFLAGS in its board.mk)"
#endif

extern uint32_t __stack_top[];

const unsigned armv7m_irq_lines = ARMV7M_IRQ_LINES;

/* __extension__: the GNU range designator fills the NVIC entries. */
__extension__ __attribute__((section(".vectors"), used))
void (*const armv7m_vectors[16u + ARMV7M_IRQ_LINES])(void) = {
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
    [16 ... 16u + ARMV7M_IRQ_LINES - 1u] = k_arch_irq_entry,
};
