# The STM32F405 board (QEMU netduinoplus2): the ARMv7-M port of the kernel
# (kernel/arch/armv7m), this folder's board support, and the firmware images
# that need nothing of the RoboCube's hardware, built with Debian's
# arm-none-eabi GCC and picolibc (ci/setup.d/arm.sh).
#
#   make firmware BOARD=stm32f405 [APP=NAME]  build/stm32f405/NAME/NAME.elf (+ .bin, .map)
#   make run BOARD=stm32f405 [APP=NAME]       boot it on qemu-system-arm -M netduinoplus2
#   make check-stm32f405-kernel               the kernel target suite on this board
#   make check-stm32f405-firmware             table1 (Table 2) and the fault report
#
# An image builds for this board when its sources include none of the
# RoboCube's hardware headers (the drivers besides those below, the RoboCube's
# board folder, the CPU32 headers); otherwise make says which it needs and stops.

STM32_BUILD   := $(BUILD)/stm32f405
ARM_CC        ?= arm-none-eabi-gcc
ARM_SIZE      ?= arm-none-eabi-size
ARM_OBJCOPY   ?= arm-none-eabi-objcopy
QEMU_ARM      ?= qemu-system-arm
STM32_MACHINE := netduinoplus2
STM32_ARCH_FLAGS := -mcpu=cortex-m4 -mthumb -mfloat-abi=soft
STM32_CFLAGS  := -std=c99 $(STM32_ARCH_FLAGS) -Os -g -ffreestanding -Wall -Wextra -Wpedantic \
                 -Wconversion -Werror -ffunction-sections -fdata-sections \
                 -fno-tree-loop-distribute-patterns -MMD -MP --specs=picolibc.specs \
                 -I$(ROOT) -I$(ROOT)/kernel/include -I$(ROOT)/kernel -I$(ROOT)/kernel/arch/armv7m \
                 -I$(ROOT)/boards/stm32f405 -I$(ROOT)/bsched -DBSCHED_MAX_PROCS=$(FW_MAX_PROCS)
STM32_LDSCRIPT := boards/stm32f405/stm32f405.ld
STM32_LDFLAGS := $(STM32_ARCH_FLAGS) --specs=picolibc.specs -nostartfiles -T $(STM32_LDSCRIPT) \
                 -Wl,--gc-sections -Wl,--build-id=none -Wl,-z,noexecstack
# Virtual time from the instruction count alone, as on the RoboCube:
# 2^3 ns = 8 ns per instruction (125 MIPS, an assumed average for a 168 MHz
# Cortex-M4, not measured), so SysTick (counting the 168 MHz clock) and the
# program advance in a fixed ratio and runs repeat exactly.
STM32_ICOUNT  := shift=3,sleep=off
# The console is USART1 on stdio; semihosting lets an image end the run
# (board_power_off: the shell's exit).
STM32_QEMU_ARGS := -M $(STM32_MACHINE) -display none -monitor none -serial stdio \
                   -semihosting-config enable=on,target=native

# The drivers that need nothing of the RoboCube: console line input and the
# command parser (an image links only what it calls: --gc-sections).
STM32_DRIVER_SRCS := drivers/console_in.c drivers/line_edit.c \
                     drivers/cmd.c drivers/drv_err.c
# The port, the board (with the board interface's shared part,
# boards/common/), the kernel and the libraries every image links,
# compiled per image at its tick rate.
STM32_BASE_SRCS := kernel/arch/armv7m/start.c kernel/arch/armv7m/fault.c \
                   kernel/arch/armv7m/k_arch_armv7m.c kernel/arch/armv7m/switch.S \
                   boards/stm32f405/vectors.c boards/stm32f405/k_board_stm32f405.c \
                   boards/stm32f405/board.c boards/common/board_common.c kernel/lib/kprintf.c kernel/lib/kstring.c \
                   bsched/bsched.c $(K_CORE_SRCS) $(STM32_DRIVER_SRCS)

# Headers that name RoboCube hardware: an image including one needs that board.
STM32_ROBOCUBE_ONLY := $(filter-out $(STM32_DRIVER_SRCS:.c=.h),$(wildcard drivers/*.h)) \
                       $(wildcard boards/robocube/*.h) mc68332.h cpu.h
# An image's sources on this board: NAME_SRCS_stm32f405 where its app.mk gives
# them (an image with a part per board), else NAME_SRCS.
stm32_srcs = $(or $($(1)_SRCS_stm32f405),$($(1)_SRCS))
# $(call stm32_needs,NAME): the RoboCube headers app NAME's sources include.
stm32_hash  := \#
stm32_includes = $(shell grep -lF '$(stm32_hash)include "$(2)' $(call stm32_srcs,$(1)) /dev/null 2>/dev/null)
stm32_needs = $(strip $(sort $(foreach h,$(STM32_ROBOCUBE_ONLY),$(if $(call stm32_includes,$(1),$(h)"),$(h)))) \
                  $(if $(call stm32_includes,$(1),net/),net/ (the radio on the DUART)) \
                  $(if $($(1)_RUNNER),its runner (the RoboCube world co-simulation)))
# The PDL runtime with this board's ports, for images that include pdl/: the
# board's own port access (ports.c), which PDL reaches through pdl/ports/board.c.
STM32_PDL_SRCS := pdl/pdl_core.c pdl/pdl_bind.c pdl/pdl_state.c pdl/pdl_board.c \
                  pdl/ports/board.c boards/stm32f405/ports.c

stm32_elf = $(STM32_BUILD)/$(1)/$(1).elf

# $(call stm32_objrules,OBJDIR,CFLAGS): how OBJDIR's objects are compiled.
define stm32_objrules
$(1)/%.c.o: %.c
	@mkdir -p $$(@D)
	$$(call quiet,CC,$$<)$$(ARM_CC) $$(STM32_CFLAGS) $(2) -c -o $$@ $$<

$(1)/%.S.o: %.S
	@mkdir -p $$(@D)
	$$(call quiet,CC,$$<)$$(ARM_CC) $$(STM32_ARCH_FLAGS) -g -c -o $$@ $$<
endef

# $(call stm32_image,OBJDIR,ELF,SRCS,CFLAGS[,BASEDIR]): ELF from SRCS + the base,
# objects in OBJDIR; the base's in BASEDIR when given (images that share it:
# its rules come from a stm32_objrules of their own).
define stm32_image
$$(eval $$(call stm32_objrules,$(1),$(4)))
$(2): $$(patsubst %,$(1)/%.o,$(3)) $$(patsubst %,$(or $(5),$(1))/%.o,$$(STM32_BASE_SRCS)) $$(STM32_LDSCRIPT)
	$$(call quiet,LD,$$@)$$(ARM_CC) $$(STM32_LDFLAGS) -Wl,-Map=$$(@:.elf=.map) -o $$@ \
	    $$(patsubst %,$(1)/%.o,$(3)) $$(patsubst %,$(or $(5),$(1))/%.o,$$(STM32_BASE_SRCS)) -lc -lgcc
	$$(call quiet,OBJCOPY,$$@)$$(ARM_OBJCOPY) -O binary $$@ $$(@:.elf=.bin)
	$$(if $$(filter 1,$$(V)),$$(ARM_SIZE) $$@,@true)

.SECONDARY: $$(patsubst %,$(1)/%.o,$(3)) $$(patsubst %,$(or $(5),$(1))/%.o,$$(STM32_BASE_SRCS))
endef
# Firmware images: every app, with its tick rate and start-up (NAME_BOOT).
define stm32_app_template
$$(eval $$(call stm32_image,$$(STM32_BUILD)/$(1)/obj,$$(call stm32_elf,$(1)),$$(call stm32_srcs,$(1)) \
    $$(if $$(filter self,$$($(1)_BOOT)),,$$(APP_BOOT_SRC)) \
    $$(if $$(call stm32_includes,$(1),pdl/),$$(STM32_PDL_SRCS)),\
    -DK_TICK_HZ=$$($(1)_TICK_HZ) -DFW_IMAGE_NAME='"$(1)"' $$($(1)_CFLAGS)))
endef
$(foreach a,$(APPS),$(eval $(call stm32_app_template,$(a))))

# The kernel target suite's images (kernel/tests/target-kernel/ktest.c).
STM32_K_DIR  := $(STM32_BUILD)/kernel
STM32_K_ELFS := $(patsubst %,$(STM32_K_DIR)/ktest-%.elf,$(K_TEST_MODES))
# The test and fault images share one build of the base (the kernel's default tick).
STM32_TEST_BASE := $(STM32_BUILD)/obj-test-base
$(eval $(call stm32_objrules,$(STM32_TEST_BASE),))
$(foreach m,$(K_TEST_MODES),$(eval $(call stm32_image,$(STM32_K_DIR)/obj-$(m),$(STM32_K_DIR)/ktest-$(m).elf,\
    kernel/tests/target-kernel/ktest.c,-DKTEST_MODE=$(call k_mode_index,$(m)),$(STM32_TEST_BASE))))

STM32_DEPS := $(shell find $(STM32_BUILD) -name '*.d' 2>/dev/null)
$(STM32_DEPS): ;
-include $(STM32_DEPS)

.PHONY: firmware-stm32f405 run-stm32f405 stm32f405-kernel-target
firmware-stm32f405: $(call stm32_elf,$(APP))
stm32f405-kernel-target: $(STM32_K_ELFS)

# An image that needs the RoboCube's hardware stops here, naming what it needs.
ifneq ($(filter stm32f405,$(BOARD)),)
ifneq ($(filter run firmware firmware-stm32f405 run-stm32f405,$(MAKECMDGOALS)),)
ifneq ($(call stm32_needs,$(APP)),)
$(error APP=$(APP) needs the RoboCube's hardware ($(call stm32_needs,$(APP))): it runs with BOARD=robocube only)
endif
endif
endif

# Piped input waits for the board's first output (robocube_emu.console_gate):
# QEMU's USART model drops what it is given before the firmware enables it.
run-stm32f405:
	@$(SETUP) base arm
	@$(MAKE) --no-print-directory firmware-stm32f405 BOARD=stm32f405 APP=$(APP)
	@echo "make run: booting $(call stm32_elf,$(APP)) on $(QEMU_ARM) -M $(STM32_MACHINE) (console = USART1 on stdio$(if $(RUN_SECONDS),; stops after $(RUN_SECONDS) s)$(if $($(APP)_QUIT),; $($(APP)_QUIT)); quit with Ctrl-C)" >&2
	@$(if $(RUN_SECONDS),timeout --foreground $(RUN_SECONDS)) \
	    $$([ -t 0 ] || echo $(PYTHON) -m robocube_emu.console_gate) $(QEMU_ARM) $(STM32_QEMU_ARGS) -icount $(STM32_ICOUNT) -kernel $(call stm32_elf,$(APP)); rc=$$?; \
	    [ $$rc -eq 0 ] || [ "$(RUN_SECONDS)" != "" -a $$rc -eq 124 ]

# The kernel target suite (kernel/tests/target-kernel) on this board: the same
# images and judgements, K_BOARD=stm32f405 picks the machine and -icount.
CHECKS += stm32f405-kernel
EMU_CHECKS += stm32f405-kernel
.PHONY: check-stm32f405-kernel
check-stm32f405-kernel:
	@$(SETUP) base arm
	@$(MAKE) --no-print-directory stm32f405-kernel-target
	@K_BOARD=stm32f405 BSCHED_QEMU=$$(command -v $(QEMU_ARM)) K_TARGET_DIR=$(STM32_K_DIR) \
	    CROSS_PREFIX=arm-none-eabi- ci/pytest-suite stm32f405-kernel kernel/tests/target-kernel

# Fault report images (boards/stm32f405/tests/fault_image.c; FAULT_KIND = position).
STM32_FAULT_KINDS := unmapped undef divzero thread
STM32_FAULT_ELFS  := $(patsubst %,$(STM32_BUILD)/tests/fault-%.elf,$(STM32_FAULT_KINDS))
stm32_fault_index  = $(strip $(foreach i,1 2 3 4,$(if $(filter $(1),$(word $(i),$(STM32_FAULT_KINDS))),$(i))))
$(foreach k,$(STM32_FAULT_KINDS),$(eval $(call stm32_image,$(STM32_BUILD)/tests/obj-$(k),\
    $(STM32_BUILD)/tests/fault-$(k).elf,boards/stm32f405/tests/fault_image.c,\
    -DFAULT_KIND=$(call stm32_fault_index,$(k)),$(STM32_TEST_BASE))))

# The firmware on this board: table1 (apps/table1/tests, as on the RoboCube)
# and the shell via make run, the fault reports, PDL (its ports, pdl_hello,
# pdl_bench), make run's refusals (boards/stm32f405/tests).
CHECKS += stm32f405-firmware
EMU_CHECKS += stm32f405-firmware
.PHONY: check-stm32f405-firmware
check-stm32f405-firmware:
	@$(SETUP) base arm
	@$(MAKE) --no-print-directory $(call stm32_elf,table1) $(call stm32_elf,pdl_hello) $(call stm32_elf,pdl_bench) \
	    $(call stm32_elf,shell) \
	    $(STM32_FAULT_ELFS) $(STM32_PDL_TEST_ELF)
	@K_BOARD=stm32f405 STM32_BUILD=$(STM32_BUILD) QEMU_ARM=$$(command -v $(QEMU_ARM)) STM32_ICOUNT=$(STM32_ICOUNT) \
	    ci/pytest-suite stm32f405-firmware boards/stm32f405/tests apps/table1/tests

# The PDL target test image (boards/stm32f405/tests/pdl_ports.c), started by
# drivers/board_main.c like any ordinary program, at the kernel's 1024 Hz.
STM32_PDL_TEST_ELF := $(STM32_BUILD)/tests/pdl-ports.elf
$(eval $(call stm32_image,$(STM32_BUILD)/tests/obj-pdl,$(STM32_PDL_TEST_ELF),\
    boards/stm32f405/tests/pdl_ports.c $(APP_BOOT_SRC) $(STM32_PDL_SRCS),\
    -DK_TICK_HZ=1024 -DFW_IMAGE_NAME='"pdl_ports"'))

# The bench image (bench/bench_armv7m.c): bsched.c and the Fig. 7
# reference at BSCHED_MAX_PROCS = $(BENCH_PROCS), as the CPU32's bench image.
STM32_BENCH_DIR  := $(BENCH_DIR)/stm32f405
STM32_BENCH_ELF  := $(STM32_BENCH_DIR)/bench-armv7m.elf
STM32_BENCH_SRCS := bench/bench_armv7m.c bsched/proofs/ref/bsched_fig7.c
STM32_BENCH_FLAGS = $(filter-out -DBSCHED_MAX_PROCS=%,$(STM32_CFLAGS)) -DBSCHED_MAX_PROCS=$(BENCH_PROCS) \
                    -I$(ROOT)/bsched/proofs/ref -I$(ROOT)/bench -DBENCH_CYCLES=$(BENCH_CYCLES)u
STM32_BENCH_OBJS := $(patsubst %,$(STM32_BENCH_DIR)/%.o,$(STM32_BENCH_SRCS) $(STM32_BASE_SRCS))
$(STM32_BENCH_DIR)/%.c.o: %.c bench/bench_image.h bench/bench_core.h
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(ARM_CC) $(STM32_BENCH_FLAGS) -c -o $@ $<
$(STM32_BENCH_DIR)/%.S.o: %.S
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(ARM_CC) $(STM32_ARCH_FLAGS) -g -c -o $@ $<
$(STM32_BENCH_ELF): $(STM32_BENCH_OBJS) $(STM32_LDSCRIPT)
	$(call quiet,LD,$@)$(ARM_CC) $(STM32_LDFLAGS) -o $@ $(STM32_BENCH_OBJS) -lc -lgcc

# make bench-cpus: the one table of both CPUs side by side (bench_cpus.py),
# written to build/bench/cpus.txt; make bench makes it too. Long (several
# minutes of traced emulation): not part of make check.
.PHONY: bench-cpus
bench: bench-cpus
bench-cpus:
	@$(SETUP) base m68k qemu arm
	@$(MAKE) --no-print-directory $(BENCH_DIR)/bench-cpu32.elf $(STM32_BENCH_ELF) \
	    $(K_BUILD)/target/ktest-measure.elf $(STM32_K_DIR)/ktest-measure.elf \
	    $(call app_elf,pdl_bench) $(call stm32_elf,pdl_bench)
	@flock /tmp/bsched-heavy.lock $(PYTHON) bench/bench_cpus.py --cycles $(BENCH_CYCLES) \
	    --robocube-bench $(BENCH_DIR)/bench-cpu32.elf --robocube-ktest $(K_BUILD)/target/ktest-measure.elf \
	    --robocube-pdl $(call app_elf,pdl_bench) --robocube-qemu $(QEMU_M68K) \
	    --stm32f405-bench $(STM32_BENCH_ELF) --stm32f405-ktest $(STM32_K_DIR)/ktest-measure.elf \
	    --stm32f405-pdl $(call stm32_elf,pdl_bench) --stm32f405-qemu $$(command -v $(QEMU_ARM)) \
	    --out $(BENCH_DIR)/cpus.txt
