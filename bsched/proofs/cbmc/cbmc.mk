# CBMC bounded model checking of bsched.c (issue 4). One folder per harness in
# bsched/proofs/cbmc/<harness>/ with its own Makefile (make -C that folder works
# on its own); this fragment runs them with the bounds below.
#
#   make cbmc            every harness at the default bounds + the negative check
#   make cbmc-deep       the harnesses at the deep bounds (long; not part of make check)
#   make check-cbmc      suite `cbmc`: the harnesses at the default bounds
#   make check-cbmc-negative  suite `cbmc-negative`: the unbalanced mutant
#                        (-DBSCHED_MUTANT_NO_REVERSE) must be caught, with a trace
# CBMC's output for each run: build/cbmc/<run>[-mutant]/cbmc.log (deep runs:
# build/cbmc-deep/). CBMC_JOBS harnesses run at once (default 2).

CBMC_PROOFS := $(ROOT)/bsched/proofs/cbmc
CBMC_JOBS   ?= 2

# Runs: name -> harness folder and Make arguments (N = most processes, P = largest
# priority value). Longest first, so that with -j2 the two long ones overlap.
# Measured times: /tmp/readme-sections/cbmc.md (README). init-sorted and step share
# their bounds: together they cover every cycle of every multiset within them.
CBMC_RUNS := step init-sorted major_cycle init errors
CBMC_HARNESS_step        := step
CBMC_ARGS_step           := N=12 P=6
CBMC_HARNESS_init-sorted := init
CBMC_ARGS_init-sorted    := ORDERS=sorted N=12 P=6
CBMC_HARNESS_major_cycle := major_cycle
CBMC_ARGS_major_cycle    := N=5 P=3
CBMC_HARNESS_init        := init
CBMC_ARGS_init           := ORDERS=any N=6 P=3
CBMC_HARNESS_errors      := errors
CBMC_ARGS_errors         := N=8

# The negative check: the unbalanced mutant must be caught by every harness that
# runs bsched_init (step builds its state from bsched_init for this).
CBMC_MUTANT_RUNS := major_cycle init step
CBMC_MUTANT_ARGS_major_cycle := N=4 P=3
CBMC_MUTANT_ARGS_init        := ORDERS=any N=4 P=3
CBMC_MUTANT_ARGS_step        := N=4 P=3 EXTRA_DEFINES=-DPROOF_STATE_FROM_INIT=1

# make cbmc-deep: the goal bounds (N <= 16, P <= 8) where they are not yet affordable.
CBMC_DEEP_RUNS := step init-sorted major_cycle init errors
CBMC_DEEP_ARGS_step        := N=16 P=8
CBMC_DEEP_ARGS_init-sorted := ORDERS=sorted N=16 P=8
CBMC_DEEP_ARGS_major_cycle := N=12 P=5
CBMC_DEEP_ARGS_init        := ORDERS=any N=8 P=4
CBMC_DEEP_ARGS_errors      := N=16

CHECKS += cbmc cbmc-negative

cbmc_sub = $(MAKE) --no-print-directory -s -C $(CBMC_PROOFS)/$(1) ROOT=$(ROOT) BUILD=$(BUILD)

.PHONY: cbmc cbmc-deep check-cbmc check-cbmc-negative check-cbmc-deep
.PHONY: $(addprefix cbmc-run-,$(CBMC_RUNS)) $(addprefix cbmc-mutant-,$(CBMC_MUTANT_RUNS)) \
        $(addprefix cbmc-deep-,$(CBMC_DEEP_RUNS))

# Each run writes build/cbmc/<run>/ (OUT), whatever the harness folder.
$(addprefix cbmc-run-,$(CBMC_RUNS)): cbmc-run-%:
	+@$(call cbmc_sub,$(CBMC_HARNESS_$*)) $(CBMC_ARGS_$*) OUT_NAME=$*
$(addprefix cbmc-mutant-,$(CBMC_MUTANT_RUNS)): cbmc-mutant-%:
	+@$(call cbmc_sub,$*) $(CBMC_MUTANT_ARGS_$*) MUTANT=1 OUT_NAME=$*-mutant
$(addprefix cbmc-deep-,$(CBMC_DEEP_RUNS)): cbmc-deep-%:
	+@$(call cbmc_sub,$(CBMC_HARNESS_$*)) $(CBMC_DEEP_ARGS_$*) OUT_NAME=$* OUT=$(BUILD)/cbmc-deep/$*

# $(call cbmc_record,SUITE,RESULT-DIRS): counts PASS/other in each dir's result.txt
# (a missing result counts as failed) and records the suite; fails if any failed.
cbmc_record = pass=0; fail=0; \
	for d in $(2); do \
	    if grep -qs '^PASS' $$d/result.txt; then pass=$$((pass+1)); \
	    else fail=$$((fail+1)); echo "$(1): $$(basename $$d): $$(cat $$d/result.txt 2>/dev/null || echo 'no result')"; fi; \
	done; \
	$(call record,$(1),$$pass,$$fail); echo "$(1): $$pass passed, $$fail failed"; [ $$fail -eq 0 ]

CBMC_RESULT_DIRS        := $(addprefix $(BUILD)/cbmc/,$(CBMC_RUNS))
CBMC_MUTANT_RESULT_DIRS := $(addprefix $(BUILD)/cbmc/,$(addsuffix -mutant,$(CBMC_MUTANT_RUNS)))

check-cbmc:
	@$(SETUP) cbmc
	@rm -f $(addsuffix /result.txt,$(CBMC_RESULT_DIRS))
	+@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-run-,$(CBMC_RUNS)) || true
	@$(call cbmc_record,cbmc,$(CBMC_RESULT_DIRS))

check-cbmc-negative:
	@$(SETUP) cbmc
	@rm -f $(addsuffix /result.txt,$(CBMC_MUTANT_RESULT_DIRS))
	+@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-mutant-,$(CBMC_MUTANT_RUNS)) || true
	@$(call cbmc_record,cbmc-negative,$(CBMC_MUTANT_RESULT_DIRS))

# Both suites in one pool of CBMC_JOBS, then both records.
cbmc:
	@$(SETUP) cbmc
	@rm -f $(addsuffix /result.txt,$(CBMC_RESULT_DIRS) $(CBMC_MUTANT_RESULT_DIRS))
	+@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-run-,$(CBMC_RUNS)) \
	    $(addprefix cbmc-mutant-,$(CBMC_MUTANT_RUNS)) || true
	@ok=0; { $(call cbmc_record,cbmc,$(CBMC_RESULT_DIRS)); } || ok=1; \
	{ $(call cbmc_record,cbmc-negative,$(CBMC_MUTANT_RESULT_DIRS)); } || ok=1; exit $$ok

cbmc-deep: check-cbmc-deep
check-cbmc-deep:
	@$(SETUP) cbmc
	@rm -f $(addsuffix /result.txt,$(addprefix $(BUILD)/cbmc-deep/,$(CBMC_DEEP_RUNS)))
	+@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-deep-,$(CBMC_DEEP_RUNS)) || true
	@$(call cbmc_record,cbmc-deep,$(addprefix $(BUILD)/cbmc-deep/,$(CBMC_DEEP_RUNS)))
