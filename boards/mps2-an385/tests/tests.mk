# The MPS2 AN385's own suite, on images the image pipeline builds
# (mk/image.mk); its kernel suite (check-mps2-an385-kernel) is
# kernel/kernel.mk's, its POSIX suite (check-mps2-an385-posix)
# apps/posixcheck/app.mk's.
#
#   make check-mps2-an385-firmware   table1 (Table 2), the LED, newlib's printf, make's refusals
CHECKS += mps2-an385-firmware
EMU_CHECKS += mps2-an385-firmware
.PHONY: check-mps2-an385-firmware
check-mps2-an385-firmware:
	@$(SETUP) base $(BOARD_mps2-an385_SETUP)
	@$(MAKE) --no-print-directory $(foreach a,table1 hello,$(call image_elf,mps2-an385,$(a)))
	@K_BOARD=mps2-an385 MPS2_BUILD=$(BOARD_mps2-an385_BUILD) BSCHED_QEMU=$$(command -v $(BOARD_mps2-an385_QEMU)) \
	    ci/pytest-suite mps2-an385-firmware boards/mps2-an385/tests apps/table1/tests
