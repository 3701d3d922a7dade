# RoboCube reference firmware (MC68332 / CPU32): startup, drivers, the
# default image (the nanokernel running Table 1 in its B-scheduler thread),
# the fault test images, `make run` and the firmware-boot suite.
#
#   make firmware                       build/firmware/robocube.elf (+ .map, .srec)
#   make run [RUN_SECONDS=N]            boot it on qemu-system-m68k -M robocube
#   make check-firmware-boot            boot and fault tests on the emulator

FW_BUILD     := $(BUILD)/firmware
FW_ELF       := $(FW_BUILD)/robocube.elf
# Processes the firmware's struct bsched has room for (Table 1 has 9).
FW_MAX_PROCS := 16
FW_CFLAGS    := $(CROSS_CFLAGS) -g -I$(ROOT) -I$(ROOT)/kernel/arch/cpu32 -I$(ROOT)/bsched \
                -DBSCHED_MAX_PROCS=$(FW_MAX_PROCS) -ffunction-sections -fdata-sections \
                -fno-tree-loop-distribute-patterns -MMD -MP
FW_ASFLAGS   := -mcpu=cpu32 -g -I$(ROOT)/kernel/arch/cpu32 -MMD -MP
FW_LDSCRIPT  := kernel/arch/cpu32/robocube.ld
FW_LDFLAGS   := -mcpu=cpu32 -nostdlib -T $(FW_LDSCRIPT) -Wl,--gc-sections -Wl,--build-id=none
CROSS_SIZE   ?= m68k-linux-gnu-size
CROSS_OBJCOPY ?= m68k-linux-gnu-objcopy
QEMU_M68K    ?= $(BSCHED_TOOLS)/qemu/bin/qemu-system-m68k
# Virtual time from the instruction count: 2^8 ns = 256 ns per instruction
# (4.3 clocks at 16.78 MHz, an assumed CPU32 average, not measured), so the
# PIT, the DUART timer and the program advance in a fixed ratio however busy
# the host is; sleep=on keeps idle time (STOP) in step with the wall clock.
FW_ICOUNT    := shift=8,sleep=on

# Startup, drivers, library: every firmware image links these.
FW_BASE_SRCS := kernel/arch/cpu32/start.S kernel/arch/cpu32/exceptions.c \
                kernel/lib/kprintf.c kernel/lib/kstring.c \
                drivers/duart_console.c drivers/pit.c drivers/led.c bsched/bsched.c
FW_BASE_OBJS := $(patsubst %,$(FW_BUILD)/obj/%.o,$(FW_BASE_SRCS))

# The default image links the nanokernel, compiled here (objects under
# $(FW_BUILD)/kobj) at the image's own tick rate: 128 Hz instead of the
# kernel's default 1024 Hz, so that every minor cycle's console line fits in
# its tick (see kernel/apps/table1.c). The kernel's source list is
# K_TARGET_SRCS (kernel/kernel.mk, which adds those objects to $(FW_ELF)).
FW_TICK_HZ       := 128
FW_KERNEL_CFLAGS := $(FW_CFLAGS) -I$(ROOT)/kernel/include -I$(ROOT)/kernel -DK_TICK_HZ=$(FW_TICK_HZ)
FW_APP_OBJ       := $(FW_BUILD)/kobj/kernel/apps/table1.c.o

FW_FAULT_KINDS := unmapped flashwrite illegal zerodivide
FW_FAULT_ELFS  := $(patsubst %,$(FW_BUILD)/tests/fault-%.elf,$(FW_FAULT_KINDS))

CHECKS += firmware-boot

.PHONY: firmware firmware-tests check-firmware-boot
firmware: $(FW_ELF)
firmware-tests: $(FW_ELF) $(FW_FAULT_ELFS)

$(FW_BUILD)/obj/%.c.o: %.c
	@mkdir -p $(@D)
	$(CROSS_CC) $(FW_CFLAGS) -c -o $@ $<

$(FW_BUILD)/obj/%.S.o: %.S
	@mkdir -p $(@D)
	$(CROSS_CC) $(FW_ASFLAGS) -c -o $@ $<

$(FW_BUILD)/kobj/%.c.o: %.c
	@mkdir -p $(@D)
	$(CROSS_CC) $(FW_KERNEL_CFLAGS) -c -o $@ $<

$(FW_BUILD)/kobj/%.S.o: %.S
	@mkdir -p $(@D)
	$(CROSS_CC) $(FW_ASFLAGS) -c -o $@ $<

# kernel/kernel.mk adds the kernel objects as further prerequisites.
$(FW_ELF): $(FW_BASE_OBJS) $(FW_APP_OBJ) $(FW_LDSCRIPT)
	$(CROSS_CC) $(FW_LDFLAGS) -Wl,-Map=$(FW_BUILD)/robocube.map -o $@ $(filter %.o,$^)
	$(CROSS_OBJCOPY) -O srec $@ $(FW_BUILD)/robocube.srec
	$(CROSS_SIZE) $@

# One image per fault kind; FAULT_KIND numbers follow kernel/tests/target/fault_image.c.
fault_kind_index  = $(strip $(foreach i,1 2 3 4,$(if $(filter $(1),$(word $(i),$(FW_FAULT_KINDS))),$(i))))

$(FW_BUILD)/tests/fault-%.o: kernel/tests/target/fault_image.c
	@mkdir -p $(@D)
	$(CROSS_CC) $(FW_CFLAGS) -DFAULT_KIND=$(call fault_kind_index,$*) -c -o $@ $<

$(FW_BUILD)/tests/fault-%.elf: $(FW_BUILD)/tests/fault-%.o $(FW_BASE_OBJS) $(FW_LDSCRIPT)
	$(CROSS_CC) $(FW_LDFLAGS) -o $@ $(FW_BASE_OBJS) $<

.PRECIOUS: $(FW_BUILD)/tests/fault-%.o

# Header dependencies from -MMD; the empty recipe stops make from looking for
# implicit rules to remake them (fault-%.o would otherwise match fault-x.d.o).
FW_DEPS := $(shell find $(FW_BUILD) -name '*.d' 2>/dev/null)
$(FW_DEPS): ;
-include $(FW_DEPS)

check-firmware-boot:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware-tests
	@BSCHED_QEMU=$(QEMU_M68K) FW_DIR=$(FW_BUILD) FW_ICOUNT=$(FW_ICOUNT) CROSS_PREFIX=m68k-linux-gnu- \
	    ci/pytest-suite firmware-boot kernel/tests/target

RUN_DEFINED := 1
RUN_SECONDS ?=
.PHONY: run
run:
	@$(SETUP) qemu m68k
	@$(MAKE) --no-print-directory firmware
	@echo "make run: booting $(FW_ELF) on $(QEMU_M68K) -M robocube (console = DUART B on stdio$(if $(RUN_SECONDS),; stops after $(RUN_SECONDS) s,; quit with Ctrl-A x))" >&2
	@$(if $(RUN_SECONDS),timeout --foreground $(RUN_SECONDS)) \
	    $(QEMU_M68K) -M robocube -icount $(FW_ICOUNT) -kernel $(FW_ELF) -nographic; rc=$$?; \
	    [ $$rc -eq 0 ] || [ "$(RUN_SECONDS)" != "" -a $$rc -eq 124 ]
