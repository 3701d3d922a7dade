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
BENCH_FW_SRCS := boards/robocube/start.S kernel/arch/cpu32/exceptions.c kernel/lib/kprintf.c \
                 kernel/lib/kstring.c boards/robocube/duart_console.c boards/robocube/pit.c \
                 bench/bench_cpu32.c $(BENCH_LIB)
BENCH_FW_OBJS := $(patsubst %,$(BENCH_DIR)/cpu32/%.o,$(BENCH_FW_SRCS))
BENCH_FW_FLAGS = $(filter-out -DBSCHED_MAX_PROCS=% -MMD -MP,$(FW_CFLAGS)) -DBSCHED_MAX_PROCS=$(BENCH_PROCS) \
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
	$(call quiet,CC,$<)$(CROSS_CC) $(FW_ASFLAGS) -c -o $@ $<

$(BENCH_DIR)/bench-cpu32.elf: $(BENCH_FW_OBJS) $(FW_LDSCRIPT) $(CPU32_RT)
	$(call quiet,LD,$@)$(CROSS_CC) $(FW_LDFLAGS) -o $@ $(BENCH_FW_OBJS) $(CPU32_RT)

.PHONY: bench
bench:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory $(BENCH_DIR)/bsched-bench $(BENCH_DIR)/bench-cpu32.elf
	@flock /tmp/bsched-heavy.lock python3 bench/bench.py --host $(BENCH_DIR)/bsched-bench \
	    --elf $(BENCH_DIR)/bench-cpu32.elf --qemu $(QEMU_M68K) --cycles $(BENCH_CYCLES) \
	    --out $(BENCH_DIR)/bench.txt
