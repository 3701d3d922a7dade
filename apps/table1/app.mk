# The paper's Table 1 set on the nanokernel's B-scheduler thread, printing Table 2.
# 128 Hz instead of the kernel's 1024 Hz: every minor cycle prints its line,
# which must fit in its tick at 38400 baud (see table1.c).
table1_TICK_HZ := 128
# Its main starts the board itself (board_start ... k_start).
table1_BOOT := self
