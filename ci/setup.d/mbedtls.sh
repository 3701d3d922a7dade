# Mbed TLS 2.28 from Debian bookworm's source package, in the minimal
# configuration of net/auth_mbedtls_config.h (AES-128 and CMAC only): the
# primitive behind the frame authentication of net/auth.c. Sourced by
# ci/setup.d/m68k.sh after newlib (m68k/newlib.sh), whose headers it is
# compiled against; `ci/setup mbedtls` alone works once `ci/setup m68k` has run.
#
#   $BSCHED_TOOLS/mbedtls-src/tree        the unpacked source package (never in git)
#   $BSCHED_TOOLS/mbedtls/HASH/include    its public headers
#   $BSCHED_TOOLS/mbedtls/HASH/library    the five sources and the library's
#                                         internal headers (the host tests compile
#                                         these with their own sanitizer flags)
#   $BSCHED_TOOLS/mbedtls/HASH/cpu32/libmbedcrypto.a   built for the CPU32
#   $BSCHED_TOOLS/mbedtls/HASH/cpu32/ci/*.ci   its call graph, for assure/stack.py
#   build/mbedtls -> $BSCHED_TOOLS/mbedtls/HASH        this checkout's link
# HASH covers this script, the configuration header and the newlib build it
# is compiled against, so a checkout with another configuration gets its own
# build and never overwrites a neighbour's.
# The source package comes through lib.sh's fetch_debian_source, as QEMU's.

mbedtls_src=$BSCHED_TOOLS/mbedtls-src
mbedtls_config=$BSCHED_ROOT/net/auth_mbedtls_config.h
mbedtls_link=$BSCHED_ROOT/build/mbedtls
# The sources the configuration needs: AES, the generic cipher layer CMAC is
# written on (cipher.c, cipher_wrap.c), CMAC, mbedtls_ct_memcmp (the MIC's
# constant-time comparison) and mbedtls_platform_zeroize.
mbedtls_files="aes.c cipher.c cipher_wrap.c cmac.c constant_time.c platform_util.c"

mbedtls_newlib=$(readlink -f "$BSCHED_ROOT/build/newlib" 2>/dev/null || true)
if [ -z "$mbedtls_newlib" ] || [ ! -f "$mbedtls_newlib/include/string.h" ]; then
    echo "ci/setup: mbedtls is compiled against newlib's headers: run ci/setup m68k" >&2
    exit 1
fi
mbedtls_want=$( { sha256sum "$BSCHED_ROOT/ci/setup.d/mbedtls.sh" "$mbedtls_config" | cut -d' ' -f1;
                  echo "$mbedtls_newlib"; } | sha256sum | cut -c1-16)
mbedtls_dir=$BSCHED_TOOLS/mbedtls/$mbedtls_want

mbedtls_link_checkout() {
    mkdir -p "$(dirname "$mbedtls_link")"
    [ "$(readlink "$mbedtls_link" 2>/dev/null)" = "$mbedtls_dir" ] || ln -sfn "$mbedtls_dir" "$mbedtls_link"
}

if [ -f "$mbedtls_dir/.complete" ]; then
    mbedtls_link_checkout
    return 0
fi

apt_install dpkg-dev gcc-m68k-linux-gnu binutils-m68k-linux-gnu

mkdir -p "$mbedtls_src"
exec 7>"$mbedtls_src/.lock"
flock 7

tree=$mbedtls_src/tree
if [ ! -f "$tree/include/mbedtls/version.h" ]; then
    echo "ci/setup: fetching bookworm's mbedtls source package into $mbedtls_src" >&2
    fetch_debian_source mbedtls "$mbedtls_src/download"
    dsc=$(ls "$mbedtls_src"/download/mbedtls_2.28*.dsc 2>/dev/null | head -n1)
    if [ -z "$dsc" ]; then
        echo "ci/setup: no mbedtls 2.28 source package found (got: $(ls "$mbedtls_src/download"))" >&2
        exit 1
    fi
    rm -rf "$tree"
    dpkg-source --no-check -x "$dsc" "$tree" >/dev/null
    rm -rf "$mbedtls_src/download"
fi

echo "ci/setup: building Mbed TLS ($(sed -n 's/^#define MBEDTLS_VERSION_STRING *"\(.*\)"/\1/p' \
    "$tree/include/mbedtls/version.h"), AES + CMAC) for the CPU32 in $mbedtls_dir" >&2
rm -rf "$mbedtls_dir.tmp" && mkdir -p "$mbedtls_dir.tmp/library" "$mbedtls_dir.tmp/cpu32/obj"
cp -r "$tree/include" "$mbedtls_dir.tmp/include"
cp "$tree"/library/*.h "$mbedtls_dir.tmp/library/"
for f in $mbedtls_files; do cp "$tree/library/$f" "$mbedtls_dir.tmp/library/"; done
cp "$tree/LICENSE" "$mbedtls_dir.tmp/" 2>/dev/null || true
# The firmware's headers (boards/robocube/board.mk): GCC's and newlib's, -nostdinc
# keeping the cross glibc's out. memcpy/memset/memcmp come from
# kernel/lib/kstring.c at the link (every image has it), the rest of the C
# library from newlib. -fno-store-merging as boards/robocube/board.mk (no word
# stores merged at odd addresses: the CPU32 faults on them).
cross=m68k-linux-gnu-
cflags=(-std=c99 -mcpu=cpu32 -Os -ffreestanding -nostdinc -isystem "$("${cross}gcc" -print-file-name=include)"
        -isystem "$mbedtls_newlib/include" -I "$BSCHED_ROOT/net"
        "-DMBEDTLS_CONFIG_FILE=\"auth_mbedtls_config.h\"" -I "$mbedtls_dir.tmp/include"
        -ffunction-sections -fdata-sections -fno-tree-loop-distribute-patterns -fno-store-merging -g
        -Werror=implicit-function-declaration
        -fstack-usage -fcallgraph-info=su)
objs=()
for f in $mbedtls_files; do
    o=$mbedtls_dir.tmp/cpu32/obj/${f%.c}.o
    "${cross}gcc" "${cflags[@]}" -c -o "$o" "$mbedtls_dir.tmp/library/$f"
    objs+=("$o")
done
"${cross}ar" rcs "$mbedtls_dir.tmp/cpu32/libmbedcrypto.a" "${objs[@]}"
# Each routine's frame and callees, for the worst-case stack analysis (assure/stack.py).
mkdir -p "$mbedtls_dir.tmp/cpu32/ci"
mv "$mbedtls_dir.tmp"/cpu32/obj/*.ci "$mbedtls_dir.tmp/cpu32/ci/"
rm -f "$mbedtls_dir.tmp"/cpu32/obj/*.su
touch "$mbedtls_dir.tmp/.complete"
rm -rf "$mbedtls_dir" && mv "$mbedtls_dir.tmp" "$mbedtls_dir"
# Keep the 4 newest builds.
ls -1dt "$BSCHED_TOOLS"/mbedtls/*/ 2>/dev/null | tail -n +5 | xargs -r rm -rf
exec 7>&-
mbedtls_link_checkout
