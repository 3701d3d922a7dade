/*
 * Fault test images of the ARMv7-M port (boards/stm32f405/tests/
 * test_stm32f405.py): each takes one kind of fault at the global label
 * fault_instruction, which the reporter must name as the stacked PC.
 *   1 unmapped  a load from an address nothing answers (BusFault, precise)
 *   2 undef     an undefined instruction (UsageFault)
 *   3 divzero   SDIV by zero with CCR.DIV_0_TRP set (UsageFault)
 *   4 thread    the load of 1 in a kernel thread: the frame is on its PSP
 */
#include <stdint.h>

#include "kernel.h"
#include "boards/include/board.h"
#include "kernel/lib/kprintf.h"

#ifndef FAULT_KIND
#error "build with -DFAULT_KIND=1..4"
#endif

/* Reserved in the STM32F405's memory map (between the peripherals and the
 * FSMC): QEMU maps nothing there. */
#define UNMAPPED_ADDRESS "0x5A000000"

extern const char fault_instruction[];
static volatile uint32_t data_check = 0x5A17C0DEu;
static volatile uint32_t bss_check;

static void take_fault(void)
{
#if FAULT_KIND == 1 || FAULT_KIND == 4
    __asm__ __volatile__("ldr r0, =" UNMAPPED_ADDRESS "\n"
                         ".globl fault_instruction\nfault_instruction:\n\t"
                         "ldr r0, [r0]" : : : "r0", "memory");
#elif FAULT_KIND == 2
    __asm__ __volatile__(".globl fault_instruction\nfault_instruction:\n\t"
                         "udf #0" : : : "memory");
#elif FAULT_KIND == 3
    __asm__ __volatile__("movs r0, #7\n\tmovs r1, #0\n"
                         ".globl fault_instruction\nfault_instruction:\n\t"
                         "sdiv r0, r0, r1" : : : "r0", "r1", "memory");
#else
#error "FAULT_KIND must be 1..4"
#endif
}

#if FAULT_KIND == 4
static struct k_thread thread;
K_STACK_DEFINE(thread_stack, 1024u);
static void *faulter(void *arg)
{
    (void)arg;
    k_printf("fault test 4: in thread '%s'\n", k_thread_self()->name);
    take_fault();
    k_printf("fault test 4: no exception was taken\n");
    return NULL;
}
#endif

int main(void)
{
    board_start("fault");
    kprintf("\nfault test %d: faulting instruction at 0x%08lx\n", FAULT_KIND,
            (unsigned long)(uintptr_t)fault_instruction);
    kprintf("startup: data_check=0x%08lx bss_check=0x%08lx\n", (unsigned long)data_check,
            (unsigned long)bss_check);
#if FAULT_KIND == 4
    (void)board_spawn(&thread, "faulter", faulter, NULL, thread_stack, sizeof thread_stack, 5);
    k_start();
#else
    take_fault();
    kprintf("fault test %d: no exception was taken\n", FAULT_KIND);
#endif
    return 1;
}
