# bsched: the verified B-scheduler and the RoboCube reference firmware.
#   make         build everything host-side (library, bsched-plan, unit tests)
#   make check   every test and proof; ends with 'N passed, N failed'
#   make run     the reference firmware on the emulated RoboCube
# Each part of the tree adds its rules in its own fragment (*.mk) and its
# suites to CHECKS; ci/run-checks runs them as 'make check-SUITE'. The proof
# suites (WP, CBMC) are also named in PROOF_CHECKS: they run in a lane of their
# own, at low priority, beside the other suites (ci/run-checks).

.DEFAULT_GOAL := all
SHELL := /bin/bash
ROOT  := $(abspath .)
BUILD := $(ROOT)/build
export BSCHED_TOOLS ?= $(or $(XDG_CACHE_HOME),$(HOME)/.cache)/bsched
SETUP := $(ROOT)/ci/setup
RESULTS := $(BUILD)/results
# This checkout's pinned Python environment (a link made by ci/setup base).
PYTHON := $(BUILD)/venv/bin/python
# Writes build/results/$(1).txt from a 'P F' pair: $(call record,SUITE,PASSED,FAILED)
record = mkdir -p $(RESULTS) && echo "$(2) passed, $(3) failed" > $(RESULTS)/$(1).txt
empty :=
space := $(empty) $(empty)
# Build lines: one short line per step ("  CC      kernel/k_sched.c") unless
# V=1, which shows every command in full. A recipe line starts with
# $(call quiet,WHAT,FILE) and then its command:
#     $(call quiet,CC,$<)$(CROSS_CC) $(FW_CFLAGS) -c -o $@ $<
V ?= 0
ifeq ($(V),1)
quiet =
else
quiet = @printf '  %-7s %s\n' '$(1)' '$(patsubst $(ROOT)/%,%,$(2))';
endif
# $(call check_whole_number,WHO,VAR,MIN,MAX,USAGE): stops make (status 2) with one line
# unless $(VAR) is one plain decimal integer within MIN..MAX. The digits are
# stripped in make first, so only a string of digits ever reaches the shell.
digits_removed = $(subst 0,,$(subst 1,,$(subst 2,,$(subst 3,,$(subst 4,,$(subst 5,,$(subst 6,,$(subst 7,,$(subst 8,,$(subst 9,,$(1)))))))))))
check_whole_number = $(if $(filter-out 1,$(words $($(2))))$(call digits_removed,$($(2))),\
    $(error $(1): $(2)='$($(2))': not a whole number (usage: $(5))),\
    $(if $(shell [ $($(2)) -ge $(3) -a $($(2)) -le $(4) ] 2>/dev/null && echo ok),,\
        $(error $(1): $(2)=$($(2)): out of range $(3)..$(4) (usage: $(5)))))

# $(call check_fraction,WHO,VAR,USAGE): as check_whole_number, for a probability:
# one plain decimal number (digits, at least one, and at most one point) within 0..1.
check_fraction = $(if $(filter-out 1,$(words $($(2))))$(if $(subst .,,$($(2))),,none)$(call digits_removed,$(subst .,,$($(2))))$(filter-out 1 2,$(words $(subst ., ,x$($(2))x))),\
    $(error $(1): $(2)='$($(2))': not a number 0..1 (usage: $(3))),\
    $(if $(shell awk 'BEGIN { exit !($($(2)) + 0 <= 1) }' 2>/dev/null && echo ok),,\
        $(error $(1): $(2)=$($(2)): out of range 0..1 (usage: $(3)))))

# The compiler runtime built for the CPU32 (soft-float, 64-bit division: LLVM's
# compiler-rt builtins, ci/setup.d/m68k.sh). Every firmware image links it instead
# of Debian's m68k libgcc, which is built for the 68020/68881 and traps on the CPU32.
# (ci/setup links it into this checkout's build/, whatever BUILD a make run uses.)
CPU32_RT := $(ROOT)/build/cpu32-rt/libbuiltins.a
# The C library built for the CPU32 (newlib, ci/setup.d/m68k/newlib.sh): its headers
# and libc.a/libm.a. Firmware sees only GCC's own headers and these (-nostdinc), never
# a C library of the build machine.
NEWLIB := $(ROOT)/build/newlib
FW_LIBC_LIBS := $(NEWLIB)/lib/libc.a $(NEWLIB)/lib/libm.a

# The seed of the runs that take one (make run's world, make net-soak): one default.
SEED ?= 1

HOST_CC     ?= cc
HOST_CFLAGS ?= -std=c99 -O2 -g -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror

ALL     :=
CHECKS  :=
PROOF_CHECKS :=
# The suites that run the emulated boards (QEMU): each fragment names its own beside
# its CHECKS line; make check-stress runs them again and again beside CPU hogs.
EMU_CHECKS :=

# Every part's fragment, in the order of the layers, lowest first, so that a
# fragment only reads variables of the fragments above it (a variable read in a
# rule's prerequisites is read when the line is parsed). No wildcard: a new
# fragment is added here, in its layer.
include bsched/bsched.mk
include bsched/proofs/ref/ref.mk
include bsched/proofs/wp/wp.mk
include bsched/proofs/cbmc/cbmc.mk
include bsched/dist/dist.mk
include bsched/tests/package/package.mk
include emu/emu.mk
include emu/io.mk
# The CPU ports' compiler flags, the boards (each declares the variables of
# mk/image.mk and nothing else) and the image pipeline that builds any image
# for any of them.
include kernel/arch/cpu32/port.mk
include kernel/arch/armv7m/port.mk
include boards/robocube/board.mk
include boards/stm32f405/board.mk
include boards/mps2-an385/board.mk
include mk/image.mk
include kernel/kernel.mk
include drivers/drivers.mk
include drivers/motion.mk
include drivers/shell.mk
include net/net.mk
include pdl/pdl.mk
include posix/posix.mk
include emu/world/world.mk
# Assurance: its checks run over every part above and every image.
include assure/assure.mk
# Firmware images last: they use the kernel's and the libraries' source lists.
include apps/apps.mk
# The bench: the library and Fig. 7 on the host and on a bare CPU32 image.
include bench/bench.mk
# The boards' own suites (the firmware on each beside the RoboCube).
include boards/stm32f405/tests/tests.mk
include boards/mps2-an385/tests/tests.mk

.PHONY: all check setup run clean check-stress
all: $(ALL)

# make check-stress: every emulator suite STRESS_ROUNDS times, one CPU hog per core
# beside them (ci/stress-checks); STRESS_SUITES picks some.
STRESS_ROUNDS ?= 20
STRESS_SUITES ?= $(EMU_CHECKS)
check-stress:
	$(call check_whole_number,check-stress,STRESS_ROUNDS,1,1000,make check-stress STRESS_ROUNDS=N [STRESS_SUITES="SUITE..."])
	$(if $(filter-out $(CHECKS),$(STRESS_SUITES)),$(error check-stress: not a suite: $(filter-out $(CHECKS),$(STRESS_SUITES)) (the suites are make check's)))
	@$(SETUP)
	@ci/stress-checks $(STRESS_ROUNDS) $(STRESS_SUITES)

setup:
	$(SETUP)

check:
	@$(SETUP)
	@ci/run-checks --proof-lane "$(PROOF_CHECKS)" $(CHECKS)

clean:
	rm -rf $(BUILD)
