# The kernel's CPU32 port (MC68332): how every object for this CPU is compiled,
# assembled and linked, and the port's sources. Read by the image pipeline
# (mk/image.mk) for each board whose BOARD_NAME_CPU is cpu32.
#
# The C flags build on bsched's own cross-compile check (CROSS_CFLAGS,
# bsched/bsched.mk: C99, -mcpu=cpu32, -Os, freestanding, the warnings as
# errors), so the library is checked with the flags the firmware uses.
# -fno-store-merging: GCC 12 merged adjacent byte stores into a word store at
# an odd address (an address error on the CPU32, which has no misaligned
# access; it did so in net/ and for two byte fields of struct k_thread).
# -fno-tree-loop-distribute-patterns: no loop becomes a memset/memcpy call,
# which start-up code runs before the C library may be called.
CPU_cpu32_CFLAGS  := $(CROSS_CFLAGS) -g -fno-tree-loop-distribute-patterns -fno-store-merging \
                     -ffunction-sections -fdata-sections -MMD -MP -I$(ROOT)/kernel/arch/cpu32
CPU_cpu32_ASFLAGS := -g -I$(ROOT)/kernel/arch/cpu32 -MMD -MP
CPU_cpu32_LDFLAGS := -nostdlib -Wl,--gc-sections -Wl,--build-id=none
# Linked once per board: the exception vectors' fault reporter.
CPU_cpu32_SOURCES := kernel/arch/cpu32/exceptions.c
# Compiled with the kernel, per image: the context switch and interrupt levels.
CPU_cpu32_KERNEL_SOURCES := kernel/arch/cpu32/k_arch_cpu32.c kernel/arch/cpu32/switch.S
