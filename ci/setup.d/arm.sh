# The ARMv7-M (Cortex-M4) firmware of the stm32f405 board (boards/stm32f405/):
# Debian's bare-metal cross compiler, picolibc (the C library the images link)
# and Debian's own qemu-system-arm, whose netduinoplus2 machine models the
# STM32F405. Sourced by ci/setup; apt_install returns at once when all are there.
apt_install gcc-arm-none-eabi picolibc-arm-none-eabi qemu-system-arm
