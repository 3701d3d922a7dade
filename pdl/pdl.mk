# PDL: behaviour processes on the B-scheduler (pdl/README.md).
#
#   make pdl-host-tests        build/pdl/tests/test_pdl (+ examples), host build of the runtime
#   make check-pdl-unit        host unit tests of the runtime and the example behaviours (cmocka)
#                              + compile-time refusals (add_value on a sensor, ...)
#   make pdl-bench             cycle cost, CPU load at 1 kHz, stack, flash/RAM (emulated board)
#   make pdl-host-lib          build/pdl/libpdl_host.a: the host runtime for simulators
# The PDL images' suite (pdl-target: pdl/tests/target on the emulated board) is
# declared beside its images, in apps/pdl_demo/app.mk.

PDL_BUILD      := $(BUILD)/pdl
# The runtime: target sources directly in pdl/ (the board platform is pdl_board.c;
# how it reaches the board's ports, pdl/ports/, is each board's choice: its
# board.mk), the host platform in pdl/host/. On the host the ports are the
# RoboCube's (the arena's robot): its port table gives pdl_bind.c the ranges.
PDL_CORE_SRCS  := pdl/pdl_core.c pdl/pdl_bind.c pdl/pdl_state.c
PDL_HOST_SRCS  := $(PDL_CORE_SRCS) pdl/host/pdl_host.c bsched/bsched.c boards/robocube/ports.c
PDL_HEADERS    := $(wildcard pdl/*.h pdl/host/*.h pdl/examples/*.h) bsched/bsched.h boards/include/board_ports.h
PDL_HOST_CFLAGS := $(HOST_CFLAGS) -I$(ROOT) -I$(ROOT)/bsched
# The example behaviours (compiled for the host here and into apps/pdl_demo for the board).
PDL_EXAMPLE_SRCS := $(wildcard pdl/examples/*.c)
# test_pdl twice: at -O2 (HOST_CFLAGS), which checks the values, and under
# ASan/UBSan with no recovery, where any undefined behaviour on a tested path
# (add_value's extremes: overflow, float-to-integer conversion) fails it.
# GCC's -fsanitize=undefined leaves float-cast-overflow out: named here.
PDL_SANITIZE   := -O1 -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all
PDL_HOST_TESTS := $(PDL_BUILD)/tests/test_pdl $(PDL_BUILD)/tests/test_pdl_sanitized \
                  $(PDL_BUILD)/tests/test_behaviours

ALL += $(PDL_HOST_TESTS)
CHECKS += pdl-unit
HOST_UNIT_CHECKS += pdl-unit

.PHONY: pdl-host-tests check-pdl-unit pdl-host-lib
pdl-host-tests: $(PDL_HOST_TESTS)

# The host runtime as a library, for simulators (the eco arena): link it with
# -I$(ROOT) -I$(ROOT)/bsched and include pdl/pdl.h and pdl/host/pdl_host.h.
PDL_HOST_LIB := $(PDL_BUILD)/libpdl_host.a
pdl-host-lib: $(PDL_HOST_LIB)
$(PDL_HOST_LIB): $(PDL_HOST_SRCS) $(PDL_HEADERS)
	@mkdir -p $(PDL_BUILD)/host-obj
	$(call quiet,HOSTCC,$@ objects)cd $(PDL_BUILD)/host-obj && $(HOST_CC) $(PDL_HOST_CFLAGS) -c $(addprefix $(ROOT)/,$(PDL_HOST_SRCS))
	$(call quiet,AR,$@)rm -f $@ && ar rcs $@ $(addprefix $(PDL_BUILD)/host-obj/,$(notdir $(PDL_HOST_SRCS:.c=.o)))

$(PDL_BUILD)/tests/test_pdl: pdl/tests/test_pdl.c $(PDL_HOST_SRCS) $(PDL_HEADERS)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(PDL_HOST_CFLAGS) -o $@ $< $(PDL_HOST_SRCS) -lcmocka

$(PDL_BUILD)/tests/test_pdl_sanitized: pdl/tests/test_pdl.c $(PDL_HOST_SRCS) $(PDL_HEADERS)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(PDL_HOST_CFLAGS) $(PDL_SANITIZE) -o $@ $< $(PDL_HOST_SRCS) -lcmocka

$(PDL_BUILD)/tests/test_behaviours: pdl/tests/test_behaviours.c $(PDL_EXAMPLE_SRCS) $(PDL_HOST_SRCS) $(PDL_HEADERS)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(PDL_HOST_CFLAGS) -o $@ $< $(PDL_EXAMPLE_SRCS) $(PDL_HOST_SRCS) -lcmocka

# pdl/README.md's complete example ("A complete program"), extracted and run.
PDL_README_TEST := $(PDL_BUILD)/tests/readme_example
$(PDL_BUILD)/readme_example.c: pdl/README.md
	@mkdir -p $(@D)
	awk '/^## A complete program/ { s = 1 } s && /^```c$$/ { c = 1; next } \
	     c && /^```$$/ { exit } c { print }' pdl/README.md > $@
	@test -s $@ || { echo "no C example under 'A complete program' in pdl/README.md"; exit 1; }
$(PDL_README_TEST): pdl/tests/readme_main.c $(PDL_BUILD)/readme_example.c $(PDL_HOST_SRCS) $(PDL_HEADERS)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(PDL_HOST_CFLAGS) -o $@ $< $(PDL_BUILD)/readme_example.c $(PDL_HOST_SRCS)
ALL += $(PDL_README_TEST)

# Misuse the compiler must refuse: each pdl/tests/refuse/*.c has to fail to
# compile (warnings are errors here, whatever HOST_CFLAGS says; no --coverage,
# which would leave a .gcno in the working folder) with the
# message on its first line ("// expect: TEXT").
PDL_REFUSE_SRCS := $(wildcard pdl/tests/refuse/*.c)

check-pdl-unit: $(PDL_HOST_TESTS) $(PDL_README_TEST)
	@$(SETUP) base
	@p=0; f=0; rc=0; \
	if $(PDL_README_TEST); then p=1; else f=1; rc=1; fi; \
	for t in $(PDL_HOST_TESTS); do \
	    out=$$($$t 2>&1); r=$$?; echo "$$out"; [ $$r -eq 0 ] || rc=1; \
	    read -r tp tf <<< "$$(echo "$$out" | ci/cmocka-suite --count)"; \
	    p=$$((p + tp)); f=$$((f + tf)); \
	done; \
	for src in $(PDL_REFUSE_SRCS); do \
	    want=$$(sed -n '1s|^// expect: ||p' $$src); \
	    out=$$(LC_ALL=C $(HOST_CC) $(filter-out --coverage,$(PDL_HOST_CFLAGS)) -Werror -fsyntax-only $$src 2>&1); \
	    if [ $$? -ne 0 ] && [ -n "$$want" ] && echo "$$out" | grep -qF -- "$$want"; then \
	        p=$$((p + 1)); echo "[       OK ] refused at compile time: $$src"; \
	    else f=$$((f + 1)); rc=1; echo "[  FAILED  ] $$src compiled or without '$$want':"; echo "$$out"; fi; \
	done; \
	$(call record,pdl-unit,$$p,$$f); [ $$rc -eq 0 ]

# ---- on the emulated board ----
.PHONY: pdl-bench
# Every figure of pdl/README.md "Speed", printed and kept in build/pdl/bench.txt.
pdl-bench:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory $(call app_elf,pdl_bench)
	@mkdir -p $(PDL_BUILD)
	@BSCHED_QEMU=$(QEMU_M68K) $(PYTHON) pdl/tests/target/pdl_measure.py \
	    $(call app_elf,pdl_bench) $(QEMU_M68K) | tee $(PDL_BUILD)/bench.txt
