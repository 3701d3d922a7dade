# The world: the simulated arena and the lockstep co-simulation (emu/world/,
# see its README). It runs whatever robot program it is given (an ELF on the
# emulated board, or a host library with the eco_host_* calls of hostmode.py)
# and names no image: the ecosystem image (apps/ecosystem/app.mk) uses it as
# its runner and declares its own tests.
#
#   make run SIM_SECONDS=600 SEED=7 ARENA=my.json   (APP=ecosystem, the default)

WORLD_RUN    := $(ROOT)/emu/world/run.py
SIM_SECONDS  ?= 120
ARENA        ?=
WORLD_RUN_ARGS  = --seconds $(SIM_SECONDS) --seed $(SEED) --out $(BUILD)/run \
                  $(if $(ARENA),--arena $(ARENA),$(if $(WORLD),--arena $(ROOT)/emu/world/arenas/$(WORLD).json))
WORLD_RUN_USAGE = make run [SIM_SECONDS=1..86400] [SEED=0..4294967295] [ARENA=FILE]
# Checked before anything is built (the seed is the program's 32-bit seed).
ifneq ($(filter run,$(MAKECMDGOALS)),)
ifeq ($(or $(APP),ecosystem),ecosystem)
$(call check_whole_number,make run,SIM_SECONDS,1,86400,$(WORLD_RUN_USAGE))
$(call check_whole_number,make run,SEED,0,4294967295,$(WORLD_RUN_USAGE))
endif
endif
