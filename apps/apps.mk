# Firmware images: one folder each, apps/NAME/, with an app.mk and its sources.
#
#   make firmware [APP=NAME]     build/firmware/NAME/NAME.elf (+ .srec, .map)
#   make firmware-all            every image
#   make run [APP=NAME]          boot it on the emulated RoboCube (default: $(APP_DEFAULT)),
#                                or run the app's host runner if it names one
#
# An image is apps/NAME/*.c, linked with the firmware base objects (startup,
# console, PIT, LED, bsched.c: kernel/firmware.mk), the C library and the CPU32
# compiler runtime (FW_LIBC_LIBS, CPU32_RT: Makefile), the nanokernel and the
# libraries drivers/, net/ and pdl/ (every *.c directly in those folders; host
# code and tests live in their subfolders). The kernel and the libraries are
# compiled per image at the image's tick rate and linked as archives, so an
# image carries only the modules it calls. apps/NAME/app.mk may set:
#   NAME_TICK_HZ   kernel tick rate (default 1024)
#   NAME_CFLAGS    extra compiler flags for the image's own sources and libraries
#   NAME_SRCS      the image's sources (default apps/NAME/*.c)
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

APPS        := $(sort $(notdir $(patsubst %/app.mk,%,$(wildcard apps/*/app.mk))))
APP_DEFAULT := ecosystem
APP         ?= $(APP_DEFAULT)
# Libraries every image may link: the target sources directly in these folders.
APP_LIB_DIRS := drivers net pdl
# Already in the firmware base objects or the kernel's own source list; the
# main-thread start-up is linked by name (NAME_BOOT), never from the archive.
APP_BOOT_SRC := drivers/board_main.c
APP_LIB_EXCLUDE := $(FW_BASE_SRCS) $(K_TARGET_SRCS) $(APP_BOOT_SRC)
# Set by a part's .mk: flags its library sources need (net/: Mbed TLS's
# configuration and headers) and libraries they call (Mbed TLS for the CPU32),
# linked in the group with the images' libraries and the C library.

include $(wildcard apps/*/app.mk)

app_lib_srcs = $(filter-out $(APP_LIB_EXCLUDE),$(wildcard $(1)/*.c))

# $(call app_lib_template,NAME,DIR): build/firmware/NAME/libDIR.a
define app_lib_template
$$(FW_BUILD)/$(1)/lib$(2).a: $$(patsubst %,$$(FW_BUILD)/$(1)/obj/%.o,$$(call app_lib_srcs,$(2)))
	@mkdir -p $$(@D)
	rm -f $$@ && $$(CROSS_AR) rcs $$@ $$^
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
	$$(CROSS_CC) $$($(1)_FLAGS) -c -o $$@ $$<

$$($(1)_DIR)/obj/%.S.o: %.S
	@mkdir -p $$(@D)
	$$(CROSS_CC) $$(FW_ASFLAGS) -c -o $$@ $$<

$$(foreach d,$$(APP_LIB_DIRS),$$(eval $$(call app_lib_template,$(1),$$(d))))

$$(call app_elf,$(1)): $$(FW_BASE_OBJS) $$($(1)_KOBJS) $$($(1)_AOBJS) $$($(1)_LIBS) $$(FW_LDSCRIPT) $$(CPU32_RT) \
                       $$(FW_LIBC_LIBS) $$(APP_LIB_LINK)
	$$(CROSS_CC) $$(FW_LDFLAGS) -Wl,-Map=$$(@:.elf=.map) -o $$@ $$(FW_BASE_OBJS) $$($(1)_KOBJS) \
	    $$($(1)_AOBJS) -Wl,--start-group $$($(1)_LIBS) $$(APP_LIB_LINK) $$(FW_LIBC_LIBS) -Wl,--end-group $$(CPU32_RT)
	$$(CROSS_OBJCOPY) -O srec $$@ $$(@:.elf=.srec)
	$$(CROSS_SIZE) $$@

.SECONDARY: $$($(1)_KOBJS) $$($(1)_AOBJS) $$(patsubst %,$$($(1)_DIR)/obj/%.o,$$(foreach d,$$(APP_LIB_DIRS),$$(call app_lib_srcs,$$(d))))
endef

$(foreach a,$(APPS),$(eval $(call app_template,$(a))))

# The board an image is built for and runs on: the RoboCube (this file) or
# one of boards/NAME/ (its board.mk has the rules).
BOARDS := robocube $(sort $(notdir $(patsubst %/board.mk,%,$(wildcard boards/*/board.mk))))
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
# emu/eco.mk).
RUN_SECONDS ?=
ifneq ($(filter run,$(MAKECMDGOALS)),)
ifneq ($(RUN_SECONDS),)
$(call check_whole_number,make run,RUN_SECONDS,1,86400,make run [APP=NAME] [RUN_SECONDS=1..86400])
endif
endif

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
	@$(SETUP) qemu m68k $(if $($(APP)_RUNNER),base)
	@$(MAKE) --no-print-directory firmware $($(APP)_RUN_DEPS) APP=$(APP)
ifneq ($($(APP)_RUNNER),)
	@$($(APP)_RUNNER)
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
	echo "created apps/$$name/ (main.c from $(NEW_APP_TEMPLATE)): make run APP=$$name"

CHECKS += new-app
.PHONY: check-new-app
check-new-app:
	@$(SETUP) base m68k qemu
	@BSCHED_QEMU=$(QEMU_M68K) ci/pytest-suite new-app apps/pdl_hello/tests
