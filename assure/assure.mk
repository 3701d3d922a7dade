# Assurance evidence (ASSURANCE.md): mutation testing, MISRA C:2012,
# static analysis, the portability matrix, sanitizers, coverage, worst-case stack
# and load independence. Everything here is generic: it works on whatever C the
# tree holds (every suite in HOST_UNIT_CHECKS, every image in apps/*).
#
#   make mutants           every mutant of bsched.c: unit tests, then CBMC, then WP (long)
#   make misra             MISRA C:2012 on bsched/ (deviation list), counts for the other parts
#   make analyze           gcc -fanalyzer and clang scan-build over every host build (make all)
#   make coverage          branch coverage of every host suite, HTML in build/coverage/html
#   make stack             worst-case stack of every firmware thread and the interrupt path
#   make prove-machdeps    WP under x86_32, x86_64 and x86_16 (long)
# Suites in make check: sanitize, bsched-edges, bsched-targets, bsched-bigendian, misra,
# analyze, coverage, mutants-sample, stack, load-independence, cpu32-isa, redteam,
# tracker-refs.

ASSURE := $(BUILD)/assure
ASSURE_PY := $(ROOT)/assure

# The bsched host suites this stream adds or re-runs.
HOST_UNIT_CHECKS += bsched-unit kernel-unit bsched-edges
CHECKS += bsched-edges sanitize bsched-targets bsched-bigendian misra analyze coverage \
          mutants-sample stack load-independence wp-step-limits cpu32-isa

# ---------------------------------------------------------------- edge tests of bsched.c
$(BUILD)/tests/test_bsched_edges: bsched/tests/test_bsched_edges.c bsched/bsched.c bsched/bsched.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(BSCHED_CFLAGS) -DBSCHED_MAX_PROCS=4096 -o $@ $< bsched/bsched.c -lcmocka
ALL += $(BUILD)/tests/test_bsched_edges

.PHONY: check-bsched-edges
check-bsched-edges: $(BUILD)/tests/test_bsched_edges
	@$(SETUP) base
	@RESULTS=$(RESULTS) ci/cmocka-suite bsched-edges $<

# ---------------------------------------------------------------- sanitizers
# Every host unit suite again, built with ASan+UBSan into its own BUILD tree.
SAN_BUILD := $(ASSURE)/sanitize
.PHONY: check-sanitize
check-sanitize:
	@$(SETUP) base
	@$(ASSURE_PY)/sanitize.sh $(SAN_BUILD) "$(HOST_CFLAGS)" "$(sort $(HOST_UNIT_CHECKS))" $(RESULTS)/sanitize.txt

# ---------------------------------------------------------------- portability matrix
# bsched.c warning-free on every target and integer size, text size of each.
.PHONY: check-bsched-targets bsched-targets
bsched-targets check-bsched-targets:
	@$(SETUP) base m68k assure
	@$(ASSURE_PY)/targets.sh $(RESULTS)/bsched-targets.txt "$(HOST_CFLAGS)"

# The unit tests on a big-endian target: s390x under qemu-user, with Debian's
# s390x cmocka (ci/setup.d/assure.sh).
.PHONY: check-bsched-bigendian
check-bsched-bigendian:
	@$(SETUP) base assure
	@$(ASSURE_PY)/bigendian.sh $(ASSURE)/s390x $(RESULTS)/bsched-bigendian.txt

# ---------------------------------------------------------------- MISRA C:2012
MISRA_INCLUDES := -I bsched -I kernel/include -I kernel -I kernel/arch/cpu32 -I .
.PHONY: misra check-misra
misra check-misra:
	@$(SETUP) assure
	@$(ASSURE_PY)/misra.py --deviations assure/misra-deviations.txt -I bsched --suite misra bsched; rc=$$?; \
	echo "== other parts (counts only, no deviation list yet):"; \
	for d in kernel boards/robocube boards/common drivers net pdl; do $(ASSURE_PY)/misra.py --count $(MISRA_INCLUDES) $$d; done; \
	exit $$rc

# ---------------------------------------------------------------- static analysis
# Every host build (make all: the libraries, bsched-plan and every host test of
# every part) under gcc -fanalyzer and clang's analyzer (scan-build). Findings in
# bsched/, kernel/ and tools/ fail the suite; findings elsewhere are listed and
# counted (their owners fix them).
ANALYZE_GATE ?= bsched/ kernel/ tools/
.PHONY: analyze check-analyze
analyze check-analyze:
	@$(SETUP) base assure
	@$(ASSURE_PY)/analyze.sh "$(ASSURE)/analyze" "$(HOST_CFLAGS)" "$(ANALYZE_GATE)" $(RESULTS)/analyze.txt

# ---------------------------------------------------------------- coverage
# Every host unit suite built with --coverage into its own BUILD tree and run;
# lcov branch coverage per part, HTML report. bsched.c must reach 100 % of its
# lines and branches (the host suites of bsched.c: bsched-unit and bsched-edges).
COV_BUILD := $(ASSURE)/coverage
.PHONY: coverage check-coverage
coverage check-coverage:
	@$(SETUP) base assure
	@$(ASSURE_PY)/coverage.sh "$(COV_BUILD)" "$(filter-out -O2,$(HOST_CFLAGS)) -O0 --coverage" \
	    "$(sort $(HOST_UNIT_CHECKS))" $(RESULTS)/coverage.txt

# ---------------------------------------------------------------- mutation testing
.PHONY: mutants check-mutants-sample
mutants:
	@$(SETUP) base cbmc frama-c
	@$(ASSURE_PY)/mutants.py run --stages unit,cbmc,wp --out $(BUILD)/mutants
# make check: 24 mutants (a fixed sample by key hash), unit tests only; each must be
# killed or listed as equivalent in assure/mutants-equivalent.txt.
check-mutants-sample:
	@$(SETUP) base
	@$(ASSURE_PY)/mutants.py run --sample 24 --stages unit --jobs 2 --out $(BUILD)/mutants \
	    --suite mutants-sample

# ---------------------------------------------------------------- worst-case stack
# Every image in apps/* rebuilt with -fstack-usage -fcallgraph-info=su into its
# own BUILD tree; assure/stack.py walks the call graph from each thread's entry
# and from the interrupt entry and compares with the stack each thread is given.
ifdef FW_STACK_INFO
FW_EXTRA_CFLAGS += -fstack-usage -fcallgraph-info=su
endif
STACK_BUILD := $(ASSURE)/stack
# full (make check): every thread must fit its own deepest call chain plus what the
# interrupts put on its stack, and the interrupt stack its nested worst case (the model:
# assure/stack.py, ASSURANCE.md); thread: the thread's own chain alone.
STACK_GATE ?= full
.PHONY: stack check-stack
stack check-stack:
	@$(SETUP) base m68k
	@mkdir -p $(ASSURE) && $(MAKE) --no-print-directory BUILD=$(STACK_BUILD) FW_STACK_INFO=1 firmware-all > $(STACK_BUILD).log 2>&1 || \
	    { tail -20 $(STACK_BUILD).log; $(call record,stack,0,1); exit 1; }
	@$(ASSURE_PY)/stack.py --build $(STACK_BUILD)/firmware --apps "$(APPS)" --gate $(STACK_GATE) --suite stack

# ---------------------------------------------------------------- CPU32 instructions only
# Every firmware image (apps/*, the fault images, the kernel's test images, the
# bench image) disassembled whole: no instruction the CPU32 lacks (bit field,
# FPU/coprocessor, CAS/CAS2, CALLM/RTM, PACK/UNPK, memory-indirect addressing).
# The probe linked with Debian's m68k libgcc must fail the same scan.
CPU32_ISA_PROBE := $(ASSURE)/cpu32-isa/libgcc-68020-probe.elf
$(CPU32_ISA_PROBE): assure/cpu32_isa_probe.c
	@mkdir -p $(@D)
	$(call quiet,LD,$@)$(CROSS_CC) -mcpu=cpu32 -Os -nostdlib -o $@ $< -lgcc
CPU32_ISA_ELFS = $(foreach a,$(APPS),$(call app_elf,$(a))) $(FW_FAULT_ELFS) $(K_TEST_ELFS) \
                 $(BENCH_DIR)/bench-cpu32.elf
.PHONY: check-cpu32-isa
check-cpu32-isa:
	@$(SETUP) base m68k
	@$(MAKE) --no-print-directory $(CPU32_ISA_ELFS) $(CPU32_ISA_PROBE)
	@$(PYTHON) $(ASSURE_PY)/cpu32_isa.py --suite cpu32-isa --expect-bad $(CPU32_ISA_PROBE) \
	    $(CPU32_ISA_ELFS)

# ---------------------------------------------------------------- red team
# The attacks of assure/redteam.txt replayed through their regression tests:
# make redteam all of them; the suite redteam of make check the quick ones (no
# emulated board). Either prints 'N of M attacks handled cleanly'.
.PHONY: redteam check-redteam
redteam:
	@$(SETUP) base m68k qemu
	@$(PYTHON) $(ASSURE_PY)/redteam.py
CHECKS += redteam
check-redteam:
	@$(SETUP) base m68k qemu
	@$(PYTHON) $(ASSURE_PY)/redteam.py --quick --suite redteam

# ---------------------------------------------------------------- tracker references
# No issue numbers and no paths outside the repository in any tracked file
# (assure/tracker_refs.py, under a second).
CHECKS += tracker-refs
.PHONY: check-tracker-refs
check-tracker-refs:
	@$(SETUP) base
	@out=$$($(PYTHON) $(ASSURE_PY)/tracker_refs.py); rc=$$?; echo "$$out"; \
	counts=$$(echo "$$out" | tail -1); \
	$(call record,tracker-refs,$$(echo "$$counts" | cut -d' ' -f1),$$(echo "$$counts" | cut -d' ' -f3)); \
	[ $$rc -eq 0 ]

# ---------------------------------------------------------------- load independence
# table1 twice on the emulator: alone, and with every core busy; the console
# output must be identical, tick for tick.
.PHONY: check-load-independence
check-load-independence:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=table1
	@$(PYTHON) $(ASSURE_PY)/load_independence.py --qemu $(QEMU_M68K) --elf $(call app_elf,table1) \
	    --icount $(FW_ICOUNT) --until 'table1 done at tick' --suite load-independence

# ---------------------------------------------------------------- WP step limits
# Every prover of make prove honours -wp-steps: a goal cut by steps is reported as
# such, and a proof's step count is read (make wp-calibrate needs it). ~30 s.
.PHONY: check-wp-step-limits
check-wp-step-limits:
	@$(SETUP) frama-c
	@WP_PROVERS=$(WP_PROVERS) WP_STEPS=$(WP_STEPS) WP_STEPS_Z3=$(WP_STEPS_Z3) $(ASSURE_PY)/wp_step_limits.sh $(RESULTS)/wp-step-limits.txt

# ---------------------------------------------------------------- WP machine models
# The full WP run once per machine model, each gated like make prove
# (assure/prove_machdeps.sh; summary in build/wp-machdeps.txt). Frama-C 25 has
# x86_16 (16-bit int and size_t), x86_32 and x86_64 (its default).
WP_MACHDEPS ?= x86_64 x86_32 x86_16
.PHONY: prove-machdeps
prove-machdeps:
	@$(SETUP) frama-c
	@$(ASSURE_PY)/prove_machdeps.sh $(BUILD) $(WP_MACHDEPS)

# ---------------------------------------------------------------- layering
# Includes and Python imports between top-level folders point down only, with
# no circle; the allowed graph is in assure/layering.py. About 1 s.
CHECKS += layering
.PHONY: check-layering
check-layering:
	@$(SETUP) base
	@$(PYTHON) assure/layering.py --results $(RESULTS)/layering.txt
