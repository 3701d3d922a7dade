# Suite bsched-package: bsched/ as a package a firmware build consumes. Its
# consumers (add_subdirectory, find_package after cmake --install, pkg-config)
# build and run on the host, a bare-metal image cross-builds for the CPU32 and
# the Cortex-M4 through this folder's toolchain files, the versions agree with
# bsched/VERSION, and the proof bundle's SOURCES.sha256 matches the bundle and
# the tree. Output in build/package/; one ok/FAILED line per case
# (bsched/tests/package/run.sh). It lives beside the library's other tests:
# what it proves is the package an embedder takes, and bsched/dist/ holds only
# the bundle's own files.
CHECKS += bsched-package
.PHONY: check-bsched-package
check-bsched-package: $(DIST_TAR)
	@$(SETUP) base m68k arm
	@mkdir -p $(BUILD)/package; \
	bsched/tests/package/run.sh $(BUILD)/package/out $(DIST_TAR) | tee $(BUILD)/package/cases.txt; rc=$${PIPESTATUS[0]}; \
	pass=$$(grep -c '^ok: ' $(BUILD)/package/cases.txt); fail=$$(grep -c '^FAILED: ' $(BUILD)/package/cases.txt); \
	if [ $$rc -ne 0 ] && [ $$fail -eq 0 ]; then fail=1; echo "FAILED: run.sh stopped with status $$rc"; fi; \
	$(call record,bsched-package,$$pass,$$fail); echo "bsched-package: $$pass passed, $$fail failed"; [ $$fail -eq 0 ]
