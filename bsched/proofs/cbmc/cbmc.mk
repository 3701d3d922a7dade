# CBMC bounded model checking of bsched.c (issue 4). One folder per harness in
# bsched/proofs/cbmc/<harness>/ with its own Makefile (make -C that folder works
# on its own); this fragment runs them with the bounds below.
#
#   make cbmc            every harness at the default bounds + the negative check
#   make cbmc-deep       the harnesses at the deep bounds (long; not part of make check)
#   make check-cbmc      suite `cbmc`: the harnesses at the default bounds
#   make check-cbmc-negative  suite `cbmc-negative`: the unbalanced mutant
#                        (-DBSCHED_MUTANT_NO_REVERSE) must be caught, with a trace
# CBMC's output for each run: build/cbmc/<harness>[-mutant]/cbmc.log (deep runs:
# build/cbmc-deep/). CBMC_JOBS harnesses run at once (default 2).

CBMC_PROOFS    := $(ROOT)/bsched/proofs/cbmc
CBMC_HARNESSES := init step major_cycle errors
CBMC_MUTANTS   := init major_cycle
CBMC_JOBS      ?= 2

# Default bounds (N = most processes, P = largest priority value). Measured
# times are in /tmp/readme-sections/cbmc.md and the README.
CBMC_BOUNDS_init        := N=12 P=6
CBMC_BOUNDS_step        := N=16 P=8
CBMC_BOUNDS_major_cycle := N=8 P=4
CBMC_BOUNDS_errors      := N=8
# The negative check needs only a small set to show the imbalance.
CBMC_MUTANT_BOUNDS_init        := N=4 P=3
CBMC_MUTANT_BOUNDS_major_cycle := N=4 P=3
# make cbmc-deep
CBMC_DEEP_BOUNDS_init        := N=16 P=8
CBMC_DEEP_BOUNDS_step        := N=16 P=8
CBMC_DEEP_BOUNDS_major_cycle := N=12 P=5
CBMC_DEEP_BOUNDS_errors      := N=16

CHECKS += cbmc cbmc-negative

cbmc_sub = $(MAKE) --no-print-directory -s -C $(CBMC_PROOFS)/$(1) ROOT=$(ROOT) BUILD=$(BUILD)

.PHONY: cbmc cbmc-deep check-cbmc check-cbmc-negative check-cbmc-deep cbmc-runs
.PHONY: $(addprefix cbmc-run-,$(CBMC_HARNESSES)) $(addprefix cbmc-mutant-,$(CBMC_MUTANTS)) \
        $(addprefix cbmc-deep-,$(CBMC_HARNESSES))

$(addprefix cbmc-run-,$(CBMC_HARNESSES)): cbmc-run-%:
	@$(call cbmc_sub,$*) $(CBMC_BOUNDS_$*)
$(addprefix cbmc-mutant-,$(CBMC_MUTANTS)): cbmc-mutant-%:
	@$(call cbmc_sub,$*) $(CBMC_MUTANT_BOUNDS_$*) MUTANT=1
$(addprefix cbmc-deep-,$(CBMC_HARNESSES)): cbmc-deep-%:
	@$(call cbmc_sub,$*) $(CBMC_DEEP_BOUNDS_$*) OUT=$(BUILD)/cbmc-deep/$*

# $(call cbmc_record,SUITE,RESULT-DIRS): counts PASS/other in each dir's result.txt
# (a missing result counts as failed) and records the suite; fails if any failed.
cbmc_record = pass=0; fail=0; \
	for d in $(2); do \
	    if grep -qs '^PASS' $$d/result.txt; then pass=$$((pass+1)); \
	    else fail=$$((fail+1)); echo "$(1): $$(basename $$d): $$(cat $$d/result.txt 2>/dev/null || echo 'no result')"; fi; \
	done; \
	$(call record,$(1),$$pass,$$fail); echo "$(1): $$pass passed, $$fail failed"; [ $$fail -eq 0 ]

CBMC_RESULT_DIRS        := $(addprefix $(BUILD)/cbmc/,$(CBMC_HARNESSES))
CBMC_MUTANT_RESULT_DIRS := $(addprefix $(BUILD)/cbmc/,$(addsuffix -mutant,$(CBMC_MUTANTS)))

check-cbmc:
	@$(SETUP) cbmc
	@rm -f $(addsuffix /result.txt,$(CBMC_RESULT_DIRS))
	@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-run-,$(CBMC_HARNESSES)) || true
	@$(call cbmc_record,cbmc,$(CBMC_RESULT_DIRS))

check-cbmc-negative:
	@$(SETUP) cbmc
	@rm -f $(addsuffix /result.txt,$(CBMC_MUTANT_RESULT_DIRS))
	@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-mutant-,$(CBMC_MUTANTS)) || true
	@$(call cbmc_record,cbmc-negative,$(CBMC_MUTANT_RESULT_DIRS))

# Both suites in one pool of CBMC_JOBS, then both records.
cbmc:
	@$(SETUP) cbmc
	@rm -f $(addsuffix /result.txt,$(CBMC_RESULT_DIRS) $(CBMC_MUTANT_RESULT_DIRS))
	@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-run-,$(CBMC_HARNESSES)) \
	    $(addprefix cbmc-mutant-,$(CBMC_MUTANTS)) || true
	@ok=0; { $(call cbmc_record,cbmc,$(CBMC_RESULT_DIRS)); } || ok=1; \
	{ $(call cbmc_record,cbmc-negative,$(CBMC_MUTANT_RESULT_DIRS)); } || ok=1; exit $$ok

cbmc-deep: check-cbmc-deep
check-cbmc-deep:
	@$(SETUP) cbmc
	@rm -f $(addsuffix /result.txt,$(addprefix $(BUILD)/cbmc-deep/,$(CBMC_HARNESSES)))
	@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-deep-,$(CBMC_HARNESSES)) || true
	@$(call cbmc_record,cbmc-deep,$(addprefix $(BUILD)/cbmc-deep/,$(CBMC_HARNESSES)))
