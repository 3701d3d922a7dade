# make bench: instructions per minor cycle of Fig. 7 (the reference engine
# bsched/proofs/ref/bsched_fig7.c) and of the library's bsched_step side by side,
# N = 9 (Table 1), 64, 256, 1024, 4096 (pv 3..12), on the host (callgrind) and on
# the emulated CPU32 (QEMU's instruction log); also bsched_init, bsched_fig7_start
# and the state's bytes per process. One line per case.
# Writes build/bench/bench.txt. Long (a minute or two): not part of make check.

BENCH_DIR    := $(BUILD)/bench
BENCH_PROCS  := 4096
BENCH_CYCLES ?= 256
BENCH_LIB    := bsched/bsched.c bsched/proofs/ref/bsched_fig7.c
BENCH_HDRS   := bsched/bsched.h bsched/proofs/ref/bsched_fig7.h bench/bench_core.h bench/bench_image.h
# The CPU32 image: the firmware's startup and console, no kernel; the library at
# BSCHED_MAX_PROCS = 4096 (the firmware base objects carry it at 16).
BENCH_FW_SRCS := $(filter-out bsched/bsched.c,$(call board_base_srcs,robocube)) bench/bench_cpu32.c $(BENCH_LIB)
BENCH_FW_OBJS := $(patsubst %,$(BENCH_DIR)/cpu32/%.o,$(BENCH_FW_SRCS))
BENCH_FW_FLAGS = $(filter-out -DBSCHED_MAX_PROCS=% -MMD -MP,$(call board_cflags,robocube)) -DBSCHED_MAX_PROCS=$(BENCH_PROCS) \
                 -I$(ROOT)/bsched/proofs/ref -DBENCH_CYCLES=$(BENCH_CYCLES)u

$(BENCH_DIR)/bsched-bench: bench/bench_host.c $(BENCH_LIB) $(BENCH_HDRS)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(BSCHED_CFLAGS) -I$(ROOT)/bsched/proofs/ref -DBSCHED_MAX_PROCS=$(BENCH_PROCS) -o $@ \
	    bench/bench_host.c $(BENCH_LIB)

$(BENCH_DIR)/cpu32/%.c.o: %.c $(BENCH_HDRS)
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(CROSS_CC) $(BENCH_FW_FLAGS) -c -o $@ $<
$(BENCH_DIR)/cpu32/%.S.o: %.S
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(CROSS_CC) $(call board_asflags,robocube) -c -o $@ $<

$(BENCH_DIR)/bench-cpu32.elf: $(BENCH_FW_OBJS) $(BOARD_robocube_LDSCRIPT) $(CPU32_RT)
	$(call quiet,LD,$@)$(CROSS_CC) $(call board_ldflags,robocube) -o $@ $(BENCH_FW_OBJS) $(CPU32_RT)

.PHONY: bench
bench:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory $(BENCH_DIR)/bsched-bench $(BENCH_DIR)/bench-cpu32.elf
	@flock /tmp/bsched-heavy.lock python3 bench/bench.py --host $(BENCH_DIR)/bsched-bench \
	    --elf $(BENCH_DIR)/bench-cpu32.elf --qemu $(QEMU_M68K) --cycles $(BENCH_CYCLES) \
	    --out $(BENCH_DIR)/bench.txt

# The Cortex-M4 bench image (bench/bench_armv7m.c): bsched.c and the Fig. 7
# reference at BSCHED_MAX_PROCS = $(BENCH_PROCS) on the stm32f405's base, as
# the CPU32's bench image; its vector table names the port's handlers, so the
# kernel and the board interface are linked too (the bench calls neither).
STM32_BENCH_DIR  := $(BENCH_DIR)/stm32f405
STM32_BENCH_ELF  := $(STM32_BENCH_DIR)/bench-armv7m.elf
STM32_BENCH_SRCS := $(filter-out bsched/bsched.c,$(call board_base_srcs,stm32f405)) $(call board_kernel_srcs,stm32f405) \
                    $(BOARD_stm32f405_LIB_SOURCES) bench/bench_armv7m.c $(BENCH_LIB)
STM32_BENCH_FLAGS = $(filter-out -DBSCHED_MAX_PROCS=% -MMD -MP,$(call board_cflags,stm32f405)) -DBSCHED_MAX_PROCS=$(BENCH_PROCS) \
                    -I$(ROOT)/bsched/proofs/ref -I$(ROOT)/bench -DBENCH_CYCLES=$(BENCH_CYCLES)u
STM32_BENCH_OBJS := $(patsubst %,$(STM32_BENCH_DIR)/%.o,$(STM32_BENCH_SRCS))
$(STM32_BENCH_DIR)/%.c.o: %.c $(BENCH_HDRS)
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(call board_cc,stm32f405) $(STM32_BENCH_FLAGS) -c -o $@ $<
$(STM32_BENCH_DIR)/%.S.o: %.S
	@mkdir -p $(@D)
	$(call quiet,AS,$<)$(call board_cc,stm32f405) $(call board_asflags,stm32f405) -c -o $@ $<
$(STM32_BENCH_ELF): $(STM32_BENCH_OBJS) $(BOARD_stm32f405_LDSCRIPT)
	$(call quiet,LD,$@)$(call board_cc,stm32f405) $(call board_ldflags,stm32f405) -o $@ $(STM32_BENCH_OBJS) \
	    $(BOARD_stm32f405_LIBS) $(BOARD_stm32f405_RUNTIME)

# make bench-cpus: the one table of both CPUs side by side (bench_cpus.py),
# written to build/bench/cpus.txt; make bench makes it too. Long (several
# minutes of traced emulation): not part of make check.
.PHONY: bench-cpus
bench: bench-cpus
bench-cpus:
	@$(SETUP) base m68k qemu arm
	@$(MAKE) --no-print-directory $(BENCH_DIR)/bench-cpu32.elf $(STM32_BENCH_ELF) \
	    $(K_BUILD)/target/ktest-measure.elf $(call k_test_dir,stm32f405)/ktest-measure.elf \
	    $(call app_elf,pdl_bench) $(call image_elf,stm32f405,pdl_bench)
	@flock /tmp/bsched-heavy.lock $(PYTHON) bench/bench_cpus.py --cycles $(BENCH_CYCLES) \
	    --robocube-bench $(BENCH_DIR)/bench-cpu32.elf --robocube-ktest $(K_BUILD)/target/ktest-measure.elf \
	    --robocube-pdl $(call app_elf,pdl_bench) --robocube-qemu $(QEMU_M68K) \
	    --stm32f405-bench $(STM32_BENCH_ELF) --stm32f405-ktest $(call k_test_dir,stm32f405)/ktest-measure.elf \
	    --stm32f405-pdl $(call image_elf,stm32f405,pdl_bench) --stm32f405-qemu $$(command -v $(BOARD_stm32f405_QEMU)) \
	    --out $(BENCH_DIR)/cpus.txt
