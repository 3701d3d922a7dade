# Test-only image of the motion drivers (TPU, motors, odometry): a line
# protocol on the console that drivers/tests/target_motion/ drives over stdin while
# it checks the board model over QMP. Not a user shell (that is apps/shell).
# Its main starts the board itself (board_start ... k_start).
motiontest_BOOT := self
