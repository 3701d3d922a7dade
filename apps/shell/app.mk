# The console shell (apps/shell/README.md): make run APP=shell.
# Interactive runs wait for keys most of the time: with sleep=off the idle
# guest jumps from timer to timer as fast as the host goes (measured: 34 % of
# a host core and uptime 18 s after 5 s; README.md), so make run uses sleep=on. The
# tests (apps/shell/tests/) run QEMU themselves with sleep=off (deterministic).
# The common commands need the LED; each board it runs on has its part (shell_SRCS_BOARD).
shell_NEEDS  := console tick led
shell_BOARDS := robocube stm32f405
shell_ICOUNT_robocube := shift=8,sleep=on
# For make run's banner: exit stops the motors and switches the board off (README.md).
shell_QUIT   := the shell's exit ends the run

# Target tests: the shell on the emulated board, every command checked over
# QMP against the board model, plus `make run APP=shell` with piped stdin.
CHECKS += shell-target
EMU_CHECKS += shell-target
.PHONY: check-shell-target
check-shell-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=shell
	@BSCHED_QEMU=$(QEMU_M68K) SHELL_ELF=$(call app_elf,shell) \
	    ci/pytest-suite shell-target apps/shell/tests
# Its main starts the board itself (board_start ... k_start).
shell_BOOT := self
# The interpreter and the common commands, and the board's part (shell.h).
shell_SRCS           := apps/shell/shell.c apps/shell/shell_main.c apps/shell/shell_robocube.c
shell_SRCS_stm32f405 := apps/shell/shell.c apps/shell/shell_main.c apps/shell/shell_stm32f405.c
