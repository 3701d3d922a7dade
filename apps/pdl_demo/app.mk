# The example behaviours (pdl/examples/) as a PDL program: phototaxis,
# obstacle avoidance, wandering, battery motivation, superposed on motors 0
# and 1 (the arena robot's wiring, pdl/robot.h). make run APP=pdl_demo runs it
# in the ecosystem arena (WORLD=none: the board alone).
pdl_demo_NEEDS := console tick ports
pdl_demo_SRCS := $(wildcard apps/pdl_demo/*.c) pdl/examples/behaviours.c
pdl_demo_WORLD := default

# The PDL images' suite (pdl-target): pdl/tests/target/ runs this image against
# the board model over QMP, apps/pdl_bench (CPU load, stack, cycle costs,
# overruns) and apps/pdl_types (every quantity type, board against host). One
# suite for the three, as they share its test helpers (pdl_measure.py).
CHECKS += pdl-target
EMU_CHECKS += pdl-target
PDL_TARGET_ELFS = $(call app_elf,pdl_demo) $(call app_elf,pdl_bench) $(call app_elf,pdl_types)
.PHONY: check-pdl-target
check-pdl-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory $(PDL_TARGET_ELFS) $(PDL_TYPES_HOST)
	@BSCHED_QEMU=$(QEMU_M68K) FW_DIR=$(FW_BUILD) PDL_TYPES_HOST=$(PDL_TYPES_HOST) ci/pytest-suite pdl-target pdl/tests/target
