# The ecosystem: the world simulation and the lockstep
# co-simulation (emu/world/), the ecosystem firmware (apps/ecosystem/) and
# the host fast mode's library. See emu/world/README.md.
#
#   make run                        the ecosystem (APP=ecosystem is the default image)
#   make run SIM_SECONDS=600 SEED=7 ARENA=my.json
#   make eco-host                   build/world/libeco_host.so (the program for the host)
#   make check-eco                  world, lockstep and ecosystem tests (pytest, ~2-3 min)
#   make eco-survival               the full goal: 10 virtual minutes on the emulated board

ECO_HOST_LIB := $(BUILD)/world/libeco_host.so
ECO_ELF       = $(call app_elf,ecosystem)
SIM_SECONDS  ?= 120
SEED         ?= 1
ARENA        ?=
ECO_RUN_ARGS  = --seconds $(SIM_SECONDS) --seed $(SEED) --out $(BUILD)/run \
                $(if $(ARENA),--arena $(ARENA),$(if $(WORLD),--arena $(ROOT)/emu/world/arenas/$(WORLD).json))
ECO_RUN_USAGE = make run [SIM_SECONDS=1..86400] [SEED=0..4294967295] [ARENA=FILE]
# Checked before anything is built (the seed is the program's 32-bit seed).
ifneq ($(filter run,$(MAKECMDGOALS)),)
ifeq ($(or $(APP),ecosystem),ecosystem)
$(call check_whole_number,make run,SIM_SECONDS,1,86400,$(ECO_RUN_USAGE))
$(call check_whole_number,make run,SEED,0,4294967295,$(ECO_RUN_USAGE))
endif
endif

CHECKS += eco
ALL    += $(ECO_HOST_LIB)

.PHONY: eco-host check-eco eco-survival
eco-host: $(ECO_HOST_LIB)

# The PDL program on the PDL host runtime (pdl/pdl.mk's PDL_HOST_SRCS: the
# same pdl_core.c and bsched.c as on the board), for the host (ctypes).
$(ECO_HOST_LIB): emu/world/host/eco_host.c apps/ecosystem/eco_program.c apps/ecosystem/eco_program.h \
                 $(PDL_HOST_SRCS) pdl/pdl.h pdl/host/pdl_host.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(HOST_CFLAGS) -fPIC -shared -I$(ROOT) -Ibsched -Iapps/ecosystem -o $@ \
	    emu/world/host/eco_host.c apps/ecosystem/eco_program.c $(PDL_HOST_SRCS)

ECO_TEST_ENV = BSCHED_QEMU=$(QEMU_M68K) ECO_ELF=$(ECO_ELF) ECO_HOST_LIB=$(ECO_HOST_LIB)

check-eco:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware eco-host APP=ecosystem
	@$(ECO_TEST_ENV) $(ROOT)/ci/pytest-suite eco $(ROOT)/emu/world/tests

# The issue's goal on the emulated board, 10 virtual minutes (a few minutes of wall time).
eco-survival:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware eco-host APP=ecosystem
	@$(ECO_TEST_ENV) ECO_SURVIVAL_SECONDS=600 $(PYTHON) -m pytest -q -rP -p no:cacheprovider \
	    $(ROOT)/emu/world/tests/test_ecosystem.py -k survival_emulated_and_alike
