# PDL benchmark and overrun image (pdl/README.md "Speed"): the cost of a PDL
# cycle for 5..30 processes, the CPU load at f0 = 1024 Hz with 20 processes
# and 40 quantities, the cycle thread's stack, then an overloaded program.
# Kernel tick 1024 Hz: one PDL cycle per tick.
pdl_bench_NEEDS := console tick ports
pdl_bench_TICK_HZ := 1024
# Its main starts the board itself (board_start ... k_start).
pdl_bench_BOOT := self
# Its tests: suite pdl-target (apps/pdl_demo/app.mk).
