# Host unit tests of the shell stream's driver-side logic (cmocka):
#   test_sai        the uniform access layer (drivers/sai.c) against fake drivers
#   test_line_edit  console line assembly (drivers/line_edit.c)
#
#   make check-shell-unit
SHELL_UNIT_BUILD := $(BUILD)/drivers/tests
SHELL_UNIT_TESTS := $(SHELL_UNIT_BUILD)/test_sai $(SHELL_UNIT_BUILD)/test_line_edit
SHELL_UNIT_CFLAGS = $(HOST_CFLAGS) -I$(ROOT)

ALL += $(SHELL_UNIT_TESTS)
CHECKS += shell-unit
HOST_UNIT_CHECKS += shell-unit

$(SHELL_UNIT_BUILD)/test_sai: drivers/tests/test_sai.c drivers/sai.c drivers/sai.h drivers/drv_err.h
	@mkdir -p $(@D)
	$(HOST_CC) $(SHELL_UNIT_CFLAGS) -o $@ drivers/tests/test_sai.c drivers/sai.c -lcmocka

$(SHELL_UNIT_BUILD)/test_line_edit: drivers/tests/test_line_edit.c drivers/line_edit.c drivers/line_edit.h
	@mkdir -p $(@D)
	$(HOST_CC) $(SHELL_UNIT_CFLAGS) -o $@ drivers/tests/test_line_edit.c drivers/line_edit.c -lcmocka

.PHONY: check-shell-unit
check-shell-unit: $(SHELL_UNIT_TESTS)
	@$(SETUP) base
	@p=0; f=0; rc=0; \
	for t in $(SHELL_UNIT_TESTS); do \
	    out=$$($$t 2>&1); r=$$?; echo "$$out"; [ $$r -eq 0 ] || rc=1; \
	    tp=$$(echo "$$out" | sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' | tail -1); \
	    tf=$$(echo "$$out" | sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' | tail -1); \
	    if [ -z "$$tp$$tf" ]; then tf=1; fi; \
	    p=$$((p + $${tp:-0})); f=$$((f + $${tf:-0})); \
	done; \
	$(call record,shell-unit,$$p,$$f); [ $$rc -eq 0 ]
