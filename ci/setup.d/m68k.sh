# Cross compiler for the MC68332 (CPU32) firmware.
apt_install gcc-m68k-linux-gnu binutils-m68k-linux-gnu
