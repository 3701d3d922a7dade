# Firmware images: one folder each, apps/NAME/, with an app.mk and its sources.
#
#   make firmware [APP=NAME] [BOARD=B]  the image for board B (default robocube):
#                                build/firmware/NAME/NAME.elf (+ .srec, .map) on the RoboCube,
#                                BOARD_B_BUILD/NAME/NAME.elf (+ .bin, .map) on another
#   make firmware-all            every image for the RoboCube
#   make run [APP=NAME] [BOARD=B]  boot it on the emulated board (default: $(APP_DEFAULT)),
#                                or run the app's host runner if it names one
#
# The image pipeline is mk/image.mk: an image is apps/NAME/*.c, linked with the
# board's base (start-up, console, bsched.c), the nanokernel at the image's tick
# rate, the board interface and the libraries drivers/, net/, pdl/ and posix/,
# archives compiled per image, so an image carries only the modules it calls,
# and the board's C library. apps/NAME/app.mk may set:
#   NAME_NEEDS     the capabilities it needs of a board (mk/image.mk's IMAGE_CAPS;
#                  default console tick libc ports, what a program from the
#                  PDL template uses): make refuses a board that lacks one
#   NAME_BOARDS    the boards it is for (default every board that has what it needs)
#   NAME_TICK_HZ   kernel tick rate (default 1024)
#   NAME_CFLAGS    extra compiler flags for the image's own sources and libraries
#   NAME_SRCS      the image's sources (default apps/NAME/*.c)
#   NAME_SRCS_BOARD  its sources on board BOARD (e.g. shell_SRCS_stm32f405),
#                  for an image with a part per board; default NAME_SRCS
#   NAME_RUN_ARGS  extra QEMU arguments for make run (serial ports, QMP, ...)
#   NAME_ICOUNT_BOARD  the -icount setting for make run on BOARD (default BOARD_BOARD_ICOUNT)
#   NAME_RUNNER    a host command that make run starts instead of QEMU on the
#                  console (e.g. a co-simulation that starts QEMU itself)
#   NAME_RUN_DEPS  further targets make run builds first (e.g. host libraries)
#   NAME_BOOT      'self' for an image whose main starts the board itself
#                  (board_start ... k_start); by default the image links
#                  drivers/board_main.c, which starts the board and runs an
#                  ordinary int main(void) as a thread
#   NAME_QUIT      how the image itself ends a run, for make run's banner
#   NAME_WORLD     the arena make run puts the image's robot in when WORLD is
#                  not given (default none: the board alone)
#
# Where make run runs the program (a PDL program with an ordinary main):
#   make run APP=x                 the emulated board alone (console on stdio)
#   make run APP=x WORLD=default   the board in the arena emu/world/arenas/default.json,
#                                  in lockstep; the world feeds the robot's sensors and
#                                  takes its wheels (the wiring: pdl/robot.h)
#   make run APP=x HOST=1          the same program on the PDL host runtime in the same
#                                  arena (WORLD defaults to default), fast
# In an arena: SIM_SECONDS (virtual seconds, default 120) and SEED (the world's
# sensor noise) as for the ecosystem (emu/world/world.mk), the summary in build/run/x/.

APPS        := $(sort $(notdir $(patsubst %/app.mk,%,$(wildcard apps/*/app.mk))))
# What make run boots when APP is not given: the ecosystem on the RoboCube;
# on another board, whose hardware it lacks, table1 (Table 2 from bsched.c).
APP_DEFAULT := $(if $(filter-out robocube,$(or $(BOARD),robocube)),table1,ecosystem)
APP         ?= $(APP_DEFAULT)
include $(wildcard apps/*/app.mk)

# An app's defaults, its sources on a board, and why it does not build there.
define app_defaults
$(1)_TICK_HZ ?= 1024
$(1)_SRCS    ?= $$(wildcard apps/$(1)/*.c)
$(1)_BOOT    ?= board
$(1)_NEEDS   ?= console tick libc ports
$(1)_BOARDS  ?= $$(IMAGE_BOARDS)
endef
$(foreach a,$(APPS),$(eval $(call app_defaults,$(a))))
# The image of app NAME on BOARD, and on the RoboCube.
image_elf = $(BOARD_$(1)_BUILD)/$(2)/$(2).elf
app_elf   = $(call image_elf,robocube,$(1))
app_srcs  = $(or $($(2)_SRCS_$(1)),$($(2)_SRCS)) $(if $(filter self,$($(2)_BOOT)),,$(APP_BOOT_SRC))
# $(call app_refusal,BOARD,NAME): the line make stops with when NAME does not
# build for BOARD (empty when it does).
app_refusal = $(strip $(if $(filter $(1),$($(2)_BOARDS)),\
    $(if $(call board_lacks,$(1),$($(2)_NEEDS)),APP=$(2) needs $(call board_lacks,$(1),$($(2)_NEEDS)): BOARD=$(1) lacks $(if $(word 2,$(call board_lacks,$(1),$($(2)_NEEDS))),them,it) (it has: $(BOARD_$(1)_CAPS))),\
    APP=$(2) is for BOARD=$(subst $(space),|,$($(2)_BOARDS)) only))
app_icount = $(or $($(2)_ICOUNT_$(1)),$(BOARD_$(1)_ICOUNT))

$(foreach b,$(IMAGE_BOARDS),$(foreach a,$(APPS),$(if $(call app_refusal,$(b),$(a)),,\
    $(eval $(call image,$(b),$(a),$(BOARD_$(b)_BUILD)/$(a),$(call image_elf,$(b),$(a)),$(call app_srcs,$(b),$(a)),\
        -DK_TICK_HZ=$($(a)_TICK_HZ) $(APP_LIB_CFLAGS) $($(a)_CFLAGS),app)))))

# A program on the PDL host runtime, for the arena's host mode (make run
# APP=NAME HOST=1): its sources with main renamed, the arena's driver of main
# and the cycles (pdl/host/pdl_app_host.c) and the host runtime, as one
# shared library the arena loads (emu/world/hostmode.py). PDL_HOST is defined,
# for the few lines a program keeps for the board (pdl/pdl_board.h).
app_host_lib = $(BUILD)/world/apps/$(1)/lib$(1)_host.so
APP_HOST_DRIVER := pdl/host/pdl_app_host.c
define app_host_template
$$(call app_host_lib,$(1)): $$($(1)_SRCS) $$(wildcard apps/$(1)/*.h) $$(APP_HOST_DRIVER) $$(PDL_HOST_SRCS) $$(PDL_HEADERS)
	@mkdir -p $$(@D)
	$$(call quiet,HOSTCC,$$@)$$(HOST_CC) $$(HOST_CFLAGS) -fPIC -shared -pthread -DPDL_HOST=1 -Dmain=pdl_app_main \
	    -I$$(ROOT) -I$$(ROOT)/bsched -Iapps/$(1) -o $$@ $$($(1)_SRCS) $$(APP_HOST_DRIVER) $$(PDL_HOST_SRCS)
endef
$(foreach a,$(APPS),$(eval $(call app_host_template,$(a))))
# make host-lib [APP=NAME]: that library (phony: quiet when it is up to date).
.PHONY: host-lib
host-lib: $(call app_host_lib,$(APP))
# The board an image is built for and runs on (boards/NAME/, mk/image.mk).
BOARD  ?= robocube
BOARD_GOALS := run firmware $(foreach b,$(IMAGE_BOARDS),run-$(b) firmware-$(b))
ifneq ($(filter $(BOARD_GOALS),$(MAKECMDGOALS)),)
ifneq ($(words $(BOARD)),1)
$(error BOARD='$(BOARD)': one board name (usage: make run [BOARD=$(subst $(eval) ,|,$(IMAGE_BOARDS))] [APP=NAME]))
endif
ifeq ($(filter $(BOARD),$(IMAGE_BOARDS)),)
$(error BOARD=$(BOARD): no such board (usage: make run [BOARD=$(subst $(eval) ,|,$(IMAGE_BOARDS))] [APP=NAME]))
endif
ifeq ($(filter $(APP),$(APPS)),)
$(error APP=$(APP): no such image (have: $(APPS)))
endif
# An image that needs what the board lacks stops here, in one line.
$(foreach b,$(or $(patsubst run-%,%,$(patsubst firmware-%,%,$(filter $(foreach b,$(IMAGE_BOARDS),run-$(b) firmware-$(b)),$(MAKECMDGOALS)))),$(BOARD)),\
    $(if $(call app_refusal,$(b),$(APP)),$(error $(call app_refusal,$(b),$(APP)))))
endif

FW_ELF := $(call app_elf,$(APP))

.PHONY: firmware firmware-all run $(foreach b,$(IMAGE_BOARDS),run-$(b) firmware-$(b))
firmware-all: $(foreach a,$(APPS),$(call app_elf,$(a)))
firmware: firmware-$(BOARD)
$(foreach b,$(IMAGE_BOARDS),$(eval firmware-$(b): $(call image_elf,$(b),$(APP))))

# make run on a board without the RoboCube's world: the image on its QEMU
# machine, console on stdio. Piped input waits for the board's first output
# (robocube_emu.console_gate): QEMU's USART model drops what it is given
# before the firmware enables it.
define run_board
run-$(1):
	@$$(SETUP) base $(BOARD_$(1)_SETUP)
	@$$(MAKE) --no-print-directory $$(if $$(filter 1,$$(V)),,-s) firmware-$(1) BOARD=$(1) APP=$$(APP)
	@echo "make run: booting $$(call image_elf,$(1),$$(APP)) on $(notdir $(BOARD_$(1)_QEMU)) -M $(BOARD_$(1)_QEMU_MACHINE) (console = $(BOARD_$(1)_CONSOLE) on stdio$$(if $$(RUN_SECONDS),; stops after $$(RUN_SECONDS) s)$$(if $$($$(APP)_QUIT),; $$($$(APP)_QUIT)); quit with Ctrl-C)" >&2
	@$$(if $$(RUN_SECONDS),timeout --foreground $$(RUN_SECONDS)) \
	    $$$$([ -t 0 ] || echo $$(PYTHON) -m robocube_emu.console_gate) $(BOARD_$(1)_QEMU) -M $(BOARD_$(1)_QEMU_MACHINE) \
	    -icount $$(call app_icount,$(1),$$(APP)) -kernel $$(call image_elf,$(1),$$(APP)) $$(QEMU_CONSOLE_ARGS) $(BOARD_$(1)_QEMU_ARGS) \
	    $$($$(APP)_RUN_ARGS); rc=$$$$?; [ $$$$rc -eq 0 ] || [ "$$(RUN_SECONDS)" != "" -a $$$$rc -eq 124 ]
endef
$(foreach b,$(filter-out robocube,$(IMAGE_BOARDS)),$(eval $(call run_board,$(b))))

# make run's options, checked before anything is built: a bad value gets one
# line naming it (make's $(error): exit status 2), never a raw error from
# timeout or a traceback from a runner (the ecosystem's SEED and SIM_SECONDS:
# emu/world/world.mk).
RUN_SECONDS ?=
HOST ?=
WORLD ?=
WORLDS    := $(sort $(basename $(notdir $(wildcard emu/world/arenas/*.json))))
RUN_WORLD := $(or $(WORLD),$($(APP)_WORLD),$(if $(filter 1,$(HOST)),default),none)
RUN_USAGE := make run [APP=NAME] [WORLD=none|$(subst $(space),|,$(WORLDS))] [HOST=0|1] [RUN_SECONDS=1..86400] [SIM_SECONDS=1..86400] [SEED=0..4294967295]
RUN_IN_ARENA := $(if $(filter none,$(RUN_WORLD)),,1)
ifneq ($(filter run,$(MAKECMDGOALS)),)
ifneq ($(RUN_SECONDS),)
$(call check_whole_number,make run,RUN_SECONDS,1,86400,$(RUN_USAGE))
endif
ifneq ($(filter-out 0 1,$(HOST))$(word 2,$(HOST)),)
$(error make run: HOST='$(HOST)': use HOST=1 (the host runtime) or HOST=0 (usage: $(RUN_USAGE)))
endif
ifneq ($(filter-out none $(WORLDS),$(RUN_WORLD))$(word 2,$(RUN_WORLD)),)
$(error make run: WORLD='$(WORLD)': no such arena (have: none $(WORLDS); emu/world/arenas/NAME.json) (usage: $(RUN_USAGE)))
endif
ifeq ($(HOST)$(RUN_WORLD),1none)
$(error make run: HOST=1 runs the program in an arena; WORLD=none has no host mode (usage: $(RUN_USAGE)))
endif
ifneq ($(filter 1,$(HOST)),)
ifneq ($(filter self,$($(APP)_BOOT)),)
ifeq ($(filter ecosystem,$(APP)),)
$(error make run: APP=$(APP) cannot run on the host: its main starts the board itself (HOST=1 runs programs with an ordinary main))
endif
endif
endif
ifneq ($($(APP)_RUNNER),)
ifeq ($(filter ecosystem,$(APP)),)
ifneq ($(WORLD),)
$(error make run: APP=$(APP) has a set-up of its own; WORLD does not apply (usage: $(RUN_USAGE)))
endif
else ifeq ($(WORLD),none)
$(error make run: APP=ecosystem is the arena's robot; WORLD=none does not apply (usage: $(RUN_USAGE)))
endif
endif
ifneq ($(RUN_IN_ARENA),)
$(call check_whole_number,make run,SIM_SECONDS,1,86400,$(RUN_USAGE))
$(call check_whole_number,make run,SEED,0,4294967295,$(RUN_USAGE))
endif
endif

# make run in an arena (emu/world/run.py): the image on the emulated board in
# lockstep, or with HOST=1 the program's host library (app_host_lib).
ARENA_RUN = $(PYTHON) $(ROOT)/emu/world/run.py --arena $(ROOT)/emu/world/arenas/$(RUN_WORLD).json \
    --seconds $(SIM_SECONDS) --seed $(SEED) --out $(BUILD)/run/$(APP) \
    $(if $(filter 1,$(HOST)),--host --host-lib $(call app_host_lib,$(APP)),--elf $(FW_ELF) --qemu $(QEMU_M68K))

# The console is the emulator's stdio and carries bytes only, with -monitor
# none: not QEMU's no-graphics mode, which multiplexes its monitor onto stdin
# (Ctrl-A c there gives whoever writes to the console the monitor, and with
# migrate "exec:..." commands on the host). The stdio chardev keeps its default signal=on, so Ctrl-C
# typed at the terminal ends QEMU (and make run); an image can also end the
# run itself (the shell's `exit`: apps/shell/README.md). QEMU_CONSOLE_ARGS is
# the one place make run names the console; the shell's tests check it.
QEMU_CONSOLE_ARGS := -display none -monitor none -serial stdio
ifneq ($(BOARD),robocube)
run: run-$(BOARD)
else
run: run-robocube
run-robocube:
	@$(SETUP) qemu m68k $(if $($(APP)_RUNNER)$(RUN_IN_ARENA),base)
	@$(MAKE) --no-print-directory $(if $(filter 1,$(V)),,-s) $(if $(filter 1,$(HOST)),,firmware) $($(APP)_RUN_DEPS) APP=$(APP) \
	    $(if $(and $(filter 1,$(HOST)),$(if $($(APP)_RUNNER),,1)),host-lib)
ifneq ($($(APP)_RUNNER),)
	@$(if $(RUN_SECONDS),timeout --foreground $(RUN_SECONDS)) $($(APP)_RUNNER); rc=$$?; \
	    [ $$rc -eq 0 ] || { [ "$(RUN_SECONDS)" != "" -a $$rc -eq 124 ] && echo "make run: stopped after RUN_SECONDS=$(RUN_SECONDS) s" >&2; }
else ifneq ($(RUN_IN_ARENA),)
	@$(if $(RUN_SECONDS),timeout --foreground $(RUN_SECONDS)) $(ARENA_RUN); rc=$$?; \
	    [ $$rc -eq 0 ] || { [ "$(RUN_SECONDS)" != "" -a $$rc -eq 124 ] && echo "make run: stopped after RUN_SECONDS=$(RUN_SECONDS) s" >&2; }
else
	@echo "make run: booting $(FW_ELF) on $(QEMU_M68K) -M robocube (console = DUART B on stdio$(if $(RUN_SECONDS),; stops after $(RUN_SECONDS) s)$(if $($(APP)_QUIT),; $($(APP)_QUIT)); quit with Ctrl-C)" >&2
	@$(if $(RUN_SECONDS),timeout --foreground $(RUN_SECONDS)) \
	    $(QEMU_M68K) -M robocube -icount $(call app_icount,robocube,$(APP)) -kernel $(FW_ELF) $(QEMU_CONSOLE_ARGS) $($(APP)_RUN_ARGS); rc=$$?; \
	    [ $$rc -eq 0 ] || [ "$(RUN_SECONDS)" != "" -a $$rc -eq 124 ]
endif
endif

# make new-app NAME=x: apps/x/ from the PDL program template (apps/pdl_hello),
# ready for make run APP=x. NAME: a lower-case C identifier not yet taken.
NEW_APP_TEMPLATE := apps/pdl_hello
.PHONY: new-app
# Through the environment, so no character of NAME reaches the shell as syntax.
new-app: export NEW_APP_NAME = $(NAME)
new-app:
	@name="$$NEW_APP_NAME"; \
	if ! printf '%s' "$$name" | grep -Eqx '[a-z][a-z0-9_]{0,31}'; then \
	    echo "make new-app: NAME='$$name': use a lower-case C identifier of 1-32 characters (make new-app NAME=my_robot)" >&2; exit 2; fi; \
	if [ -e "apps/$$name" ]; then \
	    echo "make new-app: apps/$$name exists already; choose another NAME" >&2; exit 2; fi; \
	mkdir -p "apps/$$name" && cp $(NEW_APP_TEMPLATE)/main.c "apps/$$name/main.c" && \
	echo "# A PDL program: apps/$$name/main.c (make run APP=$$name)." > "apps/$$name/app.mk" && \
	echo "created apps/$$name/ (main.c from $(NEW_APP_TEMPLATE)): make run APP=$$name [WORLD=default: in the arena] [HOST=1: on the host, in the arena]"

CHECKS += new-app
EMU_CHECKS += new-app
.PHONY: check-new-app
check-new-app:
	@$(SETUP) base m68k qemu
	@BSCHED_QEMU=$(QEMU_M68K) ci/pytest-suite new-app apps/pdl_hello/tests
