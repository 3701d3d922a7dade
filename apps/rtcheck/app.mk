# The compiler runtime and the C library checked on the board: int <-> float
# conversions, float and double arithmetic, 64-bit division and shifts, printf's
# conversions, string.h, stdlib.h, float libm, dt() and (float)value(q) in a PDL
# process, each compared with the host's result (apps/rtcheck/tests/). The suite
# also runs apps/hello's tests (an ordinary main as a thread, printf's cost): that
# image's app.mk stays the one comment line a new program needs.
# The C library, and a PDL process for dt() and value().
rtcheck_NEEDS := console tick libc ports
rtcheck_SRCS := apps/rtcheck/rtcheck.c apps/rtcheck/rt_vectors.c apps/rtcheck/rt_libc.c

RTCHECK_HOST := $(BUILD)/tests/rtcheck_host
$(RTCHECK_HOST): apps/rtcheck/tests/host_main.c $(wildcard apps/rtcheck/rt_*.[ch])
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) -std=c99 -O2 -Wall -Wextra -Werror -Iapps/rtcheck -o $@ apps/rtcheck/tests/host_main.c \
	    apps/rtcheck/rt_vectors.c apps/rtcheck/rt_libc.c -lm

CHECKS += rtcheck
EMU_CHECKS += rtcheck
.PHONY: check-rtcheck
check-rtcheck:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory $(call app_elf,rtcheck) $(call app_elf,hello) $(RTCHECK_HOST)
	@BSCHED_QEMU=$(QEMU_M68K) FW_DIR=$(FW_BUILD) RTCHECK_HOST=$(RTCHECK_HOST) \
	    ci/pytest-suite rtcheck apps/rtcheck/tests apps/hello/tests
