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

define posix_board_suite
CHECKS += $(1)-posix
EMU_CHECKS += $(1)-posix
.PHONY: check-$(1)-posix
check-$(1)-posix:
	@$$(SETUP) base $(BOARD_$(1)_SETUP)
	@$$(MAKE) --no-print-directory $$(call image_elf,$(1),posixcheck) $$(call image_elf,$(1),posixmeasure)
	@K_BOARD=$(1) BSCHED_QEMU=$$$$(command -v $(BOARD_$(1)_QEMU)) FW_DIR=$(BOARD_$(1)_BUILD) \
	    ci/pytest-suite $(1)-posix apps/posixcheck/tests apps/posixmeasure/tests
endef
$(foreach b,$(filter-out robocube,$(IMAGE_BOARDS)),$(if $(filter posix,$(BOARD_$(b)_CAPS)),$(eval $(call posix_board_suite,$(b)))))
