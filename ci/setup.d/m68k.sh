# The CPU32 (MC68332) toolchain of the firmware: Debian's cross compiler, the
# compiler runtime (m68k/runtime.sh), the C library (m68k/newlib.sh) and Mbed
# TLS (mbedtls.sh: the images' net/auth.c calls it), all built here for the
# CPU32 and cached by content under $BSCHED_TOOLS.
apt_install gcc-m68k-linux-gnu binutils-m68k-linux-gnu dpkg-dev xz-utils gcc-12-source

# Each part in a subshell of its own: bash 5.2, sourcing a file inside the
# subshell ci/setup runs this script in, lets a file that ends in `test || ln ...`
# exec ln in place of the subshell, and the parts after it never ran (measured:
# on a fresh clone newlib and Mbed TLS were not set up). mbedtls.sh's `return`
# then ends only its own subshell.
( . "$BSCHED_ROOT/ci/setup.d/m68k/runtime.sh" )
( . "$BSCHED_ROOT/ci/setup.d/m68k/newlib.sh" )
( . "$BSCHED_ROOT/ci/setup.d/mbedtls.sh" )
