# The ecosystem robot: the behaviour program (eco_program.c) on the
# nanokernel's B-scheduler thread, one minor cycle every 2 ticks of 128 Hz
# (64 Hz), against the simulated world in lockstep (emu/world/).
# `make run` (APP=ecosystem, the default) starts it through the host runner;
# WORLD=NAME picks the arena (emu/world/arenas/NAME.json, or ARENA=FILE),
# HOST=1 runs the same program on the host (fast mode).
ecosystem_TICK_HZ := 128
ecosystem_WORLD   := default
ecosystem_RUNNER  = $(PYTHON) $(ROOT)/emu/world/run.py \
                    $(if $(filter 1,$(HOST)),--host,--elf $(call app_elf,ecosystem) --qemu $(QEMU_M68K)) \
                    --host-lib $(ECO_HOST_LIB) $(ECO_RUN_ARGS)
ecosystem_RUN_DEPS = eco-host
# Its main starts the board itself (board_start ... k_start).
ecosystem_BOOT := self
