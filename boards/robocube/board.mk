# The RoboCube (MC68332 / CPU32, on the QEMU board model built from emu/):
# what the image pipeline (mk/image.mk) needs to build and boot any image on
# it. Only the variables every board declares (boards/README.md); the rules
# are mk/image.mk's, the images apps/NAME/'s.

# The kernel's CPU port (kernel/arch/cpu32/port.mk: its compiler flags) and the toolchain.
BOARD_robocube_CPU      := cpu32
BOARD_robocube_MCPU     := cpu32
BOARD_robocube_CROSS    := m68k-linux-gnu-
# The C library's headers (newlib, built for the CPU32 by ci/setup.d/m68k/newlib.sh).
BOARD_robocube_CFLAGS   := -isystem $(NEWLIB)/include
# Start-up, the polled console and the PIT: every image links them.
BOARD_robocube_SOURCES  := boards/robocube/start.S boards/robocube/duart_console.c boards/robocube/pit.c
# The kernel's board hooks (kernel/include/k_board.h): PIT tick, interrupt-driven
# console; compiled with the kernel at each image's tick rate.
BOARD_robocube_KERNEL_SOURCES := boards/robocube/k_board_robocube.c
# The board interface (boards/include/): start-up, LED, port table, the DUART's radio channel.
BOARD_robocube_LIB_SOURCES := boards/robocube/board.c boards/robocube/led.c boards/robocube/ports.c \
                              boards/robocube/radio.c boards/common/board_common.c
# PDL reaches this board's ports through its drivers (the sampler, the uniform access layer).
BOARD_robocube_PDL_PORTS := pdl/ports/drivers.c
BOARD_robocube_LDSCRIPT := boards/robocube/robocube.ld
# newlib's libc and libm in the link group; the CPU32 compiler runtime after it
# (Debian's m68k libgcc is built for the 68020/68881 and traps on the CPU32).
BOARD_robocube_LIBS     := $(FW_LIBC_LIBS)
BOARD_robocube_RUNTIME  := $(CPU32_RT)
BOARD_robocube_IMAGE_FORMAT := srec
BOARD_robocube_SETUP    := m68k qemu
BOARD_robocube_QEMU     := $(QEMU_M68K)
BOARD_robocube_QEMU_MACHINE := robocube
BOARD_robocube_QEMU_ARGS :=
BOARD_robocube_CONSOLE  := DUART B
# Virtual time from the instruction count alone: 2^8 ns = 256 ns per
# instruction (4.3 clocks at 16.78 MHz, an assumed CPU32 average, not measured),
# so the PIT, the DUART timer and the program advance in a fixed ratio. With
# sleep=off an idle guest (STOP) jumps straight to its next timer instead of
# waiting for the wall clock: with sleep=on, idle spans followed the host's
# clock, so a loaded host stretched them (a late warp lands past the next
# deadline) and a minor cycle could overrun only because the machine was busy.
# Now a run gives the same output, tick for tick, on a loaded host as on an idle one.
BOARD_robocube_ICOUNT   := shift=8,sleep=off
# What it has (mk/image.mk lists every capability and what needs each).
BOARD_robocube_CAPS     := console tick led ports libc posix radio i2c tpu analog bio motors world
BOARD_robocube_BUILD    := $(BUILD)/firmware
