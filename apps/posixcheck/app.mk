# The POSIX layer (posix/) on the board: apps/posixcheck runs each profile area
# and its error paths, judged by apps/posixcheck/tests/; apps/posixmeasure
# counts the instructions of the POSIX calls against the k_ calls they stand on.
posixcheck_NEEDS := console tick libc posix
CHECKS += posix
EMU_CHECKS += posix
.PHONY: check-posix
check-posix:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory $(call app_elf,posixcheck) $(call app_elf,posixmeasure)
	@BSCHED_QEMU=$(QEMU_M68K) FW_DIR=$(FW_BUILD) \
	    ci/pytest-suite posix apps/posixcheck/tests apps/posixmeasure/tests
