# The B-scheduler library, the bsched-plan CLI and their host tests.

BSCHED_CFLAGS := $(HOST_CFLAGS) -I$(ROOT)/bsched
# The CLI plans sets up to the library's largest capacity.
PLAN_CFLAGS   := $(BSCHED_CFLAGS) -DBSCHED_MAX_PROCS=65535 -DBSCHED_PLAN_SOURCE=\"$(ROOT)/bsched\"
CROSS_CC      ?= m68k-linux-gnu-gcc
CROSS_CFLAGS  := -std=c99 -mcpu=cpu32 -Os -ffreestanding -nostdlib -Wall -Wextra -Wpedantic -Wconversion -Werror

ALL += $(BUILD)/bin/bsched-plan $(BUILD)/tests/test_bsched
CHECKS += bsched-build bsched-unit bsched-plan
HOST_UNIT_CHECKS += bsched-unit

# The run+check certificates name the checker by the sha256 of the source it was built from.
$(BUILD)/bin/bsched-plan: tools/bsched-plan.c tools/bsched-check.c tools/bsched-check.h bsched/bsched.c bsched/bsched.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(PLAN_CFLAGS) -Itools \
	    -DBSCHED_CHECK_SHA256=\"$$(sha256sum tools/bsched-check.c | cut -c1-64)\" \
	    -o $@ tools/bsched-plan.c tools/bsched-check.c bsched/bsched.c

$(BUILD)/tests/test_bsched: bsched/tests/test_bsched.c bsched/tests/table2.h bsched/bsched.c bsched/bsched.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(BSCHED_CFLAGS) -DBSCHED_MAX_PROCS=4096 -o $@ bsched/tests/test_bsched.c bsched/bsched.c -lcmocka

# bsched.c (and Fig. 7's reference engine) must compile warning-free for the host and for the CPU32 target.
.PHONY: check-bsched-build check-bsched-unit check-bsched-plan
check-bsched-build:
	@$(SETUP) base m68k
	@pass=0; fail=0; \
	for cfg in "$(HOST_CC) $(HOST_CFLAGS)" "$(HOST_CC) $(HOST_CFLAGS) -DBSCHED_MAX_PROCS=65535" \
	           "$(CROSS_CC) $(CROSS_CFLAGS)" "$(CROSS_CC) $(CROSS_CFLAGS) -DBSCHED_MAX_PROCS=65535"; do \
	    for src in bsched/bsched.c bsched/proofs/ref/bsched_fig7.c; do \
	        if $$cfg -Ibsched -c -o /dev/null $$src; then pass=$$((pass+1)); echo "ok: $$cfg $$src"; \
	        else fail=$$((fail+1)); echo "FAILED: $$cfg $$src"; fi; \
	    done; \
	done; \
	$(call record,bsched-build,$$pass,$$fail)

check-bsched-unit: $(BUILD)/tests/test_bsched
	@$(SETUP) base
	@RESULTS=$(RESULTS) ci/cmocka-suite bsched-unit $(BUILD)/tests/test_bsched

# Its --certify tests run CBMC (ci/setup cbmc) on small sets, and the run+check
# method (the C compiler, as for the build) up to 65535 processes.
check-bsched-plan: $(BUILD)/bin/bsched-plan
	@$(SETUP) base cbmc
	@BSCHED_PLAN=$(BUILD)/bin/bsched-plan ci/pytest-suite bsched-plan tools/tests

