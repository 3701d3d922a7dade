# Test image of the board I/O drivers: brings the board up (boot report),
# starts the sensor sampler and answers one-line commands on the console so
# the target tests (drivers/tests/target/) can drive the drivers while the host
# sets and reads the board model over QMP. Test-only: the shell image
# (apps/shell) is the one for people.
iotest_TICK_HZ := 1024
# Its main starts the board itself (board_start ... k_start).
iotest_BOOT := self
