# Every quantity type (int8, int16, int32, uint8, uint16, float) for 1000
# cycles, printed: the board's output must equal the host's, line for line
# (pdl/tests/target/test_pdl_types.py). make run APP=pdl_types
pdl_types_NEEDS := console tick ports

# apps/pdl_types on the host runtime (its own main: pdl_sleep_ms runs the
# cycles), to compare with the board's output line for line (suite pdl-target,
# apps/pdl_demo/app.mk).
PDL_TYPES_HOST := $(PDL_BUILD)/pdl_types_host
$(PDL_TYPES_HOST): apps/pdl_types/main.c $(PDL_HOST_SRCS) $(PDL_HEADERS)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(PDL_HOST_CFLAGS) -DPDL_HOST=1 -o $@ $< $(PDL_HOST_SRCS)
