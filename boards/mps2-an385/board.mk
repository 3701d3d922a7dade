# ARM's MPS2 board with the AN385 image (Cortex-M3, 25 MHz; QEMU's mps2-an385
# in Debian's qemu-system-arm): what the image pipeline (mk/image.mk) needs to
# build and boot any image on it. Only the variables every board declares
# (boards/README.md).

BOARD_mps2-an385_CPU     := armv7m
BOARD_mps2-an385_MCPU    := cortex-m3
BOARD_mps2-an385_CROSS   := arm-none-eabi-
# Debian's newlib for arm-none-eabi (ci/setup.d/arm.sh), the headers this
# folder's sources include by their bare names, and the NVIC lines the port's
# vector table has (QEMU gives the AN385's Cortex-M3 32).
BOARD_mps2-an385_CFLAGS  := -isystem /usr/lib/arm-none-eabi/include -I$(ROOT)/boards/mps2-an385 \
                            -DARMV7M_IRQ_LINES=32u
# Everything it links once is the port's (kernel/arch/armv7m/port.mk).
BOARD_mps2-an385_SOURCES :=
# The kernel's board hooks: console on UART0, the tick on SysTick.
BOARD_mps2-an385_KERNEL_SOURCES := boards/mps2-an385/k_board_mps2_an385.c
BOARD_mps2-an385_LIB_SOURCES := boards/mps2-an385/board.c boards/mps2-an385/ports.c boards/common/board_common.c \
                                boards/common/board_armv7m.c
# PDL reaches the ports (the LED alone) through the board's own port access (ports.c).
BOARD_mps2-an385_PDL_PORTS := pdl/ports/board.c
BOARD_mps2-an385_LDSCRIPT := boards/mps2-an385/mps2-an385.ld
# newlib's libc and libm for the core's multilib (thumb/v7-m/nofp), and GCC's runtime.
BOARD_mps2-an385_LIBS    := -lc -lm
BOARD_mps2-an385_RUNTIME := -lgcc
BOARD_mps2-an385_IMAGE_FORMAT := binary
BOARD_mps2-an385_SETUP   := arm
BOARD_mps2-an385_QEMU    := qemu-system-arm
BOARD_mps2-an385_QEMU_MACHINE := mps2-an385
# Semihosting lets an image end the run (board_power_off).
BOARD_mps2-an385_QEMU_ARGS := -semihosting-config enable=on,target=native
BOARD_mps2-an385_CONSOLE := UART0
# Virtual time from the instruction count alone: 2^6 ns = 64 ns per
# instruction (15.6 MIPS, an assumed average for a 25 MHz Cortex-M3, not
# measured), so SysTick and the program advance in a fixed ratio.
BOARD_mps2-an385_ICOUNT  := shift=6,sleep=off
# Its port table has the LED alone (ports.c); no I/O board, no radio.
BOARD_mps2-an385_CAPS    := console tick led ports libc posix
BOARD_mps2-an385_BUILD   := $(BUILD)/mps2-an385
