# Board I/O drivers (drivers/i2c*.c, analog, bio, binin, fastout, sampler,
# board_io): host unit tests and the target suite on the emulated board.
#
#   make check-drivers-unit     cmocka: I2C state machine vs a scripted fake
#                               controller; analog numbering and range checks
#   make check-drivers-target   apps/iotest on qemu -M robocube, driven over
#                               the console and QMP (drivers/tests/target;
#                               declared with the image, apps/iotest/app.mk)
#   make drivers-size           text/data/bss of the I/O drivers (CPU32, -Os)

DRV_BUILD := $(BUILD)/drivers
DRV_HOST_TESTS := $(DRV_BUILD)/tests/test_i2c_fsm $(DRV_BUILD)/tests/test_analog
DRV_IO_SRCS := drivers/i2c.c drivers/i2c_fsm.c drivers/analog.c drivers/bio.c drivers/binin.c \
               drivers/fastout.c drivers/sampler.c drivers/board_io.c

# What the image pipeline builds for a board only when it has it (mk/image.mk):
# the I2C driver's interrupt handlers are the CPU32's vectors; the system
# calls are newlib's.
NEEDS_i2c  += drivers/i2c.c
NEEDS_libc += drivers/libc_syscalls.c

ALL += $(DRV_HOST_TESTS)
CHECKS += drivers-unit
HOST_UNIT_CHECKS += drivers-unit

.PHONY: check-drivers-unit drivers-size

$(DRV_BUILD)/tests/test_i2c_fsm: drivers/tests/host/test_i2c_fsm.c drivers/i2c_fsm.c drivers/i2c_fsm.h drivers/i2c.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(HOST_CFLAGS) -I$(ROOT) -DI2C_FSM_FAKE_HW -o $@ $< drivers/i2c_fsm.c -lcmocka

$(DRV_BUILD)/tests/test_analog: drivers/tests/host/test_analog.c drivers/analog.c drivers/analog.h drivers/i2c.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(HOST_CFLAGS) -I$(ROOT) -o $@ $< drivers/analog.c -lcmocka

check-drivers-unit: $(DRV_HOST_TESTS)
	@$(SETUP) base
	@RESULTS=$(RESULTS) ci/cmocka-suite drivers-unit $(DRV_HOST_TESTS)

# Size of the I/O drivers as linked into the iotest image (archive members).
drivers-size: $(BUILD)/firmware/iotest/iotest.elf
	@$(CROSS_SIZE) -t $(patsubst drivers/%.c,$(FW_BUILD)/iotest/obj/drivers/%.c.o,$(DRV_IO_SRCS))
