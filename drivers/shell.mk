# Host unit tests of the shell stream's driver-side logic (cmocka):
#   test_sai        the uniform access layer (drivers/sai.c) against fake drivers
#   test_line_edit  console line assembly (drivers/line_edit.c)
#   test_cmd        the console command tables (drivers/cmd.c): the parser of the
#                   shell and the test images
#
#   make check-shell-unit
SHELL_UNIT_BUILD := $(BUILD)/drivers/tests
SHELL_UNIT_TESTS := $(SHELL_UNIT_BUILD)/test_sai $(SHELL_UNIT_BUILD)/test_line_edit $(SHELL_UNIT_BUILD)/test_cmd
SHELL_UNIT_CFLAGS = $(HOST_CFLAGS) -I$(ROOT)

ALL += $(SHELL_UNIT_TESTS)
CHECKS += shell-unit
HOST_UNIT_CHECKS += shell-unit

# On the RoboCube's port table (the board whose drivers sai.c calls).
$(SHELL_UNIT_BUILD)/test_sai: drivers/tests/test_sai.c drivers/sai.c drivers/sai.h boards/include/board_ports.h \
                              boards/robocube/ports.c drivers/drv_err.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(SHELL_UNIT_CFLAGS) -o $@ drivers/tests/test_sai.c drivers/sai.c \
	    boards/robocube/ports.c -lcmocka

$(SHELL_UNIT_BUILD)/test_line_edit: drivers/tests/test_line_edit.c drivers/line_edit.c drivers/line_edit.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(SHELL_UNIT_CFLAGS) -o $@ drivers/tests/test_line_edit.c drivers/line_edit.c -lcmocka

$(SHELL_UNIT_BUILD)/test_cmd: drivers/tests/test_cmd.c drivers/cmd.c drivers/cmd.h
	@mkdir -p $(@D)
	$(HOST_CC) $(SHELL_UNIT_CFLAGS) -o $@ drivers/tests/test_cmd.c drivers/cmd.c -lcmocka

.PHONY: check-shell-unit
check-shell-unit: $(SHELL_UNIT_TESTS)
	@$(SETUP) base
	@RESULTS=$(RESULTS) ci/cmocka-suite shell-unit $(SHELL_UNIT_TESTS)
