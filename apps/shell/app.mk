# The console shell (apps/shell/README.md): make run APP=shell.
# Interactive runs wait for keys most of the time: with sleep=off the idle
# guest would jump from timer to timer at full host speed (a busy host core,
# and uptime racing ahead of the wall clock), so make run uses sleep=on. The
# tests (apps/shell/tests/) run QEMU themselves with sleep=off (deterministic).
shell_ICOUNT := shift=8,sleep=on

# Target tests: the shell on the emulated board, every command checked over
# QMP against the board model, plus `make run APP=shell` with piped stdin.
CHECKS += shell-target
.PHONY: check-shell-target
check-shell-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=shell
	@BSCHED_QEMU=$(QEMU_M68K) SHELL_ELF=$(call app_elf,shell) \
	    ci/pytest-suite shell-target apps/shell/tests
