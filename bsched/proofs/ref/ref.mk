# Fig. 7's reference engine (bsched/proofs/ref/): its host unit tests. Its WP proof is
# run `ref` of bsched/proofs/wp/wp.mk, its agreement with bsched_step CBMC's
# `agree` harness.

ALL += $(BUILD)/tests/test_bsched_fig7
CHECKS += bsched-fig7
HOST_UNIT_CHECKS += bsched-fig7

$(BUILD)/tests/test_bsched_fig7: bsched/proofs/ref/tests/test_bsched_fig7.c bsched/tests/table2.h bsched/proofs/ref/bsched_fig7.c \
        bsched/proofs/ref/bsched_fig7.h bsched/bsched.c bsched/bsched.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(BSCHED_CFLAGS) -I$(ROOT)/bsched/proofs/ref -DBSCHED_MAX_PROCS=1024 -o $@ \
	    bsched/proofs/ref/tests/test_bsched_fig7.c bsched/proofs/ref/bsched_fig7.c bsched/bsched.c -lcmocka

.PHONY: check-bsched-fig7
check-bsched-fig7: $(BUILD)/tests/test_bsched_fig7
	@$(SETUP) base
	@RESULTS=$(RESULTS) ci/cmocka-suite bsched-fig7 $(BUILD)/tests/test_bsched_fig7
