# Frama-C WP proofs of bsched/bsched.c (the file that ships, no copy).
#   make prove                 every goal, gated on the report (build/wp/)
#   make check-wp              the same as a check suite
#   make check-wp-negative     the mutant (-DBSCHED_MUTANT_NO_REVERSE) must fail
#   make wp-session            race every goal and record its prover (session.tsv)
#   make check-wp-trust        a forged cache, a deleted goal, a weakened contract
#                              each fail the proof suite (on copies of reverse_bits)
# Deterministic: fixed prover list, timeout, memory limit (why3.conf) and -wp-par.

WP_DIR      := $(BUILD)/wp
WP_SPEC     := $(addprefix bsched/spec/,bsched_logic.h bsched_lemmas.h bsched_order.h \
               bsched_fold.h bsched_rev.h bsched_balance.h bsched_slots.h bsched_step.h \
               bsched_word.h)
WP_SOURCES  := bsched/bsched.c bsched/bsched.h $(WP_SPEC)
# WP starts the provers side by side on each goal and keeps the first proof (measured
# 2026-11-24, 2669 goals: Qed 1549, CVC4 671, CVC5 260, Z3 with bounded instantiation
# 189; plain Z3 is left out). z3-qi and the cvc5 entry are set up by ci/setup.d/frama-c.sh.
WP_PROVERS  ?= cvc4,z3-qi,cvc5
# Every prover call is limited by steps (-wp-steps: cvc4/cvc5 --rlimit, Z3 rlimit),
# which do not depend on the machine's speed or load, so neither can turn a proven
# goal into a failure. Each limit is 2x the most steps a proof by that prover took
# (make wp-calibrate prints them; re-run it when the goals change): WP_STEPS for
# cvc4 and cvc5, WP_STEPS_Z3 for Z3, whose units are ~13x cheaper (prover-steps.sh).
# A goal cut by steps is reported as "Step limit" by all three (why3-config.sh). The
# wall-clock timeout is only a backstop against a prover that hangs: Why3 kills a
# step-limited call after 2 x WP_TIMEOUT + 1 s and reports Timeout from 0.9 x WP_TIMEOUT.
WP_STEPS    ?= 2500000
export WP_STEPS_Z3 ?= 13000000
WP_TIMEOUT  ?= 600
# Prover jobs per Frama-C process: prover start-up, not CPU, bounds a run.
WP_PAR      ?= 3
# The full run has more goals than this; fewer means something was not analysed.
WP_MIN_GOALS ?= 2600
WP_DEFINES  ?=
WP_FCT      ?=
WP_OUT      ?= $(WP_DIR)
WP_EXPECT_FAIL ?=
# Goals known not to be proven yet (bsched/proofs/README.md, "Not proven"): the gate
# lists them as KNOWN GAP instead of failing. Empty when the proof is complete.
WP_KNOWN_GAPS ?=
# Extra Frama-C options, e.g. -machdep x86_32 (make prove-machdeps, assure/assure.mk).
WP_MACHDEP_FLAGS ?=
# The directory name carries the configuration version (why3-config.sh).
export WHY3CONFIG := $(BSCHED_TOOLS)/why3-v5/why3.conf

# -wp-cache none: every result comes from a prover run now, whatever FRAMAC_WP_CACHE
# says in the environment (a cached result is a file anyone can write).
WP_FLAGS = -cpp-extra-args="-I$(ROOT)/bsched $(WP_DEFINES)" \
	-wp -wp-rte -wp-timeout $(WP_TIMEOUT) \
	$(if $(filter-out 0,$(WP_STEPS)),-wp-steps $(WP_STEPS)) \
	-wp-verbose 1 -wp-cache none $(WP_MACHDEP_FLAGS)

# What the proof proves is recorded (wp_goals.py): goals.tsv, every goal with its
# prover, and contracts.tsv, the digest of each source's ACSL annotations. Only a full
# run of the shipping configuration that proves every goal writes them (not a WP_FCT,
# mutant, machine-model or calibration run, and not check-wp, which is a check and
# leaves the source tree alone); make check holds its proof against them.
WP_RECORD_DIR := bsched/proofs/wp
WP_RECORD ?= $(if $(WP_FCT)$(WP_DEFINES)$(WP_MACHDEP_FLAGS)$(filter-out $(WP_DIR),$(WP_OUT)),0,1)

# The full run is split over Frama-C processes: WP generates its goals in one thread,
# so one process would leave a core idle much of the time. Part A takes the library's
# code behind bsched_init and bsched_step; part B everything else (bsched_due and the
# lemma functions), so a new function always lands in B and none is left out; run ref
# Fig. 7's reference engine.
WP_PART_A   := bsched_init,place_processes,plan_classes,perfect_load,reverse_bits,period_of,plausible_state,bsched_step,collect_due,collect_class,next_reversed
WP_RUNS      = $(if $(WP_FCT),all,a b ref)
WP_SEL_all   = -wp-fct $(WP_FCT) -wp-par $(WP_PAR)
WP_SEL_a     = -wp-fct $(WP_PART_A) -wp-par $(WP_PAR)
WP_SEL_b     = -wp-skip-fct $(WP_PART_A),bsched_run_cycle -wp-par $(WP_PAR)

# The proof session. WP races the provers on each goal, so a goal costs up to three
# times the CPU of its fastest proof, and on 2 cores the race is what a full run
# waits for (measured 2026-11-27: 1249 s of wall time for 879 s of the winners'
# prover time; replaying the session, 719 s on the idle machine, about half the
# CPU). session.tsv names the prover that proved each goal in a racing run;
# make prove installs it as WP's proof scripts (wp_session.py) and replays them
# (-wp-prover script,...): each goal runs its prover alone, with make prove's own
# limits, and a goal whose prover fails, or that is not in the session, is raced as
# before, so a stale session costs time, never the verdict. make wp-session races
# every goal (WP_SESSION=0) and writes session.tsv anew: run it when the goals change.
WP_SESSION      ?= 1
WP_SESSION_TSV  := bsched/proofs/wp/session.tsv
wp_session_on    = $(filter 1,$(WP_SESSION))
wp_empty :=
wp_space := $(wp_empty) $(wp_empty)
wp_comma := ,
# Run `ref`: Fig. 7's reference engine (bsched/proofs/ref/bsched_fig7.c, spec in
# spec/bsched_fig7.h). Only its own functions: the shared lemma functions it
# calls are the same text that runs a and b prove. WP_FILE: the file of a
# WP_FCT run (make prove WP_FCT=bsched_fig7_step WP_FILE=bsched/proofs/ref/bsched_fig7.c).
WP_REF_FCT  := bsched_fig7_start,bsched_fig7_step,fig7_run_due,fig7_count_down,fig7_plan_plausible,fig7_period,lemma_fig7_zero_slots,lemma_fig7_next_phase
# Its slowest goals (the loop and frame steps of bsched_fig7_step) take a few seconds
# of CPU, which on the shared 2-core machine at load 12-15 exceeded 30 s of wall time:
# a wider wall-clock timeout keeps the verdict independent of the load.
WP_REF_TIMEOUT ?= 120
WP_SEL_ref   = -wp-fct $(WP_REF_FCT) -wp-par $(WP_PAR) -wp-timeout $(WP_REF_TIMEOUT)
WP_FILE     ?= bsched/bsched.c
WP_FILE_all  = $(WP_FILE)
WP_FILE_a    = bsched/bsched.c
WP_FILE_b    = bsched/bsched.c
WP_FILE_ref  = bsched/proofs/ref/bsched_fig7.c
WP_SPEC     += bsched/spec/bsched_fig7.h
WP_SOURCES  += bsched/proofs/ref/bsched_fig7.c bsched/proofs/ref/bsched_fig7.h bsched/spec/bsched_fig7.h

# make check runs the full proof (suite wp: every goal Qed leaves goes to a prover,
# the session's first, then the race), held against the record of goals and contracts
# (wp_goals.py check), and the negative check.
CHECKS += wp wp-negative
PROOF_CHECKS += wp wp-negative
.PHONY: prove check-wp check-wp-negative wp-calibrate wp-session nightly

# $(call wp_run,RUN,PROVERS): one Frama-C process, its log and JSON report in WP_OUT.
wp_run = nice frama-c $(WP_FLAGS) -wp-prover $(if $(wp_session_on),script$(wp_comma))$(2) \
	$(if $(wp_session_on),-wp-session $(WP_OUT)/session) $(WP_SEL_$(1)) -wp-report-json $(WP_OUT)/wp-$(1).json \
	$(WP_FILE_$(1)) > $(WP_OUT)/wp-$(1).log 2>&1

# The shell steps of every run of WP_RUNS side by side (one Frama-C process each),
# for make prove: the logs joined in WP_OUT/wp.log, the JSON
# reports merged in WP_OUT/wp.json; leaves rc (0, or the status of what failed)
# and secs (the wall time) to the gate that follows.
wp_run_all = start=$$(date +%s); rc=0; pids=; \
	$(foreach r,$(WP_RUNS),$(call wp_run,$(r),$(WP_PROVERS)) & pids="$$pids $$!";) \
	for pid in $$pids; do wait $$pid || rc=$$?; done; \
	cat $(foreach r,$(WP_RUNS),$(WP_OUT)/wp-$(r).log) > $(WP_OUT)/wp.log; \
	python3 bsched/proofs/wp/wp_report.py --merge $(WP_OUT)/wp.json \
	    $(foreach r,$(WP_RUNS),$(WP_OUT)/wp-$(r).json) || rc=1; \
	secs=$$(( $$(date +%s) - start ))

# Runs WP, then gates on the report: any goal not proven, fewer than
# WP_MIN_GOALS goals, or an axiom in the spec fails the target.
prove:
	@$(SETUP) frama-c
	@python3 bsched/proofs/tools_check.py --only frama-c,why3,z3,cvc4,cvc5
	@mkdir -p $(WP_OUT)
	@$(if $(wp_session_on),python3 bsched/proofs/wp/wp_session.py install $(WP_SESSION_TSV) $(WP_OUT)/session \
	    --steps $(WP_STEPS) --steps-z3 $(WP_STEPS_Z3) --timeout $(WP_TIMEOUT),rm -rf $(WP_OUT)/session)
	@$(wp_run_all); \
	grep -E "^\[(kernel|wp)\].*(Warning|Error|error)" $(WP_OUT)/wp.log | grep -v "pedantic-assigns" | head -20; \
	if [ $$rc -ne 0 ]; then tail -20 $(WP_OUT)/wp.log; echo "prove: frama-c exited $$rc"; exit 1; fi; \
	python3 bsched/proofs/wp/wp_report.py $(WP_OUT)/wp.log $(WP_OUT)/wp.json $(WP_OUT)/report.json \
	    --min-goals $(WP_MIN_GOALS) --spec $(WP_SPEC) --seconds $$secs \
	    $(if $(WP_EXPECT_FAIL),--expect-fail $(WP_EXPECT_FAIL)) \
	    $(if $(WP_KNOWN_GAPS),--known-gap $(WP_KNOWN_GAPS)) || exit 1; \
	$(if $(filter 1,$(WP_RECORD)),python3 bsched/proofs/wp/wp_goals.py record $(WP_OUT)/report.json $(WP_RECORD_DIR) \
	    --root $(ROOT) --spec $(WP_SOURCES))

# Suite wp-trust: what make check's proof cannot be talked into (wp_trust_check.sh, on
# copies of the proof sources whose reverse_bits is changed): a false postcondition
# with forged cache entries and session lines fails make prove, though the forgery
# passes an offline replay of that cache; a deleted and a weakened postcondition fail
# the record's check.
CHECKS += wp-trust
PROOF_CHECKS += wp-trust
.PHONY: check-wp-trust
check-wp-trust:
	@$(SETUP) frama-c
	@WP_PROVERS=$(WP_PROVERS) WP_STEPS=$(WP_STEPS) WP_STEPS_Z3=$(WP_STEPS_Z3) \
	    bsched/proofs/wp/wp_trust_check.sh $(BUILD)/wp-trust $(RESULTS)/wp-trust.txt $(WP_SOURCES)

# Suite wp-session: replaying the session proves a goal with its recorded prover alone
# (session_check.sh, ~15 s).
CHECKS += wp-session
PROOF_CHECKS += wp-session
.PHONY: check-wp-session
check-wp-session:
	@$(SETUP) frama-c
	@WP_PROVERS=$(WP_PROVERS) WP_STEPS=$(WP_STEPS) WP_TIMEOUT=$(WP_TIMEOUT) \
	    bsched/proofs/wp/session_check.sh $(WP_SESSION_TSV) $(WP_DIR)/session-check $(RESULTS)/wp-session.txt

# make wp-session: the full run racing every goal (its log and report in
# build/wp-race/), then session.tsv from its report. Fails, writing nothing, unless
# every goal is proven.
wp-session:
	@$(MAKE) --no-print-directory prove WP_SESSION=0 WP_OUT=$(BUILD)/wp-race && \
	python3 bsched/proofs/wp/wp_session.py write $(BUILD)/wp-race/report.json $(WP_SESSION_TSV)

# The full run with step limits far above any proof's (z3's rlimit is 32-bit), then
# the steps each prover used and the limits they call for (wp_steps.py); fails when
# WP_STEPS or WP_STEPS_Z3 no longer keeps its 2x margin. One run of make prove's length.
WP_CALIBRATE_STEPS ?= 2000000000
wp-calibrate:
	@$(MAKE) --no-print-directory prove WP_STEPS=$(WP_CALIBRATE_STEPS) WP_STEPS_Z3=$(WP_CALIBRATE_STEPS) \
	    WP_SESSION=0 WP_OUT=$(BUILD)/wp-calibrate; rc=$$?; \
	python3 bsched/proofs/wp/wp_steps.py $(BUILD)/wp-calibrate/wp.log --margin 2 \
	    --limit $(WP_STEPS) --limit-z3 $(WP_STEPS_Z3) --timeout $(WP_TIMEOUT) || rc=1; exit $$rc

# Suite wp: make prove (it writes no record), then its goals and the sources'
# annotations against the record. Two results: the proof, the record.
check-wp:
	@$(SETUP) frama-c
	@mkdir -p $(WP_DIR)
	@$(MAKE) --no-print-directory prove WP_RECORD=0 > $(WP_DIR)/check.log 2>&1; rc=$$?; \
	cat $(WP_DIR)/check.log; pass=0; fail=0; \
	if [ $$rc -eq 0 ]; then pass=1; else fail=1; fi; \
	if python3 bsched/proofs/wp/wp_goals.py check $(WP_DIR)/report.json $(WP_RECORD_DIR) \
	    --root $(ROOT) --spec $(WP_SOURCES); then pass=$$((pass+1)); else fail=$$((fail+1)); fi; \
	$(call record,wp,$$pass,$$fail); [ $$fail -eq 0 ]

# Negative check: with -DBSCHED_MUTANT_NO_REVERSE, reverse_bits is the identity and
# the spec's fig6_map with it (bsched_logic.h), so bsched_init still meets its (mutant)
# closed form; the proof of the balance theorem must then fail where it ties the waits
# of the schedule to the balanced residues (bsched_slots.h: member j of class k is due
# iff rev_k(t mod 2^k) is its position). WP_FCT keeps this run to those functions.
WP_MUTANT_FCT := $(subst $(wp_space),,lemma_slots_disjoint,lemma_slots_mod_sum, \
    lemma_slots_due,lemma_slots_init_wait,lemma_slots_slot,lemma_slots_all,lemma_slots_step, \
    lemma_slots_class,lemma_slots_by_class,reverse_bits)
WP_MUTANT_GOALS := typed_lemma_slots_init_wait_ensures_init_wait_def
# The goal that must fail has no proof, so cvc4 would spend its whole step allowance or
# the 600 s backstop on it (measured: over 6 min beside other jobs); a short backstop
# suffices: the check asks only that make prove fail and that this goal be unproven.
WP_NEGATIVE_TIMEOUT ?= 60
check-wp-negative:
	@$(SETUP) frama-c
	@mkdir -p $(WP_DIR)
	@$(MAKE) --no-print-directory prove WP_DEFINES=-DBSCHED_MUTANT_NO_REVERSE WP_SESSION=0 \
	    WP_FCT=$(WP_MUTANT_FCT) WP_MIN_GOALS=150 WP_OUT=$(WP_DIR)/mutant WP_TIMEOUT=$(WP_NEGATIVE_TIMEOUT) \
	    > $(WP_DIR)/mutant.log 2>&1; rc=$$?; \
	cat $(WP_DIR)/mutant.log; \
	failed=$$(python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print(" ".join(g["goal"] for g in r["goals"] if g["status"]!="Valid"))' $(WP_DIR)/mutant/report.json 2>/dev/null); \
	pass=0; fail=0; \
	if [ $$rc -ne 0 ]; then pass=$$((pass+1)); echo "ok: make prove fails on the mutant"; \
	else fail=$$((fail+1)); echo "FAILED: make prove passes on the mutant"; fi; \
	for g in $(WP_MUTANT_GOALS); do \
	    if echo " $$failed " | grep -q " $$g "; then pass=$$((pass+1)); echo "ok: $$g not proven on the mutant"; \
	    else fail=$$((fail+1)); echo "FAILED: $$g proven on the mutant"; fi; \
	done; \
	$(call record,wp-negative,$$pass,$$fail); [ $$fail -eq 0 ]

# The installed proof tools are the ones bsched/proofs/tools.txt lists (the verified
# configuration); and the check itself fails on a manifest that differs.
CHECKS += proof-tools
.PHONY: check-proof-tools
check-proof-tools:
	@$(SETUP) frama-c cbmc
	@bad=$$(mktemp); sed 's/^z3 *4\.8\.12 /z3         4.8.99 /' bsched/proofs/tools.txt > $$bad; \
	if python3 bsched/proofs/tools_check.py --strict --only z3 --manifest $$bad > /dev/null; then \
	    echo "FAILED: a manifest listing z3 4.8.99 was not refused"; rm -f $$bad; $(call record,proof-tools,0,1); exit 1; fi; \
	rm -f $$bad; echo "ok: a manifest that differs is refused"
	@CBMC=$(CBMC_BIN) KISSAT=$(dir $(CBMC_BIN))kissat python3 bsched/proofs/tools_check.py --strict --suite proof-tools

# make proof-report: one report of what the proof jobs left in build/ (WP goals by
# function and property with prover, steps and time; CBMC runs with bounds, property
# count, solver and time; the negative checks; the mutants summary; the tool
# versions) as build/proof-report/index.html and proof-report.json
# (bsched/proofs/proof_report.py). Re-runs nothing: run make prove and make cbmc
# first; a run without a result is a row saying so.
PROOF_REPORT_DIR := $(BUILD)/proof-report
.PHONY: proof-report check-proof-report
proof-report:
	@CBMC=$(CBMC_BIN) KISSAT=$(dir $(CBMC_BIN))kissat python3 bsched/proofs/proof_report.py \
	    --build $(BUILD) --out $(PROOF_REPORT_DIR) --cbmc-runs $(CBMC_RUNS) --cbmc-mutants $(CBMC_MUTANT_RUNS)

# Suite proof-report (in make check, ~40 s: 37 s of CPU): the report against Frama-C's and CBMC's
# own output, on small runs of both made by the test.
CHECKS += proof-report
PROOF_CHECKS += proof-report
check-proof-report:
	@$(SETUP) base frama-c cbmc
	@CBMC=$(CBMC_BIN) KISSAT=$(dir $(CBMC_BIN))kissat ci/pytest-suite proof-report bsched/proofs/tests/test_proof_report.py

# make nightly: the long proof jobs that make check leaves out, each as a suite with
# its record in build/results/ and the summary line of ci/run-checks, then the proof
# report: CBMC at the goal bounds (suite cbmc-deep).
NIGHTLY_CHECKS += cbmc-deep
nightly:
	@$(SETUP) base frama-c cbmc
	@ci/run-checks --proof-lane "$(NIGHTLY_CHECKS)" $(NIGHTLY_CHECKS); rc=$$?; \
	$(MAKE) --no-print-directory proof-report; exit $$rc
