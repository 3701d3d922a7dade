# The STM32F405's own suite and test images, built by the image pipeline
# (mk/image.mk); its kernel suite (check-stm32f405-kernel) is kernel/kernel.mk's.
#
#   make check-stm32f405-firmware   table1 (Table 2), the shell, fault reports, PDL ports, make's refusals

STM32_TESTS := $(BOARD_stm32f405_BUILD)/tests
# Fault report images (fault_image.c; FAULT_KIND = position): the board's base,
# whose vector table names the kernel port's handlers, and the kernel.
STM32_FAULT_KINDS := unmapped undef divzero thread
STM32_FAULT_ELFS  := $(patsubst %,$(STM32_TESTS)/fault-%.elf,$(STM32_FAULT_KINDS))
stm32_fault_index  = $(strip $(foreach i,1 2 3 4,$(if $(filter $(1),$(word $(i),$(STM32_FAULT_KINDS))),$(i))))
$(foreach k,$(STM32_FAULT_KINDS),$(eval $(call image,stm32f405,fault-$(k),$(STM32_TESTS)/fault-$(k),\
    $(STM32_TESTS)/fault-$(k).elf,boards/stm32f405/tests/fault_image.c,-DFAULT_KIND=$(call stm32_fault_index,$(k)),\
    kernel,$(STM32_TESTS)/shared)))

# The PDL target test image (pdl_ports.c), started by drivers/board_main.c like
# any ordinary program, at the kernel's 1024 Hz.
STM32_PDL_TEST_ELF := $(STM32_TESTS)/pdl-ports.elf
$(eval $(call image,stm32f405,pdl_ports,$(STM32_TESTS)/pdl-ports,$(STM32_PDL_TEST_ELF),\
    boards/stm32f405/tests/pdl_ports.c $(APP_BOOT_SRC),-DK_TICK_HZ=1024,app))

# The firmware on this board: table1 (apps/table1/tests, as on the RoboCube)
# and the shell via make run, the fault reports, PDL (its ports, pdl_hello,
# pdl_bench), make's refusals (boards/stm32f405/tests).
CHECKS += stm32f405-firmware
EMU_CHECKS += stm32f405-firmware
.PHONY: check-stm32f405-firmware
check-stm32f405-firmware:
	@$(SETUP) base $(BOARD_stm32f405_SETUP)
	@$(MAKE) --no-print-directory $(foreach a,table1 pdl_hello pdl_bench shell,$(call image_elf,stm32f405,$(a))) \
	    $(STM32_FAULT_ELFS) $(STM32_PDL_TEST_ELF)
	@K_BOARD=stm32f405 STM32_BUILD=$(BOARD_stm32f405_BUILD) QEMU_ARM=$$(command -v $(BOARD_stm32f405_QEMU)) \
	    STM32_ICOUNT=$(BOARD_stm32f405_ICOUNT) ci/pytest-suite stm32f405-firmware boards/stm32f405/tests apps/table1/tests
