# emu core: qemu-system-m68k with the RoboCube board (machine, SIM, QSM SCI,
# MC68681 DUART, interrupt arbitration, CPU32 bus errors), built by
# ci/setup qemu from bookworm's QEMU 7.2 source plus emu/hw and emu/qemu-patches.
#   make emu              build (or incrementally rebuild) the QEMU binary
#   make check-emu-core   qtest device tests of the board core (emu/tests/test_core_*.py)
# This checkout's link to the binary built from its own emu/ (ci/setup.d/qemu.sh).
QEMU_M68K := $(BUILD)/emu/qemu-system-m68k
export BSCHED_QEMU := $(QEMU_M68K)

CHECKS += emu-core
EMU_CHECKS += emu-core

.PHONY: emu check-emu-core
emu:
	@$(SETUP) qemu

# m68k: the cross assembler builds the tiny CPU-side test programs (bus errors, IACK).
check-emu-core:
	@$(SETUP) base m68k qemu
	@$(ROOT)/ci/pytest-suite emu-core $(ROOT)/emu/tests/test_core_*.py
