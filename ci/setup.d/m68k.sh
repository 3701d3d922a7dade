# The CPU32 (MC68332) toolchain of the firmware: Debian's cross compiler, the
# compiler runtime (m68k/runtime.sh), the C library (m68k/newlib.sh) and Mbed
# TLS (mbedtls.sh: the images' net/auth.c calls it), all built here for the
# CPU32 and cached by content under $BSCHED_TOOLS.
apt_install gcc-m68k-linux-gnu binutils-m68k-linux-gnu dpkg-dev xz-utils gcc-12-source

. "$BSCHED_ROOT/ci/setup.d/m68k/runtime.sh"
. "$BSCHED_ROOT/ci/setup.d/m68k/newlib.sh"
# Last: it returns from this script at once when its build is present.
. "$BSCHED_ROOT/ci/setup.d/mbedtls.sh"
