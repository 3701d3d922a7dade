# emu I/O side (TPU, PCF8584 I2C + I/O board, motors, fast binary outputs):
# qtest/QMP device tests against the robocube machine (see emu/IO.md).
CHECKS += emu-io
EMU_CHECKS += emu-io

.PHONY: check-emu-io
check-emu-io:
	@$(SETUP) base qemu
	@BSCHED_QEMU=$(QEMU_M68K) \
	  $(ROOT)/ci/pytest-suite emu-io $(ROOT)/emu/tests/test_io_*.py
