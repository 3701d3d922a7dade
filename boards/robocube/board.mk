# The RoboCube board (MC68332 / CPU32): how every firmware image is compiled
# and linked (flags, linker script), the startup and base objects every image
# links, the kernel's board support (BOARD_KERNEL_SRCS, compiled with the
# kernel at each image's tick rate) and the fault test images. The images
# themselves (apps/NAME/), `make firmware` and `make run` are in apps/apps.mk;
# the firmware-boot suite, which boots table1 and the fault images, is
# declared beside its image in apps/table1/app.mk.

FW_BUILD     := $(BUILD)/firmware
# The image of firmware app NAME (apps/NAME/, built by apps/apps.mk).
app_elf       = $(FW_BUILD)/$(1)/$(1).elf
# Processes the firmware's struct bsched has room for (Table 1 has 9; PDL programs up to 32).
FW_MAX_PROCS := 32
# -fno-store-merging: GCC 12 merged adjacent byte stores into a word store at an odd
# address in net/ (an address error on the CPU32, which has no misaligned access); the
# net code works around it, and this keeps the class of bug out of every other part.
# The firmware's C headers: GCC's own, the POSIX layer's (posix/include: its
# pthread types stand in for newlib's) and newlib's, in that order. The
# feature macros make newlib's headers declare the calls of the POSIX
# profile the layer provides (clock_gettime, clock_nanosleep, sched_yield ...).
FW_POSIX_FEATURES := -D_POSIX_THREADS=1 -D_POSIX_TIMERS=1 -D_POSIX_MONOTONIC_CLOCK=200112L \
                -D_POSIX_CLOCK_SELECTION=200112L -D_POSIX_PRIORITY_SCHEDULING=1
FW_CFLAGS    := $(CROSS_CFLAGS) -g -I$(ROOT) -I$(ROOT)/kernel/arch/cpu32 -I$(ROOT)/bsched \
                -DBSCHED_MAX_PROCS=$(FW_MAX_PROCS) -ffunction-sections -fdata-sections \
                -fno-tree-loop-distribute-patterns -fno-store-merging -MMD -MP \
                -nostdinc -isystem $(shell $(CROSS_CC) -print-file-name=include) \
                -isystem $(ROOT)/posix/include -isystem $(NEWLIB)/include $(FW_POSIX_FEATURES)
FW_ASFLAGS   := -mcpu=cpu32 -g -I$(ROOT)/kernel/arch/cpu32 -MMD -MP
FW_LDSCRIPT  := boards/robocube/robocube.ld
FW_LDFLAGS   := -mcpu=cpu32 -nostdlib -T $(FW_LDSCRIPT) -Wl,--gc-sections -Wl,--build-id=none
CROSS_SIZE   ?= m68k-linux-gnu-size
CROSS_OBJCOPY ?= m68k-linux-gnu-objcopy
CROSS_AR     ?= m68k-linux-gnu-ar
# Virtual time from the instruction count alone: 2^8 ns = 256 ns per
# instruction (4.3 clocks at 16.78 MHz, an assumed CPU32 average, not measured),
# so the PIT, the DUART timer and the program advance in a fixed ratio. With
# sleep=off an idle guest (STOP) jumps straight to its next timer instead of
# waiting for the wall clock: with sleep=on, idle spans followed the host's
# clock, so a loaded host stretched them (a late warp lands past the next
# deadline) and a minor cycle could overrun only because the machine was busy.
# Now a run gives the same output, tick for tick, on a loaded host as on an idle one.
FW_ICOUNT    := shift=8,sleep=off

# Startup, fault reporter, formatter, the board's console and PIT, bsched.c:
# every firmware image links these (with or without the kernel).
FW_BASE_SRCS := boards/robocube/start.S kernel/arch/cpu32/exceptions.c \
                kernel/lib/kprintf.c kernel/lib/kstring.c \
                boards/robocube/duart_console.c boards/robocube/pit.c bsched/bsched.c
# The board interface of the images and the drivers (boards/include/:
# board.h, board_led.h, board_ports.h, board_radio.h) on this board, linked as a
# library of every image (apps/apps.mk).
FW_BOARD_LIB_SRCS := boards/robocube/board.c boards/robocube/led.c boards/robocube/ports.c \
                     boards/robocube/radio.c boards/common/board_common.c
# PDL reaches this board's ports through its drivers (the sampler, the uniform
# access layer): linked with the PDL runtime (apps/apps.mk).
FW_PDL_PORTS_SRCS := pdl/ports/drivers.c
# The kernel's board interface (kernel/include/k_board.h) on this board: PIT
# tick, interrupt-driven console; linked with the kernel (kernel/kernel.mk).
BOARD_KERNEL_SRCS := boards/robocube/k_board_robocube.c
FW_BASE_OBJS := $(patsubst %,$(FW_BUILD)/obj/%.o,$(FW_BASE_SRCS))

FW_FAULT_KINDS := unmapped flashwrite illegal zerodivide
FW_FAULT_ELFS  := $(patsubst %,$(FW_BUILD)/tests/fault-%.elf,$(FW_FAULT_KINDS))

$(CPU32_RT) $(FW_LIBC_LIBS):
	@$(SETUP) m68k

$(FW_BUILD)/obj/%.c.o: %.c
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(CROSS_CC) $(FW_CFLAGS) -c -o $@ $<

$(FW_BUILD)/obj/%.S.o: %.S
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(CROSS_CC) $(FW_ASFLAGS) -c -o $@ $<

# One image per fault kind; FAULT_KIND numbers follow kernel/tests/target/fault_image.c.
fault_kind_index  = $(strip $(foreach i,1 2 3 4,$(if $(filter $(1),$(word $(i),$(FW_FAULT_KINDS))),$(i))))

$(FW_BUILD)/tests/fault-%.o: kernel/tests/target/fault_image.c
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(CROSS_CC) $(FW_CFLAGS) -DFAULT_KIND=$(call fault_kind_index,$*) -c -o $@ $<

$(FW_BUILD)/tests/fault-%.elf: $(FW_BUILD)/tests/fault-%.o $(FW_BASE_OBJS) $(FW_LDSCRIPT)
	$(call quiet,LD,$@)$(CROSS_CC) $(FW_LDFLAGS) -o $@ $(FW_BASE_OBJS) $<

.PRECIOUS: $(FW_BUILD)/tests/fault-%.o

# Header dependencies from -MMD; the empty recipe stops make from looking for
# implicit rules to remake them (fault-%.o would otherwise match fault-x.d.o).
FW_DEPS := $(shell find $(FW_BUILD) -name '*.d' 2>/dev/null)
$(FW_DEPS): ;
-include $(FW_DEPS)
