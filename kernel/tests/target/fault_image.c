/*
 * Test images that fault on purpose, one per FAULT_KIND (chosen at build
 * time by boards/robocube/board.mk):
 *   1 unmapped   long read from 0x400000, where nothing is mapped -> bus error
 *   2 flashwrite word write into the read-only flash               -> bus error
 *   3 illegal    the ILLEGAL opcode                                -> illegal instruction
 *   4 zerodivide DIVU.W by zero                                    -> zero divide
 * The faulting instruction carries the global label fault_instruction, so
 * the test can compare the reported PC with the symbol's address.
 */
#include <stdint.h>

#include "boards/robocube/duart_console.h"
#include "kernel/lib/kprintf.h"

#ifndef FAULT_KIND
#error "build with -DFAULT_KIND=1..4"
#endif

#define UNMAPPED_ADDRESS "0x400000"
#define FLASH_ADDRESS    "0xE00100"

extern const char fault_instruction[];

/* Startup checks: .data must arrive with its initial value (copied from
 * flash), .bss cleared, whatever the SRAM held before. */
static volatile uint32_t data_check = 0x5A17C0DEu;
static volatile uint32_t bss_check;

int main(void)
{
    console_init();
    kprintf("\nfault test %d: faulting instruction at 0x%08lx\n", FAULT_KIND,
            (unsigned long)(uintptr_t)fault_instruction);
    kprintf("startup: data_check=0x%08lx at %p, bss_check=0x%08lx at %p\n",
            (unsigned long)data_check, (const void *)&data_check, (unsigned long)bss_check,
            (const void *)&bss_check);
#if FAULT_KIND == 1
    __asm__ __volatile__(".globl fault_instruction\nfault_instruction:\n\t"
                         "move.l " UNMAPPED_ADDRESS ",%%d0" : : : "d0", "memory");
#elif FAULT_KIND == 2
    __asm__ __volatile__(".globl fault_instruction\nfault_instruction:\n\t"
                         "move.w #0x1234," FLASH_ADDRESS : : : "memory");
#elif FAULT_KIND == 3
    __asm__ __volatile__(".globl fault_instruction\nfault_instruction:\n\t"
                         "illegal" : : : "memory");
#elif FAULT_KIND == 4
    __asm__ __volatile__("moveq #0,%%d1\n\tmoveq #7,%%d0\n"
                         ".globl fault_instruction\nfault_instruction:\n\t"
                         "divu.w %%d1,%%d0" : : : "d0", "d1", "cc", "memory");
#else
#error "FAULT_KIND must be 1..4"
#endif
    kprintf("fault test %d: no exception was taken\n", FAULT_KIND);
    return 1;
}
