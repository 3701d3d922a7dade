# The kernel's ARMv7-M port (any Cortex-M3 or M4): how every object for it is
# compiled, assembled and linked, and the port's sources. Read by the image
# pipeline (mk/image.mk) for each board whose BOARD_NAME_CPU is armv7m; the
# board names its core (BOARD_NAME_MCPU: cortex-m3, cortex-m4).
#
# Soft float: the port saves no FPU state (an M4F's FPU stays off), and the M3
# has none. -fno-tree-loop-distribute-patterns: no loop becomes a memset/memcpy
# call, which the reset code runs before .data and .bss exist.
CPU_armv7m_CFLAGS  := -std=c99 -mthumb -mfloat-abi=soft -Os -g -ffreestanding -Wall -Wextra -Wpedantic \
                      -Wconversion -Werror -ffunction-sections -fdata-sections \
                      -fno-tree-loop-distribute-patterns -MMD -MP -I$(ROOT)/kernel/arch/armv7m
CPU_armv7m_ASFLAGS := -mthumb -g -I$(ROOT)/kernel/arch/armv7m -MMD -MP
CPU_armv7m_LDFLAGS := -mthumb -mfloat-abi=soft -nostdlib -Wl,--gc-sections -Wl,--build-id=none \
                      -Wl,-z,noexecstack
# Linked once per board: the vector table (sized by the board's
# -DARMV7M_IRQ_LINES), the reset entry and the fault reporter.
CPU_armv7m_SOURCES := kernel/arch/armv7m/vectors.c kernel/arch/armv7m/start.c kernel/arch/armv7m/fault.c
# Compiled with the kernel, per image: the context switch, interrupt levels, the MPU guard.
CPU_armv7m_KERNEL_SOURCES := kernel/arch/armv7m/k_arch_armv7m.c kernel/arch/armv7m/switch.S
