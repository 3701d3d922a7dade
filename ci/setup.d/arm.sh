# The ARMv7-M (Cortex-M3/M4) firmware of the boards on that port
# (boards/stm32f405/, boards/mps2-an385/): Debian's bare-metal cross compiler,
# its newlib for arm-none-eabi (the C library the images link, the same
# newlib 3.3.0 the RoboCube's is built from) and Debian's own qemu-system-arm,
# whose netduinoplus2 and mps2-an385 machines model the two boards. Sourced by
# ci/setup; apt_install returns at once when all are there.
apt_install gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm
