/* The part of the board interface (boards/include/board.h) that is the same
 * on every ARMv7-M board (boards/stm32f405, boards/mps2-an385): halting on
 * the port, and switching off through semihosting. */
#include "boards/include/board.h"

#include "armv7m.h"

void board_halt(const char *image, const char *why)
{
    board_say(image, why);
    armv7m_halt();
}

/* ARM semihosting SYS_EXIT (ADP_Stopped_ApplicationExit): QEMU, started with
 * -semihosting-config enable=on (make run does), ends the emulation; a real
 * board without a debugger attached would fault on the BKPT, so it only
 * comes after the message, and the fault handler halts. */
void board_power_off(const char *image, const char *why)
{
    board_say(image, why);
    {
        /* set after the call above, which is free to use r0 and r1 */
        register uint32_t op __asm__("r0") = 0x18u;       /* SYS_EXIT */
        register uint32_t arg __asm__("r1") = 0x20026u;   /* ADP_Stopped_ApplicationExit */
        __asm__ __volatile__("bkpt 0xab" : : "r"(op), "r"(arg) : "memory");
    }
    armv7m_halt();
}
