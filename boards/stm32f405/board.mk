# The STM32F405 (Cortex-M4, 168 MHz; QEMU's netduinoplus2 in Debian's
# qemu-system-arm): what the image pipeline (mk/image.mk) needs to build and
# boot any image on it. Only the variables every board declares
# (boards/README.md); its suites are in tests/tests.mk.

BOARD_stm32f405_CPU     := armv7m
BOARD_stm32f405_MCPU    := cortex-m4
BOARD_stm32f405_CROSS   := arm-none-eabi-
# Debian's newlib for arm-none-eabi (ci/setup.d/arm.sh), the headers this
# folder's sources include by their bare names, and the NVIC lines the port's
# vector table has (RM0090 table 61: IRQ 0..81).
BOARD_stm32f405_CFLAGS  := -isystem /usr/lib/arm-none-eabi/include -I$(ROOT)/boards/stm32f405 \
                           -DARMV7M_IRQ_LINES=82u
# Everything it links once is the port's (kernel/arch/armv7m/port.mk).
BOARD_stm32f405_SOURCES :=
# The kernel's board hooks: console on USART1, the tick on SysTick.
BOARD_stm32f405_KERNEL_SOURCES := boards/stm32f405/k_board_stm32f405.c
BOARD_stm32f405_LIB_SOURCES := boards/stm32f405/board.c boards/stm32f405/ports.c boards/common/board_common.c \
                               boards/common/board_armv7m.c
# PDL reaches the ports through the board's own port access (ports.c).
BOARD_stm32f405_PDL_PORTS := pdl/ports/board.c
BOARD_stm32f405_LDSCRIPT := boards/stm32f405/stm32f405.ld
# newlib's libc and libm for the core's multilib (thumb/v7e-m/nofp), and GCC's runtime.
BOARD_stm32f405_LIBS    := -lc -lm
BOARD_stm32f405_RUNTIME := -lgcc
BOARD_stm32f405_IMAGE_FORMAT := binary
BOARD_stm32f405_SETUP   := arm
BOARD_stm32f405_QEMU    := qemu-system-arm
BOARD_stm32f405_QEMU_MACHINE := netduinoplus2
# Semihosting lets an image end the run (board_power_off: the shell's exit).
BOARD_stm32f405_QEMU_ARGS := -semihosting-config enable=on,target=native
BOARD_stm32f405_CONSOLE := USART1
# Virtual time from the instruction count alone, as on the RoboCube:
# 2^3 ns = 8 ns per instruction (125 MIPS, an assumed average for a 168 MHz
# Cortex-M4, not measured), so SysTick (counting the 168 MHz clock) and the
# program advance in a fixed ratio and runs repeat exactly.
BOARD_stm32f405_ICOUNT  := shift=3,sleep=off
# Its ports are ADC, PWM and the LED, the rest simulated in RAM (README.md).
BOARD_stm32f405_CAPS    := console tick led ports libc posix
BOARD_stm32f405_BUILD   := $(BUILD)/stm32f405
