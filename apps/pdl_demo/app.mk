# The example behaviours (pdl/examples/) as a PDL program: phototaxis,
# obstacle avoidance, wandering, battery motivation, superposed on motors 0
# and 1 (the arena robot's wiring, pdl/robot.h). make run APP=pdl_demo runs it
# in the ecosystem arena (WORLD=none: the board alone).
pdl_demo_SRCS := $(wildcard apps/pdl_demo/*.c) pdl/examples/behaviours.c
pdl_demo_WORLD := default
