# The paper's Table 1 set on the nanokernel's B-scheduler thread, printing Table 2.
# 128 Hz instead of the kernel's 1024 Hz: every minor cycle prints its line,
# which must fit in its tick at 38400 baud (see table1.c).
# It blinks the LED after the run (the firmware-boot suite checks it).
table1_NEEDS := console tick led
table1_TICK_HZ := 128
# Its main starts the board itself (board_start ... k_start).
table1_BOOT := self

# Its suite (firmware-boot): apps/table1/tests/ runs this image with make run
# on the emulated RoboCube and checks Table 2 row by row (the stm32f405's
# suite runs the same tests on that board); kernel/tests/target/ boots it for
# the LED after the run, boots the fault images (boards/robocube/board.mk's
# FW_FAULT_ELFS), checks every image's load address and compares kprintf with
# C's printf on the host.
CHECKS += firmware-boot
EMU_CHECKS += firmware-boot
.PHONY: firmware-tests check-firmware-boot
firmware-tests: $(call app_elf,table1) $(FW_FAULT_ELFS)
check-firmware-boot:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware-tests
	@BSCHED_QEMU=$(QEMU_M68K) FW_DIR=$(FW_BUILD) FW_ELF=$(call app_elf,table1) FW_ICOUNT=$(FW_ICOUNT) CROSS_PREFIX=m68k-linux-gnu- \
	    ci/pytest-suite firmware-boot kernel/tests/target apps/table1/tests
