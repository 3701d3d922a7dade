# The nanokernel: host unit tests (cmocka, on the ucontext port), the CPU32
# build, the target test images and their pytest suite, and the size report.
#
#   make kernel-host-tests     build/kernel/tests/test_k_struct, test_k_threads
#   make check-kernel-unit     run them (strict HOST_CFLAGS)
#   make kernel-target         build/kernel/target/ktest-MODE.elf (one image per test mode)
#   make check-kernel-target   boot each on qemu -M robocube, judged by pytest
#   make check-NAME-kernel     the same on board NAME (boards/NAME/)
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

# ---- target ----
# The kernel target suite's images (kernel/tests/target-kernel/ktest.c, one
# per test mode, KTEST_MODE = position), built for every board by the image
# pipeline (mk/image.mk): the test program per mode; the kernel (at its
# default tick) and the board interface shared by the modes. The RoboCube's
# stay where the tools look for them (ksize.py, kmeasure.py).
K_TEST_MODES := preempt priority semaphore inherit queue drift overrun stackguard baduse measure \
                overload tcbguard nesting timing
k_mode_index  = $(strip $(foreach i,1 2 3 4 5 6 7 8 9 10 11 12 13 14,$(if $(filter $(1),$(word $(i),$(K_TEST_MODES))),$(i))))
k_test_dir    = $(if $(filter robocube,$(1)),$(K_BUILD)/target,$(BOARD_$(1)_BUILD)/kernel)
k_test_elfs   = $(patsubst %,$(call k_test_dir,$(1))/ktest-%.elf,$(K_TEST_MODES))
$(foreach b,$(IMAGE_BOARDS),$(foreach m,$(K_TEST_MODES),$(eval $(call image,$(b),ktest-$(m),$(call k_test_dir,$(b))/$(m),\
    $(call k_test_dir,$(b))/ktest-$(m).elf,kernel/tests/target-kernel/ktest.c,-DKTEST_MODE=$(call k_mode_index,$(m)),kernel,\
    $(call k_test_dir,$(b))))))
K_TEST_ELFS  := $(call k_test_elfs,robocube)

# The CPU32 port's fault report images (kernel/tests/target/fault_image.c,
# FAULT_KIND = position) on the RoboCube's base alone; the firmware-boot suite
# boots them (apps/table1/app.mk).
FW_FAULT_KINDS := unmapped flashwrite illegal zerodivide
FW_FAULT_ELFS  := $(patsubst %,$(FW_BUILD)/tests/fault-%.elf,$(FW_FAULT_KINDS))
fault_kind_index = $(strip $(foreach i,1 2 3 4,$(if $(filter $(1),$(word $(i),$(FW_FAULT_KINDS))),$(i))))
$(foreach k,$(FW_FAULT_KINDS),$(eval $(call image,robocube,fault-$(k),$(FW_BUILD)/tests/fault-$(k),\
    $(FW_BUILD)/tests/fault-$(k).elf,kernel/tests/target/fault_image.c,-DFAULT_KIND=$(call fault_kind_index,$(k)),bare,\
    $(FW_BUILD)/tests/shared)))

CHECKS += kernel-target
EMU_CHECKS += kernel-target

.PHONY: kernel-target check-kernel-target kernel-size $(foreach b,$(IMAGE_BOARDS),$(b)-kernel-target)
kernel-target: $(K_TEST_ELFS)
$(foreach b,$(IMAGE_BOARDS),$(eval $(b)-kernel-target: $(call k_test_elfs,$(b))))

# The same suite on every other board (check-NAME-kernel): the same images and
# judgements; K_BOARD picks the board's machine and -icount
# (robocube_emu.launch.BOARDS).
define k_board_suite
CHECKS += $(1)-kernel
EMU_CHECKS += $(1)-kernel
.PHONY: check-$(1)-kernel
check-$(1)-kernel:
	@$$(SETUP) base $(BOARD_$(1)_SETUP)
	@$$(MAKE) --no-print-directory $(1)-kernel-target
	@K_BOARD=$(1) BSCHED_QEMU=$$$$(command -v $(BOARD_$(1)_QEMU)) K_TARGET_DIR=$(call k_test_dir,$(1)) \
	    CROSS_PREFIX=$(BOARD_$(1)_CROSS) ci/pytest-suite $(1)-kernel kernel/tests/target-kernel
endef
$(foreach b,$(filter-out robocube,$(IMAGE_BOARDS)),$(eval $(call k_board_suite,$(b))))

check-kernel-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory kernel-target
	@BSCHED_QEMU=$(QEMU_M68K) K_TARGET_DIR=$(K_BUILD)/target CROSS_PREFIX=m68k-linux-gnu- \
	    ci/pytest-suite kernel-target kernel/tests/target-kernel

# Text bytes (code + constants) of the kernel and bsched.c for CPU32 at -Os:
# every kernel object whole, then what one linked test image keeps.
K_SIZE_OBJS := $(patsubst %,$(K_BUILD)/target/obj/%.o,$(call board_kernel_srcs,robocube))
kernel-size: $(K_TEST_ELFS)
	@echo "== kernel objects (all services, nothing garbage-collected; kprintf.c is the"
	@echo "   formatter k_printf uses), m68k-linux-gnu-size:"
	@$(CROSS_SIZE) $(K_SIZE_OBJS) $(FW_BUILD)/obj/kernel/lib/kprintf.c.o \
	    $(FW_BUILD)/obj/bsched/bsched.c.o | awk \
	    'NR>1 { t += $$1; if ($$6 !~ /\/bsched\/bsched\.c\.o$$/) k += $$1 } { print } \
	     END { printf "kernel text %d bytes, kernel + bsched.c %d bytes (goal < 16384)\n", k, t }'
	@echo "== linked into ktest-overrun.elf (threads, sleep, bsched thread, console):"
	@$(PYTHON) kernel/tests/target-kernel/ksize.py $(K_BUILD)/target/ktest-overrun.map
