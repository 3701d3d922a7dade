# The image pipeline: how any firmware image is built for any board.
#
# A board is one folder, boards/NAME/, whose board.mk declares the variables
# below and nothing else (boards/README.md); this file turns them into rules.
# Its CPU port, kernel/arch/CPU/port.mk, gives the compiler flags for that CPU
# (CPU_CPU_CFLAGS, _ASFLAGS, _LDFLAGS) and the port's sources (_SOURCES, linked
# once per board; _KERNEL_SOURCES, compiled with the kernel per image).
#
#   BOARD_NAME_CPU            the kernel's CPU port: kernel/arch/CPU/
#   BOARD_NAME_MCPU           the compiler's -mcpu
#   BOARD_NAME_CROSS          the toolchain's prefix (CROSSgcc, CROSSar, ...)
#   BOARD_NAME_CFLAGS         the board's compile flags beyond its port's (C library headers, -I)
#   BOARD_NAME_SOURCES        start-up, vectors, polled console: compiled once, linked into every image
#   BOARD_NAME_KERNEL_SOURCES the kernel's board hooks (kernel/include/k_board.h), per image
#   BOARD_NAME_LIB_SOURCES    the board interface (boards/include/), an archive per image
#   BOARD_NAME_PDL_PORTS      how PDL reaches the board's ports (pdl/ports/)
#   BOARD_NAME_LDSCRIPT       the linker script
#   BOARD_NAME_LIBS           the C library, linked in the group with the image's libraries
#   BOARD_NAME_RUNTIME        the compiler runtime, linked after them
#   BOARD_NAME_IMAGE_FORMAT   objcopy's output format beside the ELF (srec, binary)
#   BOARD_NAME_SETUP          the ci/setup components its toolchain and QEMU come from
#   BOARD_NAME_QEMU           the emulator, BOARD_NAME_QEMU_MACHINE its -M, _QEMU_ARGS its further arguments
#   BOARD_NAME_CONSOLE        the console's device, for make run's banner
#   BOARD_NAME_ICOUNT         QEMU's -icount (virtual time from the instruction count)
#   BOARD_NAME_CAPS           what the board has, from IMAGE_CAPS
#   BOARD_NAME_BUILD          where its images go
#
# An app (apps/NAME/app.mk) says what it needs (NAME_NEEDS, from IMAGE_CAPS)
# and may say which boards it is for (NAME_BOARDS); a library source that needs
# a capability is listed in NEEDS_CAP by its part's .mk (drivers/, net/,
# posix/), and is built only for the boards that have it.

# Every capability a board may have:
#   console tick led  a console, the kernel's tick, a status LED (every board so far)
#   ports    a port table PDL binds to (boards/include/board_ports.h)
#   libc     newlib and its system calls (drivers/libc_syscalls.c): printf, malloc
#   posix    the POSIX layer (posix/) on that C library
#   radio    the radio channel the network stack runs on (boards/include/board_radio.h, net/)
#   i2c tpu analog bio motors  the RoboCube's I/O board: I2C, TPU, analog and binary I/O, motors
#   world    the arena's co-simulation in lockstep (emu/world/)
IMAGE_CAPS := console tick led ports libc posix radio i2c tpu analog bio motors world

# Processes the firmware's struct bsched has room for (Table 1 has 9; PDL programs up to 32).
FW_MAX_PROCS := 32
# Every board's base links these beside its own and its port's sources.
IMAGE_COMMON_SOURCES := kernel/lib/kprintf.c kernel/lib/kstring.c bsched/bsched.c
# The feature macros make newlib's headers declare the calls of the POSIX
# profile the layer provides (clock_gettime, clock_nanosleep, sched_yield ...).
FW_POSIX_FEATURES := -D_POSIX_THREADS=1 -D_POSIX_TIMERS=1 -D_POSIX_MONOTONIC_CLOCK=200112L \
                -D_POSIX_CLOCK_SELECTION=200112L -D_POSIX_PRIORITY_SCHEDULING=1
# Extra flags for every image object (the stack check's -fstack-usage: assure/assure.mk).
FW_EXTRA_CFLAGS :=

IMAGE_BOARDS := $(sort $(notdir $(patsubst %/board.mk,%,$(wildcard boards/*/board.mk))))

board_cc      = $(BOARD_$(1)_CROSS)gcc
board_ar      = $(BOARD_$(1)_CROSS)ar
board_objcopy = $(BOARD_$(1)_CROSS)objcopy
board_size    = $(BOARD_$(1)_CROSS)size
# GCC's own headers for each board's compiler, asked once per make run.
$(foreach b,$(IMAGE_BOARDS),$(eval board_gcc_include_$(b) := $(shell $(call board_cc,$(b)) -print-file-name=include 2>/dev/null)))
# The C headers an image sees: GCC's own, the POSIX layer's (posix/include:
# its pthread types stand in for newlib's) and the board's C library's, in that
# order, never the build machine's (-nostdinc).
board_cflags  = -mcpu=$(BOARD_$(1)_MCPU) $(CPU_$(BOARD_$(1)_CPU)_CFLAGS) -I$(ROOT) -I$(ROOT)/kernel/include \
                -I$(ROOT)/kernel -I$(ROOT)/bsched -DBSCHED_MAX_PROCS=$(FW_MAX_PROCS) \
                -nostdinc -isystem $(board_gcc_include_$(1)) -isystem $(ROOT)/posix/include \
                $(BOARD_$(1)_CFLAGS) $(FW_POSIX_FEATURES) $(FW_EXTRA_CFLAGS)
board_asflags = -mcpu=$(BOARD_$(1)_MCPU) $(CPU_$(BOARD_$(1)_CPU)_ASFLAGS)
board_ldflags = -mcpu=$(BOARD_$(1)_MCPU) $(CPU_$(BOARD_$(1)_CPU)_LDFLAGS) -T $(BOARD_$(1)_LDSCRIPT)
board_base_srcs   = $(BOARD_$(1)_SOURCES) $(CPU_$(BOARD_$(1)_CPU)_SOURCES) $(IMAGE_COMMON_SOURCES)
board_base_objs   = $(patsubst %,$(BOARD_$(1)_BUILD)/obj/%.o,$(call board_base_srcs,$(1)))
board_kernel_srcs = $(K_CORE_SRCS) $(CPU_$(BOARD_$(1)_CPU)_KERNEL_SOURCES) $(BOARD_$(1)_KERNEL_SOURCES)
# The link's files that make must have first (flags such as -lgcc are not).
board_link_files  = $(filter /%,$(BOARD_$(1)_LIBS) $(BOARD_$(1)_RUNTIME))

# $(call board_lacks,BOARD,CAPS): those of CAPS the board does not have.
board_lacks = $(strip $(filter-out $(BOARD_$(1)_CAPS),$(2)))
# The libraries an app image may link, the target sources directly in these
# folders (host code and tests live in their subfolders), and the board's interface.
IMAGE_LIB_DIRS := board drivers net pdl posix
# Already in the base or the kernel; the main-thread start-up is linked by
# name (NAME_BOOT), never from the archive.
APP_BOOT_SRC := drivers/board_main.c
image_lib_all_srcs = $(if $(filter board,$(2)),$(BOARD_$(1)_LIB_SOURCES),\
                     $(if $(filter pdl,$(2)),$(wildcard pdl/*.c) $(BOARD_$(1)_PDL_PORTS),$(wildcard $(2)/*.c)))
# $(call image_lib_srcs,BOARD,DIR): DIR's sources for BOARD, less those that
# need a capability the board lacks (NEEDS_CAP).
image_lib_srcs = $(filter-out $(call board_base_srcs,$(1)) $(call board_kernel_srcs,$(1)) $(APP_BOOT_SRC) \
                     $(foreach c,$(call board_lacks,$(1),$(IMAGE_CAPS)),$(NEEDS_$(c))),\
                     $(call image_lib_all_srcs,$(1),$(2)))

# $(call image_objrules,BOARD,OBJDIR,CFLAGS): how OBJDIR's objects are made;
# the first call for an OBJDIR sets its flags (images that share one use it).
define image_objrules
ifndef image_rules_$(2)
image_rules_$(2) := 1
$(2)/%.c.o: %.c
	@mkdir -p $$(@D)
	$$(call quiet,CC,$$<)$$(call board_cc,$(1)) $$(call board_cflags,$(1)) $(3) -c -o $$@ $$<

$(2)/%.S.o: %.S
	@mkdir -p $$(@D)
	$$(call quiet,AS,$$<)$$(call board_cc,$(1)) $$(call board_asflags,$(1)) -c -o $$@ $$<
endif
endef

# Each board's base, compiled once.
$(foreach b,$(IMAGE_BOARDS),$(eval $(call image_objrules,$(b),$(BOARD_$(b)_BUILD)/obj,)))
$(foreach b,$(IMAGE_BOARDS),$(eval .SECONDARY: $(call board_base_objs,$(b))))

# $(call image_lib,BOARD,DIR,LIB,OBJDIR): DIR/libLIB.a from OBJDIR's objects.
define image_lib
$(2)/lib$(3).a: $$(patsubst %,$(4)/%.o,$$(call image_lib_srcs,$(1),$(3)))
	@mkdir -p $$(@D)
	$$(call quiet,AR,$$@)rm -f $$@ && $$(call board_ar,$(1)) rcs $$@ $$^
.SECONDARY: $$(patsubst %,$(4)/%.o,$$(call image_lib_srcs,$(1),$(3)))
endef

# $(call image,BOARD,NAME,DIR,ELF,SRCS,CFLAGS,KIND[,SHARED])
# ELF from SRCS (objects in DIR/obj, compiled with CFLAGS) and the board's base;
# KIND bare adds the board interface, kernel the kernel too (at the tick in
# CFLAGS), app the libraries of IMAGE_LIB_DIRS as well. Images that share the
# kernel and the board interface (a suite's test images) name a SHARED folder
# for their objects and archives, compiled without the image's CFLAGS.
image = $(call image_rules,$(strip $(1)),$(strip $(2)),$(strip $(3)),$(strip $(4)),$(strip $(5)),$(strip $(6)),$(strip $(7)),$(strip $(8)))
define image_rules
$$(eval $$(call image_objrules,$(1),$(3)/obj,-DFW_IMAGE_NAME='"$(2)"' $(6)))
$(if $(8),$$(eval $$(call image_objrules,$(1),$(8)/obj,)))
image_libs_$(4) := $$(foreach d,board $(if $(filter app,$(7)),$(filter-out board,$(IMAGE_LIB_DIRS))),\
                     $$(if $$(call image_lib_srcs,$(1),$$(d)),$(or $(8),$(3))/lib$$(d).a))
image_kobjs_$(4) := $(if $(filter kernel app,$(7)),$$(patsubst %,$(or $(8),$(3))/obj/%.o,$$(call board_kernel_srcs,$(1))))
image_aobjs_$(4) := $$(patsubst %,$(3)/obj/%.o,$(5))
$$(foreach d,$$(patsubst $(or $(8),$(3))/lib%.a,%,$$(image_libs_$(4))),\
    $$(if $$(image_lib_done_$(or $(8),$(3))_$$(d)),,$$(eval image_lib_done_$(or $(8),$(3))_$$(d) := 1)\
    $$(eval $$(call image_lib,$(1),$(or $(8),$(3)),$$(d),$(or $(8),$(3))/obj))))
# The network's libraries (Mbed TLS) come with the network.
image_link_$(4) := $$(if $$(filter %/libnet.a,$$(image_libs_$(4))),$$(APP_LIB_LINK))

$(4): $$(call board_base_objs,$(1)) $$(image_kobjs_$(4)) $$(image_aobjs_$(4)) $$(image_libs_$(4)) \
      $$(BOARD_$(1)_LDSCRIPT) $$(call board_link_files,$(1)) $$(image_link_$(4))
	@mkdir -p $$(@D)
	$$(call quiet,LD,$$@)$$(call board_cc,$(1)) $$(call board_ldflags,$(1)) -Wl,-Map=$$(@:.elf=.map) -o $$@ \
	    $$(call board_base_objs,$(1)) $$(image_kobjs_$(4)) $$(image_aobjs_$(4)) \
	    -Wl,--start-group $$(image_libs_$(4)) $$(image_link_$(4)) $$(BOARD_$(1)_LIBS) -Wl,--end-group $$(BOARD_$(1)_RUNTIME)
	$$(call quiet,OBJCOPY,$$@)$$(call board_objcopy,$(1)) -O $$(BOARD_$(1)_IMAGE_FORMAT) $$@ \
	    $$(@:.elf=.$$(if $$(filter binary,$$(BOARD_$(1)_IMAGE_FORMAT)),bin,$$(BOARD_$(1)_IMAGE_FORMAT)))
	$$(if $$(filter 1,$$(V)),$$(call board_size,$(1)) $$@,@true)

.SECONDARY: $$(image_kobjs_$(4)) $$(image_aobjs_$(4))
endef

# Header dependencies from -MMD, for every board; the empty recipe stops make
# from looking for implicit rules to remake them.
IMAGE_DEPS := $(shell find $(sort $(foreach b,$(IMAGE_BOARDS),$(BOARD_$(b)_BUILD))) -name '*.d' 2>/dev/null)
$(IMAGE_DEPS): ;
-include $(IMAGE_DEPS)

# The RoboCube's images and flags by the names the tools and suites use.
FW_BUILD := $(BOARD_robocube_BUILD)
FW_ICOUNT := $(BOARD_robocube_ICOUNT)
