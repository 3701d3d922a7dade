/*
 * Reset entry of the ARMv7-M firmware. The board's vector table (boards/NAME/)
 * gives the initial MSP (the top of SRAM: the boot stack, used until the
 * first thread runs) and this function as the reset vector.
 */
#include <stdint.h>

#include "k_arch_ctx.h"
#include "armv7m.h"

extern uint32_t __data_load[], __data_start[], __data_end[], __bss_start[], __bss_end[];

/* The C entry: an image whose main starts the board itself (board_start ...
 * k_start) is entered at main; an image that links drivers/board_main.c
 * gets that file's firmware_entry, which runs main as a thread. */
int main(void);
void firmware_entry(void) __attribute__((weak));
void firmware_entry(void)
{
    (void)main();
}

void armv7m_reset(void)
{
    /* volatile: the copy loops must not become calls to memcpy/memset,
     * which would run before .data and .bss exist. */
    volatile uint32_t *src = __data_load, *dst = __data_start;
    while (dst < __data_end)
        *dst++ = *src++;
    for (dst = __bss_start; dst < __bss_end;)
        *dst++ = 0;

    /* Kernel levels masked until the first thread runs (k_thread_start
     * unmasks), as the CPU32 leaves reset with its mask at 7. */
    (void)k_arch_irq_save();
    SCB_VTOR = (uint32_t)(uintptr_t)armv7m_vectors;
    SCB_SHPR(ARMV7M_EXC_SVC) = 0x00u;      /* above BASEPRI: switches inside critical sections */
    SCB_SHPR(ARMV7M_EXC_PENDSV) = 0xF0u;   /* below every kernel level */
    SCB_SHCSR |= SHCSR_MEMFAULTENA | SHCSR_BUSFAULTENA | SHCSR_USGFAULTENA;
    SCB_CCR |= CCR_DIV_0_TRP | CCR_STKALIGN;
    __asm__ __volatile__("dsb\n\tisb" : : : "memory");
    firmware_entry();
    armv7m_halt();
}
