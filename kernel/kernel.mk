# The nanokernel: host unit tests (cmocka, on the ucontext port), the CPU32
# build, the target test images and their pytest suite, and the size report.
#
#   make kernel-host-tests     build/kernel/tests/test_k_struct, test_k_threads
#   make check-kernel-unit     run them (strict HOST_CFLAGS)
#   make kernel-target         build/kernel/target/ktest.elf (all target tests in one image)
#   make check-kernel-target   boot it once per test mode on qemu -M robocube, judged by pytest
#   make kernel-size           kernel text size for CPU32 at -Os

K_BUILD      := $(BUILD)/kernel
K_CORE_SRCS  := kernel/k_struct.c kernel/k_sched.c kernel/k_sync.c kernel/k_mq.c \
                kernel/k_irq.c kernel/k_fmt.c kernel/k_bsched.c kernel/k_console_tx.c
# The formatter is the firmware's (kernel/lib/kprintf.c); on the target it
# comes with the firmware base objects.
K_HOST_LIB   := kernel/lib/kprintf.c
K_HEADERS    := $(wildcard kernel/include/*.h) kernel/k_internal.h
K_HOST_CFLAGS := $(HOST_CFLAGS) -I$(ROOT) -I$(ROOT)/kernel/include -I$(ROOT)/kernel \
                 -I$(ROOT)/kernel/tests/host/arch -I$(ROOT)/bsched \
                 -DK_BSCHED_REPORTER_STACK_BYTES=16384u
K_HOST_PORT  := kernel/tests/host/arch/k_arch_host.c
K_HOST_TESTS := $(K_BUILD)/tests/test_k_struct $(K_BUILD)/tests/test_k_threads

ALL += $(K_HOST_TESTS)
CHECKS += kernel-unit

.PHONY: kernel-host-tests check-kernel-unit
kernel-host-tests: $(K_HOST_TESTS)

$(K_BUILD)/tests/test_k_%: kernel/tests/host/test_k_%.c $(K_CORE_SRCS) $(K_HOST_PORT) \
                           $(K_HOST_LIB) bsched/bsched.c $(K_HEADERS) kernel/tests/host/arch/*.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(K_HOST_CFLAGS) -o $@ $< $(K_CORE_SRCS) $(K_HOST_PORT) $(K_HOST_LIB) \
	    bsched/bsched.c -lcmocka

check-kernel-unit: $(K_HOST_TESTS)
	@$(SETUP) base
	@RESULTS=$(RESULTS) ci/cmocka-suite kernel-unit $(K_HOST_TESTS)

# ---- CPU32 target ----
# -fno-store-merging as for every firmware image (boards/robocube/board.mk): GCC 12
# merges adjacent byte stores into a word store at an odd address, an address
# error on the CPU32 (it did so for two byte fields of struct k_thread).
K_CROSS_CFLAGS := $(CROSS_CFLAGS) -g -fno-tree-loop-distribute-patterns -fno-store-merging -ffunction-sections \
                  -fdata-sections -I$(ROOT)/kernel/include -I$(ROOT)/kernel \
                  -I$(ROOT)/kernel/arch/cpu32 -I$(ROOT)/bsched -I$(ROOT) \
                  -DBSCHED_MAX_PROCS=$(FW_MAX_PROCS) -MMD -MP
# Everything of the kernel a CPU32 image links (with the firmware base objects),
# and the board's support for it (boards/robocube/board.mk); every firmware
# image (apps/apps.mk) builds the same list at its own tick rate.
K_TARGET_SRCS := $(K_CORE_SRCS) kernel/arch/cpu32/k_arch_cpu32.c kernel/arch/cpu32/switch.S \
                 $(BOARD_KERNEL_SRCS)
K_TARGET_OBJS := $(patsubst %,$(K_BUILD)/target/obj/%.o,$(K_TARGET_SRCS))
# Test modes of kernel/tests/target-kernel/ktest.c (KTEST_MODE = position).
K_TEST_MODES := preempt priority semaphore inherit queue drift overrun stackguard baduse measure \
                overload tcbguard nesting timing
K_TEST_ELFS  := $(patsubst %,$(K_BUILD)/target/ktest-%.elf,$(K_TEST_MODES))
k_mode_index  = $(strip $(foreach i,1 2 3 4 5 6 7 8 9 10 11 12 13 14,$(if $(filter $(1),$(word $(i),$(K_TEST_MODES))),$(i))))

CHECKS += kernel-target
EMU_CHECKS += kernel-target

.PHONY: kernel-target check-kernel-target kernel-size
kernel-target: $(K_TEST_ELFS)

$(K_BUILD)/target/obj/%.c.o: %.c
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(CROSS_CC) $(K_CROSS_CFLAGS) -c -o $@ $<

$(K_BUILD)/target/obj/%.S.o: %.S
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(CROSS_CC) -mcpu=cpu32 -g -c -o $@ $<

$(K_BUILD)/target/ktest-%.o: kernel/tests/target-kernel/ktest.c
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(CROSS_CC) $(K_CROSS_CFLAGS) -DKTEST_MODE=$(call k_mode_index,$*) -c -o $@ $<

$(K_BUILD)/target/ktest-%.elf: $(K_BUILD)/target/ktest-%.o $(K_TARGET_OBJS) $(FW_BASE_OBJS) $(FW_LDSCRIPT)
	$(call quiet,LD,$@)$(CROSS_CC) $(FW_LDFLAGS) -Wl,-Map=$(@:.elf=.map) -o $@ $(FW_BASE_OBJS) $(K_TARGET_OBJS) $<

.PRECIOUS: $(K_BUILD)/target/ktest-%.o $(K_BUILD)/target/obj/%.o
.SECONDARY: $(K_TARGET_OBJS)

# Dependency files are only read, never remade (no built-in rule may try).
K_DEP_FILES := $(shell find $(K_BUILD)/target -name '*.d' 2>/dev/null)
$(K_DEP_FILES): ;
-include $(K_DEP_FILES)

check-kernel-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory kernel-target
	@BSCHED_QEMU=$(QEMU_M68K) K_TARGET_DIR=$(K_BUILD)/target CROSS_PREFIX=m68k-linux-gnu- \
	    ci/pytest-suite kernel-target kernel/tests/target-kernel

# Text bytes (code + constants) of the kernel and bsched.c for CPU32 at -Os:
# every kernel object whole, then what one linked test image keeps.
K_SIZE_OBJS := $(filter-out %/switch.S.o,$(K_TARGET_OBJS)) $(K_BUILD)/target/obj/kernel/arch/cpu32/switch.S.o
kernel-size: $(K_TEST_ELFS)
	@echo "== kernel objects (all services, nothing garbage-collected; kprintf.c is the"
	@echo "   formatter k_printf uses), m68k-linux-gnu-size:"
	@$(CROSS_SIZE) $(K_SIZE_OBJS) $(FW_BUILD)/obj/kernel/lib/kprintf.c.o \
	    $(FW_BUILD)/obj/bsched/bsched.c.o | awk \
	    'NR>1 { t += $$1; if ($$6 !~ /\/bsched\/bsched\.c\.o$$/) k += $$1 } { print } \
	     END { printf "kernel text %d bytes, kernel + bsched.c %d bytes (goal < 16384)\n", k, t }'
	@echo "== linked into ktest-overrun.elf (threads, sleep, bsched thread, console):"
	@$(PYTHON) kernel/tests/target-kernel/ksize.py $(K_BUILD)/target/ktest-overrun.map
