# CBMC bounded model checking of bsched.c. One folder per harness in
# bsched/proofs/cbmc/<harness>/ with its own Makefile (make -C that folder works
# on its own); this fragment runs them with the bounds below.
#
#   make cbmc            every harness at the default bounds + the negative check
#   make cbmc-deep       the full-simulation harnesses at larger bounds (long; not in make check)
#   make check-cbmc      suite `cbmc`: the harnesses at the default bounds
#   make check-cbmc-negative  suite `cbmc-negative`: the unbalanced mutant
#                        (-DBSCHED_MUTANT_NO_REVERSE) must be caught, with a trace
#   make cbmc-report     HTML reports (cbmc-viewer) of the runs in build/cbmc/
# CBMC's output for each run: build/cbmc/<run>[-mutant]/cbmc.log (deep runs:
# build/cbmc-deep/). CBMC_JOBS runs at once (default 2).

CBMC_PROOFS := $(ROOT)/bsched/proofs/cbmc
CBMC_JOBS   ?= 2

# The default bounds. balance and step (the inductive step and the balance
# theorem on the closed form) run at the goal bounds, CBMC_N processes and
# priority values 0..CBMC_P; init (that bsched_init yields the closed form, the
# base case) at CBMC_INIT_N, CBMC_INIT_P, as far as the time budget allows;
# make cbmc-deep runs init at the goal bounds too. CBMC_INIT_N was 12 until
# 2026-11-27: its runs for n = 11 and 12 took 272 s of CPU in a make check that
# ran over its 30 minutes (n = 1..10: 274 s).
CBMC_N      ?= 16
CBMC_P      ?= 8
CBMC_INIT_N ?= 10
CBMC_INIT_P ?= 6

# Runs: name -> harness folder and Make arguments (N = most processes, P = largest
# priority value). Together, for every multiset within the bounds (one ascending
# input order each):
#   init-sorted-<part>-n<k>  bsched_init on every set of exactly k processes, one
#                        part of its properties per run (state, perfect, offsets:
#                        see init/init_harness.c and init/Makefile; one SAT instance
#                        per n and part is far faster than one for all n and parts);
#   balance              every cycle t of the closed-form offsets is balanced;
#   step                 bsched_step keeps the periodicity invariant from t to t+1.
# The rest: major_cycle (full simulation, every input order) and init with every
# input order at small bounds, and errors. Longest runs first, so that with -j2
# the long ones overlap.
CBMC_INIT_PARTS := state perfect offsets
# $(call cbmc_init_runs,PREFIX,N): the run names PREFIX-<part>-n<k>, k = N..1
cbmc_init_runs = $(foreach n,$(shell seq $(2) -1 1),$(foreach part,$(CBMC_INIT_PARTS),$(1)-$(part)-n$(n)))
define cbmc_init_run
CBMC_HARNESS_$(1)-$(2)-n$(3) := init
CBMC_ARGS_$(1)-$(2)-n$(3)    := ORDERS=sorted PARTS=$(2) EXACT_N=$(3) N=$(4) P=$(5)
endef
# $(call cbmc_define_init_runs,PREFIX,N,P)
cbmc_define_init_runs = $(foreach n,$(shell seq $(2) -1 1),$(foreach part,$(CBMC_INIT_PARTS),\
    $(eval $(call cbmc_init_run,$(1),$(part),$(n),$(2),$(3)))))

CBMC_INIT_RUNS := $(call cbmc_init_runs,init-sorted,$(CBMC_INIT_N))
$(call cbmc_define_init_runs,init-sorted,$(CBMC_INIT_N),$(CBMC_INIT_P))
CBMC_RUNS := major_cycle step agree init balance $(CBMC_INIT_RUNS) errors
# agree: bsched_step and Fig. 7's reference engine (bsched/proofs/ref/) give the same
# results from any cycle t, and both states are again consistent for t + 1. In
# make check at CBMC_AGREE_N, CBMC_AGREE_P; make cbmc-agree runs it at the goal
# bounds CBMC_N, CBMC_P, one run per process count (long; not in make check).
CBMC_AGREE_N ?= 4
CBMC_AGREE_P ?= 3
CBMC_HARNESS_agree       := agree
CBMC_ARGS_agree          := N=$(CBMC_AGREE_N) P=$(CBMC_AGREE_P)
# step: the new bsched_step divides by 2^(maxpv - k) and reduces mod 2^k (shifts
# and masks for the compiler, dividers for the SAT back end), so its run is far
# below the goal bounds (bsched/proofs/README.md); WP proves it for every set.
CBMC_STEP_N ?= 4
CBMC_STEP_P ?= 3
CBMC_HARNESS_step        := step
CBMC_ARGS_step           := N=$(CBMC_STEP_N) P=$(CBMC_STEP_P)
CBMC_HARNESS_balance     := balance
CBMC_ARGS_balance        := N=$(CBMC_N) P=$(CBMC_P)
CBMC_HARNESS_major_cycle := major_cycle
CBMC_ARGS_major_cycle    := N=4 P=3
CBMC_HARNESS_init        := init
CBMC_ARGS_init           := ORDERS=any N=6 P=3
CBMC_HARNESS_errors      := errors
CBMC_ARGS_errors         := N=16
# The negative check: the unbalanced mutant must be caught by every harness that
# runs bsched_init (balance takes its offsets from bsched_init for this).
# major_cycle at P = 2: the mutant already differs there (rev_2 swaps offsets 1 and
# 2) and fails periodicity in 74 s of CPU, against 173 s at P = 3 (measured
# 2026-11-27; N = 3, P = 3 took longer than either).
# errors with valid calls as well (errors/Makefile): the NOT_REACHED stubs must fail.
CBMC_MUTANT_RUNS := major_cycle init balance errors
CBMC_MUTANT_ARGS_major_cycle := N=4 P=2
CBMC_MUTANT_ARGS_init        := ORDERS=any N=4 P=3
CBMC_MUTANT_ARGS_balance     := N=4 P=3 EXTRA_DEFINES=-DPROOF_STATE_FROM_INIT=1
CBMC_MUTANT_ARGS_errors      := N=4

# make cbmc-deep: bsched_init at the goal bounds (the base case of the chain, so
# that with balance and step every multiset within CBMC_N, CBMC_P is covered), the
# full-simulation cross-check and every input order at larger bounds.
CBMC_DEEP_INIT_RUNS := $(call cbmc_init_runs,init-sorted,$(CBMC_N))
$(call cbmc_define_init_runs,deep-init-sorted,$(CBMC_N),$(CBMC_P))
CBMC_DEEP_RUNS := $(CBMC_DEEP_INIT_RUNS) major_cycle init errors
CBMC_DEEP_ARGS_major_cycle := N=12 P=5
CBMC_DEEP_ARGS_init        := ORDERS=any N=8 P=4
CBMC_DEEP_ARGS_errors      := N=64
$(foreach r,$(CBMC_DEEP_INIT_RUNS),$(eval CBMC_DEEP_ARGS_$(r) := $(CBMC_ARGS_deep-$(r))))
$(foreach r,$(CBMC_DEEP_RUNS),$(eval CBMC_DEEP_HARNESS_$(r) := $(or $(CBMC_HARNESS_deep-$(r)),$(r))))

CHECKS += cbmc cbmc-negative
PROOF_CHECKS += cbmc cbmc-negative

# The cbmc binary the harnesses use (Makefile.common picks it the same way).
CBMC_BIN ?= $(or $(wildcard $(BSCHED_TOOLS)/cbmc/bin/cbmc),$(shell command -v cbmc),$(BSCHED_TOOLS)/cbmc/bin/cbmc)
cbmc_sub = $(MAKE) --no-print-directory -s -C $(CBMC_PROOFS)/$(1) ROOT=$(ROOT) BUILD=$(BUILD)

.PHONY: cbmc cbmc-deep check-cbmc check-cbmc-negative check-cbmc-deep cbmc-report
.PHONY: $(addprefix cbmc-run-,$(CBMC_RUNS)) $(addprefix cbmc-mutant-,$(CBMC_MUTANT_RUNS)) \
        $(addprefix cbmc-deep-,$(CBMC_DEEP_RUNS))

# Each run writes build/cbmc/<run>/ (OUT), whatever the harness folder.
$(addprefix cbmc-run-,$(CBMC_RUNS)): cbmc-run-%:
	+@$(call cbmc_sub,$(CBMC_HARNESS_$*)) $(CBMC_ARGS_$*) OUT_NAME=$*
$(addprefix cbmc-mutant-,$(CBMC_MUTANT_RUNS)): cbmc-mutant-%:
	+@$(call cbmc_sub,$*) $(CBMC_MUTANT_ARGS_$*) MUTANT=1 OUT_NAME=$*-mutant
$(addprefix cbmc-deep-,$(CBMC_DEEP_RUNS)): cbmc-deep-%:
	+@$(call cbmc_sub,$(CBMC_DEEP_HARNESS_$*)) $(CBMC_DEEP_ARGS_$*) OUT_NAME=$* OUT=$(BUILD)/cbmc-deep/$*

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
	@CBMC=$(CBMC_BIN) KISSAT=$(dir $(CBMC_BIN))kissat python3 bsched/proofs/tools_check.py --only cbmc,kissat
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
	@CBMC=$(CBMC_BIN) KISSAT=$(dir $(CBMC_BIN))kissat python3 bsched/proofs/tools_check.py --only cbmc,kissat
	@rm -f $(addsuffix /result.txt,$(CBMC_RESULT_DIRS) $(CBMC_MUTANT_RESULT_DIRS))
	+@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-run-,$(CBMC_RUNS)) \
	    $(addprefix cbmc-mutant-,$(CBMC_MUTANT_RUNS)) || true
	@ok=0; { $(call cbmc_record,cbmc,$(CBMC_RESULT_DIRS)); } || ok=1; \
	{ $(call cbmc_record,cbmc-negative,$(CBMC_MUTANT_RESULT_DIRS)); } || ok=1; exit $$ok

# HTML reports (cbmc-viewer) of the runs already in build/cbmc/ (and build/cbmc-deep/):
# build/cbmc/<run>/html/html/index.html. Re-runs nothing; not part of make check.
cbmc-report:
	@$(SETUP) base cbmc
	@$(CBMC_PROOFS)/report.sh $(BSCHED_TOOLS) $(ROOT) \
	    $(patsubst %/cbmc.log,%,$(wildcard $(BUILD)/cbmc/*/cbmc.log $(BUILD)/cbmc-deep/*/cbmc.log))

cbmc-deep: check-cbmc-deep
check-cbmc-deep:
	@$(SETUP) cbmc
	@rm -f $(addsuffix /result.txt,$(addprefix $(BUILD)/cbmc-deep/,$(CBMC_DEEP_RUNS)))
	+@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-deep-,$(CBMC_DEEP_RUNS)) || true
	@$(call cbmc_record,cbmc-deep,$(addprefix $(BUILD)/cbmc-deep/,$(CBMC_DEEP_RUNS)))

# make cbmc-agree: harness agree at the goal bounds (N <= CBMC_N, P <= CBMC_P), one
# SAT instance per process count n (agree-n<k>, exactly k processes), into
# build/cbmc-agree/; suite record cbmc-agree. Long: not part of make check.
CBMC_AGREE_RUNS := $(foreach n,$(shell seq $(CBMC_N) -1 1),agree-n$(n))
.PHONY: cbmc-agree $(addprefix cbmc-agree-,$(CBMC_AGREE_RUNS))
$(addprefix cbmc-agree-,$(CBMC_AGREE_RUNS)): cbmc-agree-agree-n%:
	+@$(call cbmc_sub,agree) N=$(CBMC_N) P=$(CBMC_P) EXACT_N=$* OUT_NAME=agree-n$* \
	    OUT=$(BUILD)/cbmc-agree/agree-n$*
cbmc-agree:
	@$(SETUP) cbmc
	@rm -f $(addsuffix /result.txt,$(addprefix $(BUILD)/cbmc-agree/,$(CBMC_AGREE_RUNS)))
	+@$(MAKE) --no-print-directory -k -j$(CBMC_JOBS) $(addprefix cbmc-agree-,$(CBMC_AGREE_RUNS)) || true
	@$(call cbmc_record,cbmc-agree,$(addprefix $(BUILD)/cbmc-agree/,$(CBMC_AGREE_RUNS)))
