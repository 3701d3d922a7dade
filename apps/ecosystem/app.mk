# The ecosystem robot: the behaviour program (eco_program.c) on the
# nanokernel's B-scheduler thread, one minor cycle every 2 ticks of 128 Hz
# (64 Hz), against the simulated world in lockstep (emu/world/, its runner).
# The same program on the PDL host runtime (host/eco_host.c, pdl/host/) is the
# world's fast mode. `make run` (APP=ecosystem, the default) starts it
# through the world's runner; WORLD=NAME picks the arena
# (emu/world/arenas/NAME.json, or ARENA=FILE), HOST=1 runs the program on the host.
#
#   make run                        the ecosystem (SIM_SECONDS, SEED, ARENA: emu/world/world.mk)
#   make eco-host                   build/world/libeco_host.so (the program for the host)
#   make check-eco                  world, lockstep and ecosystem tests (pytest, ~2-3 min)
#   make eco-survival               the full goal: 10 virtual minutes on the emulated board
# What it needs of a board (mk/image.mk): the arena's co-simulation and the ports PDL binds.
ecosystem_NEEDS := console tick ports world
ecosystem_TICK_HZ := 128
ecosystem_WORLD   := default
ECO_HOST_LIB := $(BUILD)/world/libeco_host.so
ECO_ELF       = $(call app_elf,ecosystem)
ecosystem_RUNNER  = $(PYTHON) $(WORLD_RUN) \
                    $(if $(filter 1,$(HOST)),--host,--elf $(ECO_ELF) --qemu $(QEMU_M68K)) \
                    --host-lib $(ECO_HOST_LIB) $(WORLD_RUN_ARGS)
ecosystem_RUN_DEPS = eco-host
# Its main starts the board itself (board_start ... k_start).
ecosystem_BOOT := self

CHECKS += eco
EMU_CHECKS += eco
ALL    += $(ECO_HOST_LIB)

.PHONY: eco-host check-eco eco-survival
eco-host: $(ECO_HOST_LIB)

# The PDL program on the PDL host runtime (pdl/pdl.mk's PDL_HOST_SRCS: the
# same pdl_core.c and bsched.c as on the board), for the host (ctypes).
$(ECO_HOST_LIB): apps/ecosystem/host/eco_host.c apps/ecosystem/eco_program.c apps/ecosystem/eco_program.h \
                 $(PDL_HOST_SRCS) $(PDL_HEADERS)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(HOST_CFLAGS) -fPIC -shared -I$(ROOT) -Ibsched -Iapps/ecosystem -o $@ \
	    apps/ecosystem/host/eco_host.c apps/ecosystem/eco_program.c $(PDL_HOST_SRCS)

ECO_TEST_ENV = BSCHED_QEMU=$(QEMU_M68K) ECO_ELF=$(ECO_ELF) ECO_HOST_LIB=$(ECO_HOST_LIB)

check-eco:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware eco-host APP=ecosystem
	@$(ECO_TEST_ENV) $(ROOT)/ci/pytest-suite eco $(ROOT)/emu/world/tests

# The goal on the emulated board, 10 virtual minutes (a few minutes of wall time).
eco-survival:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware eco-host APP=ecosystem
	@$(ECO_TEST_ENV) ECO_SURVIVAL_SECONDS=600 $(PYTHON) -m pytest -q -rP -p no:cacheprovider \
	    $(ROOT)/emu/world/tests/test_ecosystem.py -k survival_emulated_and_alike

# The host library's dependencies are complete: make calls it up to date after
# a build, and out of date (and rebuilds it) once any of its sources is new
# (make -W: as if touched, without changing the tree other suites read). A few
# seconds (one rebuild of the library).
# The list is written out, not taken from the variables the rule uses, so that
# a variable read before it is set (a make file included too early) shows.
ECO_HOST_DEP_SRCS := apps/ecosystem/host/eco_host.c apps/ecosystem/eco_program.c apps/ecosystem/eco_program.h \
                     pdl/pdl_core.c pdl/pdl_bind.c pdl/pdl_state.c pdl/host/pdl_host.c bsched/bsched.c \
                     pdl/pdl.h pdl/host/pdl_host.h bsched/bsched.h boards/include/board_ports.h \
                     boards/robocube/ports.c
CHECKS += eco-host-deps
.PHONY: check-eco-host-deps
check-eco-host-deps: $(ECO_HOST_LIB)
	@pass=0; fail=0; lib=$(ECO_HOST_LIB); \
	if $(MAKE) --no-print-directory -q $$lib; then pass=$$((pass+1)); echo "ok: $$lib up to date after its build"; \
	else fail=$$((fail+1)); echo "FAILED: $$lib out of date right after its build"; fi; \
	for src in $(ECO_HOST_DEP_SRCS); do \
	    if $(MAKE) --no-print-directory -q -W $$src $$lib; then fail=$$((fail+1)); echo "FAILED: $$src new, and make calls $$lib up to date (a stale build)"; \
	    else pass=$$((pass+1)); echo "ok: $$src new: $$lib is rebuilt"; fi; \
	done; \
	before=$$(stat -c %Y.%y $$lib); sleep 1; \
	if $(MAKE) --no-print-directory -W bsched/bsched.c $$lib >/dev/null && [ "$$(stat -c %Y.%y $$lib)" != "$$before" ]; then \
	    pass=$$((pass+1)); echo "ok: bsched/bsched.c new: make rebuilt $$lib"; \
	else fail=$$((fail+1)); echo "FAILED: bsched/bsched.c new: make did not rebuild $$lib"; fi; \
	$(call record,eco-host-deps,$$pass,$$fail); echo "eco-host-deps: $$pass passed, $$fail failed"; [ $$fail -eq 0 ]
