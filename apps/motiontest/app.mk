# Test-only image of the motion drivers (TPU, motors, odometry): a line
# protocol on the console that drivers/tests/target_motion/ drives over stdin while
# it checks the board model over QMP. Not a user shell (that is apps/shell).
# Its main starts the board itself (board_start ... k_start).
# The RoboCube's TPU and motors, and its DUART's registers (boards/robocube/mc68681.h).
motiontest_NEEDS  := console tick tpu motors
motiontest_BOARDS := robocube
motiontest_BOOT := self

# Its tests (suite motion-target): drivers/tests/target_motion/ boots it on the
# emulated board and checks the TPU, motors and odometry over QMP.
CHECKS += motion-target
EMU_CHECKS += motion-target
.PHONY: check-motion-target
check-motion-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=motiontest
	@BSCHED_QEMU=$(QEMU_M68K) MOTION_ELF=$(call app_elf,motiontest) FW_ICOUNT=$(FW_ICOUNT) \
	    ci/pytest-suite motion-target drivers/tests/target_motion
