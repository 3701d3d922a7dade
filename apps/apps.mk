# Firmware images: one folder each, apps/NAME/, with an app.mk and its sources.
#
#   make firmware [APP=NAME]     build/firmware/NAME/NAME.elf (+ .srec, .map)
#   make firmware-all            every image
#   make run [APP=NAME]          boot it on the emulated RoboCube (default: $(APP_DEFAULT)),
#                                or run the app's host runner if it names one
#
# An image is apps/NAME/*.c, linked with the firmware base objects (startup,
# console, PIT, bsched.c: boards/robocube/board.mk), the C library and the CPU32
# compiler runtime (FW_LIBC_LIBS, CPU32_RT: Makefile), the nanokernel, the board's
# side of boards/include/ (start-up, LED: FW_BOARD_LIB_SRCS) and the libraries
# drivers/, net/, pdl/ and posix/ (every *.c directly in those folders; host
# code and tests live in their subfolders). The kernel and the libraries are
# compiled per image at the image's tick rate and linked as archives, so an
# image carries only the modules it calls. apps/NAME/app.mk may set:
#   NAME_TICK_HZ   kernel tick rate (default 1024)
#   NAME_CFLAGS    extra compiler flags for the image's own sources and libraries
#   NAME_SRCS      the image's sources (default apps/NAME/*.c)
#   NAME_SRCS_BOARD  its sources on another board (e.g. shell_SRCS_stm32f405),
#                  for an image with a part per board; default NAME_SRCS
#   NAME_RUN_ARGS  extra QEMU arguments for make run (serial ports, QMP, ...)
#   NAME_ICOUNT    the -icount setting for make run (default $(FW_ICOUNT))
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
# sensor noise) as for the ecosystem (emu/eco.mk), the summary in build/run/x/.

APPS        := $(sort $(notdir $(patsubst %/app.mk,%,$(wildcard apps/*/app.mk))))
# What make run boots when APP is not given: the ecosystem on the RoboCube;
# on another board, whose hardware it lacks, table1 (Table 2 from bsched.c).
APP_DEFAULT := $(if $(filter-out robocube,$(or $(BOARD),robocube)),table1,ecosystem)
APP         ?= $(APP_DEFAULT)
# Libraries every image may link: the target sources directly in these folders,
# and the board's interface (board, FW_BOARD_LIB_SRCS: boards/robocube/board.mk).
APP_LIB_DIRS := board drivers net pdl posix
APP_LIB_SRCS_board := $(FW_BOARD_LIB_SRCS)
APP_LIB_SRCS_pdl := $(wildcard pdl/*.c) $(FW_PDL_PORTS_SRCS)
# Already in the firmware base objects or the kernel's own source list; the
# main-thread start-up is linked by name (NAME_BOOT), never from the archive.
APP_BOOT_SRC := drivers/board_main.c
APP_LIB_EXCLUDE := $(FW_BASE_SRCS) $(K_TARGET_SRCS) $(APP_BOOT_SRC)
# Set by a part's .mk: flags its library sources need (net/: Mbed TLS's
# configuration and headers) and libraries they call (Mbed TLS for the CPU32),
# linked in the group with the images' libraries and the C library.

include $(wildcard apps/*/app.mk)

app_lib_srcs = $(filter-out $(APP_LIB_EXCLUDE),$(or $(APP_LIB_SRCS_$(1)),$(wildcard $(1)/*.c)))

# $(call app_lib_template,NAME,DIR): build/firmware/NAME/libDIR.a
define app_lib_template
$$(FW_BUILD)/$(1)/lib$(2).a: $$(patsubst %,$$(FW_BUILD)/$(1)/obj/%.o,$$(call app_lib_srcs,$(2)))
	@mkdir -p $$(@D)
	$$(call quiet,AR,$$@)rm -f $$@ && $$(CROSS_AR) rcs $$@ $$^
endef

# $(call app_template,NAME)
define app_template
$(1)_TICK_HZ ?= 1024
$(1)_SRCS    ?= $$(wildcard apps/$(1)/*.c)
$(1)_ICOUNT  ?= $$(FW_ICOUNT)
$(1)_BOOT    ?= board
$(1)_DIR     := $$(FW_BUILD)/$(1)
$(1)_FLAGS   := $$(FW_CFLAGS) -I$$(ROOT)/kernel/include -I$$(ROOT)/kernel \
                -DK_TICK_HZ=$$($(1)_TICK_HZ) -DFW_IMAGE_NAME='"$(1)"' $$(APP_LIB_CFLAGS) $$($(1)_CFLAGS)
$(1)_KOBJS   := $$(patsubst %,$$($(1)_DIR)/obj/%.o,$$(K_TARGET_SRCS))
$(1)_AOBJS   := $$(patsubst %,$$($(1)_DIR)/obj/%.o,$$($(1)_SRCS) \
                  $$(if $$(filter self,$$($(1)_BOOT)),,$$(APP_BOOT_SRC)))
$(1)_LIBS    := $$(foreach d,$$(APP_LIB_DIRS),$$(if $$(call app_lib_srcs,$$(d)),$$($(1)_DIR)/lib$$(d).a))

$$($(1)_DIR)/obj/%.c.o: %.c
	@mkdir -p $$(@D)
	$$(call quiet,CC,$$<)$$(CROSS_CC) $$($(1)_FLAGS) -c -o $$@ $$<

$$($(1)_DIR)/obj/%.S.o: %.S
	@mkdir -p $$(@D)
	$$(call quiet,CC,$$<)$$(CROSS_CC) $$(FW_ASFLAGS) -c -o $$@ $$<

$$(foreach d,$$(APP_LIB_DIRS),$$(eval $$(call app_lib_template,$(1),$$(d))))

$$(call app_elf,$(1)): $$(FW_BASE_OBJS) $$($(1)_KOBJS) $$($(1)_AOBJS) $$($(1)_LIBS) $$(FW_LDSCRIPT) $$(CPU32_RT) \
                       $$(FW_LIBC_LIBS) $$(APP_LIB_LINK)
	$$(call quiet,LD,$$@)$$(CROSS_CC) $$(FW_LDFLAGS) -Wl,-Map=$$(@:.elf=.map) -o $$@ $$(FW_BASE_OBJS) $$($(1)_KOBJS) \
	    $$($(1)_AOBJS) -Wl,--start-group $$($(1)_LIBS) $$(APP_LIB_LINK) $$(FW_LIBC_LIBS) -Wl,--end-group $$(CPU32_RT)
	$$(call quiet,OBJCOPY,$$@)$$(CROSS_OBJCOPY) -O srec $$@ $$(@:.elf=.srec)
	$$(if $$(filter 1,$$(V)),$$(CROSS_SIZE) $$@,@true)

.SECONDARY: $$($(1)_KOBJS) $$($(1)_AOBJS) $$(patsubst %,$$($(1)_DIR)/obj/%.o,$$(foreach d,$$(APP_LIB_DIRS),$$(call app_lib_srcs,$$(d))))
endef

$(foreach a,$(APPS),$(eval $(call app_template,$(a))))

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
# The board an image is built for and runs on: the RoboCube (this file and
# boards/robocube/) or another of boards/NAME/ (its board.mk has the rules).
BOARDS := $(sort robocube $(notdir $(patsubst %/board.mk,%,$(wildcard boards/*/board.mk))))
BOARD  ?= robocube
ifneq ($(filter run firmware,$(MAKECMDGOALS)),)
ifneq ($(words $(BOARD)),1)
$(error BOARD='$(BOARD)': one board name (usage: make run [BOARD=$(subst $(eval) ,|,$(BOARDS))] [APP=NAME]))
endif
ifeq ($(filter $(BOARD),$(BOARDS)),)
$(error BOARD=$(BOARD): no such board (usage: make run [BOARD=$(subst $(eval) ,|,$(BOARDS))] [APP=NAME]))
endif
endif

ifeq ($(filter $(APP),$(APPS)),)
$(if $(filter run firmware,$(MAKECMDGOALS)),$(error APP=$(APP): no such image (have: $(APPS))))
endif

FW_ELF := $(call app_elf,$(APP))

.PHONY: firmware firmware-all run
firmware-all: $(foreach a,$(APPS),$(call app_elf,$(a)))
ifneq ($(BOARD),robocube)
firmware: firmware-$(BOARD)
else
firmware: $(FW_ELF)
endif

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
run:
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
	    $(QEMU_M68K) -M robocube -icount $($(APP)_ICOUNT) -kernel $(FW_ELF) $(QEMU_CONSOLE_ARGS) $($(APP)_RUN_ARGS); rc=$$?; \
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
