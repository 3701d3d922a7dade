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

APPS        := $(sort $(notdir $(patsubst %/app.mk,%,$(wildcard apps/*/app.mk))))
APP_DEFAULT := ecosystem
APP         ?= $(APP_DEFAULT)
# Libraries every image may link: the target sources directly in these folders.
APP_LIB_DIRS := drivers net pdl
# Already in the firmware base objects or the kernel's own source list.
APP_LIB_EXCLUDE := $(FW_BASE_SRCS) $(K_TARGET_SRCS)
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
$(1)_DIR     := $$(FW_BUILD)/$(1)
$(1)_FLAGS   := $$(FW_CFLAGS) -I$$(ROOT)/kernel/include -I$$(ROOT)/kernel \
                -DK_TICK_HZ=$$($(1)_TICK_HZ) $$(APP_LIB_CFLAGS) $$($(1)_CFLAGS)
$(1)_KOBJS   := $$(patsubst %,$$($(1)_DIR)/obj/%.o,$$(K_TARGET_SRCS))
$(1)_AOBJS   := $$(patsubst %,$$($(1)_DIR)/obj/%.o,$$($(1)_SRCS))
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

ifeq ($(filter $(APP),$(APPS)),)
$(if $(filter run firmware,$(MAKECMDGOALS)),$(error APP=$(APP): no such image (have: $(APPS))))
endif

FW_ELF := $(call app_elf,$(APP))

.PHONY: firmware firmware-all run
firmware: $(FW_ELF)
firmware-all: $(foreach a,$(APPS),$(call app_elf,$(a)))

RUN_SECONDS ?=
run:
	@$(SETUP) qemu m68k $(if $($(APP)_RUNNER),base)
	@$(MAKE) --no-print-directory firmware $($(APP)_RUN_DEPS) APP=$(APP)
ifneq ($($(APP)_RUNNER),)
	@$($(APP)_RUNNER)
else
	@echo "make run: booting $(FW_ELF) on $(QEMU_M68K) -M robocube (console = DUART B on stdio$(if $(RUN_SECONDS),; stops after $(RUN_SECONDS) s,; quit with Ctrl-A x))" >&2
	@$(if $(RUN_SECONDS),timeout --foreground $(RUN_SECONDS)) \
	    $(QEMU_M68K) -M robocube -icount $($(APP)_ICOUNT) -kernel $(FW_ELF) -nographic $($(APP)_RUN_ARGS); rc=$$?; \
	    [ $$rc -eq 0 ] || [ "$(RUN_SECONDS)" != "" -a $$rc -eq 124 ]
endif
