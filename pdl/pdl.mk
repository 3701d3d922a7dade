# PDL: behaviour processes on the B-scheduler (pdl/README.md).
#
#   make pdl-host-tests        build/pdl/tests/test_pdl (+ examples), host build of the runtime
#   make check-pdl-unit        host unit tests of the runtime and the example behaviours (cmocka)
#                              + compile-time refusals (add_value on a sensor, ...)
#   make check-pdl-target      a PDL image on the emulated board (pytest over QMP)
#   make pdl-bench             cycle cost, CPU load at 1 kHz, stack, flash/RAM (emulated board)

PDL_BUILD      := $(BUILD)/pdl
# The runtime: target sources directly in pdl/ (the board platform is pdl_board.c),
# the host platform in pdl/host/.
PDL_CORE_SRCS  := pdl/pdl_core.c pdl/pdl_bind.c
PDL_HOST_SRCS  := $(PDL_CORE_SRCS) pdl/host/pdl_host.c bsched/bsched.c
PDL_HEADERS    := $(wildcard pdl/*.h pdl/host/*.h pdl/examples/*.h) bsched/bsched.h
PDL_HOST_CFLAGS := $(HOST_CFLAGS) -I$(ROOT) -I$(ROOT)/bsched
# The example behaviours (compiled for the host here and into apps/pdl_demo for the board).
PDL_EXAMPLE_SRCS := $(wildcard pdl/examples/*.c)
PDL_HOST_TESTS := $(PDL_BUILD)/tests/test_pdl $(PDL_BUILD)/tests/test_behaviours

ALL += $(PDL_HOST_TESTS)
CHECKS += pdl-unit
HOST_UNIT_CHECKS += pdl-unit

.PHONY: pdl-host-tests check-pdl-unit
pdl-host-tests: $(PDL_HOST_TESTS)

$(PDL_BUILD)/tests/test_pdl: pdl/tests/test_pdl.c $(PDL_HOST_SRCS) $(PDL_HEADERS)
	@mkdir -p $(@D)
	$(HOST_CC) $(PDL_HOST_CFLAGS) -o $@ $< $(PDL_HOST_SRCS) -lcmocka

$(PDL_BUILD)/tests/test_behaviours: pdl/tests/test_behaviours.c $(PDL_EXAMPLE_SRCS) $(PDL_HOST_SRCS) $(PDL_HEADERS)
	@mkdir -p $(@D)
	$(HOST_CC) $(PDL_HOST_CFLAGS) -o $@ $< $(PDL_EXAMPLE_SRCS) $(PDL_HOST_SRCS) -lcmocka

# Misuse the compiler must refuse: each pdl/tests/refuse/*.c has to fail to
# compile with the message on its first line ("// expect: TEXT").
PDL_REFUSE_SRCS := $(wildcard pdl/tests/refuse/*.c)

check-pdl-unit: $(PDL_HOST_TESTS)
	@$(SETUP) base
	@p=0; f=0; rc=0; \
	for t in $(PDL_HOST_TESTS); do \
	    out=$$($$t 2>&1); r=$$?; echo "$$out"; [ $$r -eq 0 ] || rc=1; \
	    tp=$$(echo "$$out" | sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' | tail -1); \
	    tf=$$(echo "$$out" | sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' | tail -1); \
	    if [ -z "$$tp$$tf" ]; then tf=1; fi; \
	    p=$$((p + $${tp:-0})); f=$$((f + $${tf:-0})); \
	done; \
	for src in $(PDL_REFUSE_SRCS); do \
	    want=$$(sed -n '1s|^// expect: ||p' $$src); \
	    out=$$(LC_ALL=C $(HOST_CC) $(PDL_HOST_CFLAGS) -fsyntax-only $$src 2>&1); \
	    if [ $$? -ne 0 ] && [ -n "$$want" ] && echo "$$out" | grep -qF -- "$$want"; then \
	        p=$$((p + 1)); echo "[       OK ] refused at compile time: $$src"; \
	    else f=$$((f + 1)); rc=1; echo "[  FAILED  ] $$src compiled or without '$$want':"; echo "$$out"; fi; \
	done; \
	$(call record,pdl-unit,$$p,$$f); [ $$rc -eq 0 ]

# ---- on the emulated board ----
CHECKS += pdl-target
PDL_TARGET_ELFS := $(call app_elf,pdl_demo) $(call app_elf,pdl_bench)

.PHONY: check-pdl-target pdl-bench
check-pdl-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory $(PDL_TARGET_ELFS)
	@BSCHED_QEMU=$(QEMU_M68K) FW_DIR=$(FW_BUILD) ci/pytest-suite pdl-target pdl/tests/target

# Every figure of pdl/README.md "Speed", printed and kept in build/pdl/bench.txt.
pdl-bench:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory $(call app_elf,pdl_bench)
	@mkdir -p $(PDL_BUILD)
	@BSCHED_QEMU=$(QEMU_M68K) $(PYTHON) pdl/tests/target/pdl_measure.py \
	    $(call app_elf,pdl_bench) $(QEMU_M68K) | tee $(PDL_BUILD)/bench.txt
