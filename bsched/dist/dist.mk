# The certified core as a drop-in bundle. It stays in bsched/ because it is part
# of what an embedder takes: the bundle's Makefile, setup.sh and README are
# this folder's other files, shipped as they are, and the bundle is built from
# bsched/ alone (nothing outside it goes in or is read).
#   make dist        build/dist/bsched-VERSION.tar.gz: library, spec, its CMake, pkg-config,
#                    Zephyr and PlatformIO files, the WP and CBMC proof jobs, unit tests,
#                    SOURCES.sha256 (every file of its bsched/ with its SHA-256),
#                    a README for embedders and a standalone
#                    Makefile (bsched/dist/Makefile) whose make prove / make cbmc run
#                    in the unpacked folder without this repository
#   make distcheck   unpacks it in a temporary folder and runs its make test, make
#                    prove and make cbmc there (long: the full proofs; not in make check)
#   make check-dist  suite `dist`: the bundle unpacks and builds warning-free, its unit
#                    tests pass and its CBMC `errors` harness passes at capacity 2

DIST_VERSION := $(shell cat bsched/VERSION)
DIST_NAME    := bsched-$(DIST_VERSION)
DIST_TAR     := $(BUILD)/dist/$(DIST_NAME).tar.gz
# Repository paths, kept as they are inside the bundle (so the proof jobs' own
# Makefiles run unchanged there).
DIST_FILES = bsched/bsched.c bsched/bsched.h bsched/VERSION bsched/CHANGELOG.md $(wildcard bsched/spec/*.h) \
    bsched/CMakeLists.txt $(wildcard bsched/cmake/*.in) bsched/library.json $(wildcard bsched/zephyr/*) \
    bsched/proofs/ref/bsched_fig7.c bsched/proofs/ref/bsched_fig7.h bsched/proofs/ref/tests/test_bsched_fig7.c \
    bsched/tests/test_bsched.c bsched/tests/table2.h bsched/proofs/README.md bsched/CAVEATS.md \
    bsched/proofs/tools.txt bsched/proofs/tools_check.py bsched/proofs/proof_report.py \
    $(filter-out %.pyc,$(shell find bsched/proofs/wp bsched/proofs/cbmc -type f -not -path '*/__pycache__/*'))

CHECKS += dist
# check-dist runs the bundle's CBMC errors job at a small capacity: it shows the job
# runs in the unpacked folder; suite cbmc checks the same harness at N = 8.
DIST_CHECK_ERRORS_N ?= 2
.PHONY: dist distcheck check-dist

# The proof report of this tree's last proof runs (make proof-report), when there is
# one, goes in as proof-report/: what the proofs gave here, beside the jobs to re-run.
DIST_REPORT := $(wildcard $(BUILD)/proof-report/index.html $(BUILD)/proof-report/proof-report.json)
$(DIST_TAR): $(DIST_FILES) $(DIST_REPORT) bsched/dist/Makefile bsched/dist/setup.sh bsched/dist/README.md
	@rm -rf $(BUILD)/dist/$(DIST_NAME) && mkdir -p $(BUILD)/dist/$(DIST_NAME)
	@tar -cf - $(DIST_FILES) | tar -xf - -C $(BUILD)/dist/$(DIST_NAME)
	@$(if $(DIST_REPORT),mkdir -p $(BUILD)/dist/$(DIST_NAME)/proof-report && cp $(DIST_REPORT) $(BUILD)/dist/$(DIST_NAME)/proof-report/)
	@cp bsched/dist/Makefile bsched/dist/setup.sh $(BUILD)/dist/$(DIST_NAME)/
	@# The exact sources the bundle's proofs run on, by digest, so a reviewer can
	@# tell that a bsched.c in a firmware tree is the one proven (sha256sum -c).
	@cd $(BUILD)/dist/$(DIST_NAME) && find bsched -type f | LC_ALL=C sort | xargs sha256sum > SOURCES.sha256
	@sed 's/VERSION/$(DIST_VERSION)/' bsched/dist/README.md > $(BUILD)/dist/$(DIST_NAME)/README.md
	@tar -czf $@ --owner=0 --group=0 --sort=name -C $(BUILD)/dist $(DIST_NAME)
	@rm -rf $(BUILD)/dist/$(DIST_NAME)
	@echo "dist: $@ ($$(tar -tzf $@ | grep -vc '/$$') files, $$(stat -c %s $@) bytes)"

dist: $(DIST_TAR)

# $(call dist_unpack,DIR): a fresh copy of the bundle in DIR/$(DIST_NAME)
dist_unpack = rm -rf $(1) && mkdir -p $(1) && tar -xzf $(DIST_TAR) -C $(1)

distcheck: $(DIST_TAR)
	@$(SETUP) base frama-c cbmc
	@dir=$$(mktemp -d /tmp/bsched-distcheck.XXXXXX); tar -xzf $(DIST_TAR) -C $$dir; \
	cd $$dir/$(DIST_NAME) && start=$$(date +%s) && \
	$(MAKE) --no-print-directory test > test.log 2>&1 && echo "distcheck: unit tests passed" && \
	$(MAKE) --no-print-directory prove > prove.log 2>&1; rc=$$?; tail -4 prove.log; \
	echo "distcheck: make prove exited $$rc after $$(( $$(date +%s) - start )) s"; \
	t=$$(date +%s); $(MAKE) --no-print-directory cbmc > cbmc.log 2>&1; rc2=$$?; tail -3 cbmc.log; \
	echo "distcheck: make cbmc exited $$rc2 after $$(( $$(date +%s) - t )) s (in $$dir/$(DIST_NAME))"; \
	[ $$rc -eq 0 ] && [ $$rc2 -eq 0 ] && rm -rf $$dir

check-dist: $(DIST_TAR)
	@$(SETUP) base cbmc
	@dir=$(BUILD)/dist/check; $(call dist_unpack,$$dir); cd $$dir/$(DIST_NAME); pass=0; fail=0; \
	if $(MAKE) --no-print-directory all > all.log 2>&1; then pass=$$((pass+1)); echo "ok: the bundle builds warning-free"; \
	else fail=$$((fail+1)); echo "FAILED: the bundle does not build"; tail -20 all.log; fi; \
	if $(MAKE) --no-print-directory test > test.log 2>&1 && [ $$(grep -c '^\[  PASSED  \]' test.log) -eq 2 ]; then \
	    pass=$$((pass+1)); echo "ok: its unit tests pass ($$(grep -h '^\[==========\] [0-9]* test(s) run' test.log | awk '{s+=$$2} END {print s}') tests)"; \
	else fail=$$((fail+1)); echo "FAILED: its unit tests"; tail -20 test.log; fi; \
	if $(MAKE) --no-print-directory cbmc-run-errors CBMC_ARGS_errors=N=$(DIST_CHECK_ERRORS_N) > cbmc.log 2>&1 && \
	    grep -q '^PASS' build/cbmc/errors/result.txt; then \
	    pass=$$((pass+1)); echo "ok: its CBMC errors harness passes"; \
	else fail=$$((fail+1)); echo "FAILED: its CBMC errors harness"; tail -20 cbmc.log; fi; \
	if [ -s bsched/proofs/wp/goals.tsv ] && [ -s bsched/proofs/wp/contracts.tsv ] && \
	    $(MAKE) --no-print-directory proof-report > report.log 2>&1 && \
	    grep -q '<td>errors</td><td>N=2' build/proof-report/index.html; then \
	    pass=$$((pass+1)); echo "ok: it carries the WP record, and its make proof-report lists its CBMC run"; \
	else fail=$$((fail+1)); echo "FAILED: the bundle's WP record or make proof-report"; tail -20 report.log; fi; \
	cd $(ROOT); $(call record,dist,$$pass,$$fail); echo "dist: $$pass passed, $$fail failed"; [ $$fail -eq 0 ]
