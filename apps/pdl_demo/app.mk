# The example behaviours (pdl/examples/) as a PDL program on the board:
# phototaxis, obstacle avoidance, wandering, battery motivation, superposed
# on motors 0 and 1 (wiring: pdl/examples/behaviours.h). make run APP=pdl_demo
pdl_demo_SRCS := $(wildcard apps/pdl_demo/*.c) pdl/examples/behaviours.c
# Its main starts the board itself (board_start ... k_start).
pdl_demo_BOOT := self
