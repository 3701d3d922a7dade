# Test image of the board I/O drivers: brings the board up (boot report),
# starts the sensor sampler and answers one-line commands on the console so
# the target tests (drivers/tests/target/) can drive the drivers while the host
# sets and reads the board model over QMP. Test-only: the shell image
# (apps/shell) is the one for people.
# The RoboCube's I/O board, and its DUART console's internals (boards/robocube/duart_console.h).
iotest_NEEDS  := console tick i2c analog bio
iotest_BOARDS := robocube
iotest_TICK_HZ := 1024
# Its main starts the board itself (board_start ... k_start).
iotest_BOOT := self

# Its tests (suite drivers-target): drivers/tests/target/ boots it on
# qemu -M robocube and drives the I/O drivers over the console and QMP.
CHECKS += drivers-target
EMU_CHECKS += drivers-target
.PHONY: check-drivers-target
check-drivers-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=iotest
	@BSCHED_QEMU=$(QEMU_M68K) IOTEST_ELF=$(call app_elf,iotest) FW_ICOUNT=$(FW_ICOUNT) \
	    ci/pytest-suite drivers-target drivers/tests/target
