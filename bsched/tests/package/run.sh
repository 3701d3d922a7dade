#!/usr/bin/env bash
# The bsched-package suite: bsched/ as a package a firmware build consumes.
#   bsched/tests/package/run.sh OUT DIST_TAR
# Builds every consumer in OUT (fresh each run) and prints one 'ok: ...' or
# 'FAILED: ...' line per case; package.mk counts them. Each step's output goes
# to OUT/NAME.log and its tail is printed when the case fails.
set -uo pipefail
cd "$(dirname "$0")/../../.."
root=$PWD
out=$(realpath -m "$1"); dist_tar=$(realpath -m "$2")
here=bsched/tests/package
version=$(cat bsched/VERSION)
major=${version%%.*}
CMAKE=${CMAKE:-cmake}
PKG_CONFIG=${PKG_CONFIG:-pkg-config}
# The library and the consumers must build warning-free, as bsched.c does in
# suite bsched-build. The flags go in through CFLAGS, which CMake takes as the
# start of CMAKE_C_FLAGS and appends a toolchain file's CMAKE_C_FLAGS_INIT to
# (-DCMAKE_C_FLAGS would replace that, and with it the toolchain's -mcpu).
warn="-Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror"
export CFLAGS="-O2 $warn"
rm -rf "$out"; mkdir -p "$out"

ok()   { echo "ok: $1"; }
fail() { echo "FAILED: $1"; [ -n "${2:-}" ] && [ -f "$2" ] && tail -15 "$2" | sed 's/^/    /'; }
# case_run NAME LOG CMD...: the case passes when CMD exits 0
case_run() {
    local what=$1 log=$2; shift 2
    if "$@" > "$log" 2>&1; then ok "$what"; else fail "$what" "$log"; fi
}
configure() { "$CMAKE" -S "$1" -B "$2" "${@:3}"; }
conf_build() { configure "$@" && "$CMAKE" --build "$2"; }
# Firmware is built for size, as the firmware of this repository is.
cross_build() { CFLAGS="-Os $warn" conf_build "$@"; }

# --- CMake, add_subdirectory (host) -------------------------------------------
case_run "add_subdirectory: the consumer builds warning-free with BSCHED_MAX_PROCS=16" "$out/subdir.log" \
    conf_build $here/subdir "$out/subdir" -DBSCHED_MAX_PROCS=16 -DBSCHED_EXPECT_MAX_PROCS=16
case_run "add_subdirectory: the consumer plans Table 2 and sees capacity 16" "$out/subdir-run.log" \
    "$out/subdir/consumer"
if configure $here/subdir "$out/subdir-bad" -DBSCHED_MAX_PROCS=0 > "$out/subdir-bad.log" 2>&1; then
    fail "BSCHED_MAX_PROCS=0 is refused at configure time" "$out/subdir-bad.log"
elif grep -q "BSCHED_MAX_PROCS='0' is not a whole number 1..65535" "$out/subdir-bad.log"; then
    ok "BSCHED_MAX_PROCS=0 is refused at configure time, by name"
else
    fail "BSCHED_MAX_PROCS=0 is refused at configure time, by name" "$out/subdir-bad.log"
fi

# --- cmake --install, find_package (host) --------------------------------------
# Configured for the default prefix and installed elsewhere with --prefix: the
# installed files must not depend on where the configure step thought they go.
inst=$out/install
lib_install() {
    "$CMAKE" -S bsched -B "$out/lib" -DBSCHED_MAX_PROCS=64 && \
        "$CMAKE" --build "$out/lib" && "$CMAKE" --install "$out/lib" --prefix "$inst"
}
case_run "the library alone configures, builds warning-free and installs (BSCHED_MAX_PROCS=64)" "$out/lib.log" lib_install
missing=
for f in include/bsched.h lib/libbsched.a lib/cmake/bsched/bschedConfig.cmake \
         lib/cmake/bsched/bschedConfigVersion.cmake lib/cmake/bsched/bschedTargets.cmake lib/pkgconfig/bsched.pc; do
    [ -f "$inst/$f" ] || missing="$missing $f"
done
if [ -z "$missing" ]; then ok "the install holds bsched.h, libbsched.a, the CMake config, version and targets files, bsched.pc"
else fail "the install lacks:$missing"; fi
got=$(sed -n 's/^set(PACKAGE_VERSION "\(.*\)")$/\1/p' "$inst/lib/cmake/bsched/bschedConfigVersion.cmake" 2>/dev/null)
if [ "$got" = "$version" ]; then ok "the installed version file says $version, bsched/VERSION's"
else fail "the installed version file says '$got', bsched/VERSION says $version"; fi

case_run "find_package: the consumer configures (bsched_VERSION is $version) and builds warning-free" "$out/installed.log" \
    conf_build $here/installed "$out/installed" "-DCMAKE_PREFIX_PATH=$inst" -DBSCHED_EXPECT_VERSION="$version" \
    -DBSCHED_EXPECT_MAX_PROCS=64
case_run "find_package: the consumer plans Table 2 and sees the installed capacity 64" "$out/installed-run.log" \
    "$out/installed/consumer"
case_run "find_package(bsched $major.0): an older minor version of the same major is accepted" "$out/want-old-minor.log" \
    configure $here/installed "$out/want-old-minor" "-DCMAKE_PREFIX_PATH=$inst" -DBSCHED_WANT_VERSION="$major.0"
next="$((major + 1)).0"
if configure $here/installed "$out/want-next-major" "-DCMAKE_PREFIX_PATH=$inst" -DBSCHED_WANT_VERSION="$next" \
        > "$out/want-next-major.log" 2>&1; then
    fail "find_package(bsched $next) fails: the next major version is incompatible" "$out/want-next-major.log"
elif grep -q "requested version \"$next\"" "$out/want-next-major.log" && \
     grep -q "bschedConfig.cmake, version: $version" "$out/want-next-major.log"; then
    ok "find_package(bsched $next) fails: version $version is not compatible with $next"
else
    fail "find_package(bsched $next) fails for the version, not for another reason" "$out/want-next-major.log"
fi

# The installed tree holds no path of its own, so a copy works where it lands.
moved=$out/moved
cp -r "$inst" "$moved"
if grep -rlF "$inst" "$inst" > "$out/moved.log" 2>&1; then
    fail "the installed files name the folder they were installed in" "$out/moved.log"
elif configure $here/installed "$out/installed-moved" "-DCMAKE_PREFIX_PATH=$moved" >> "$out/moved.log" 2>&1 && \
     grep -q "bsched $version from $moved/lib/cmake/bsched" "$out/moved.log" && \
     [ "$(realpath -m "$(PKG_CONFIG_PATH=$moved/lib/pkgconfig "$PKG_CONFIG" --variable=includedir bsched)")" = "$moved/include" ]; then
    ok "a copy of the installed tree elsewhere is what find_package and pkg-config find there"
else fail "a copy of the installed tree elsewhere is not found there" "$out/moved.log"; fi

# --- pkg-config (host) ---------------------------------------------------------
export PKG_CONFIG_PATH=$inst/lib/pkgconfig
got=$("$PKG_CONFIG" --modversion bsched 2>&1)
if [ "$got" = "$version" ]; then ok "pkg-config --modversion bsched is $version"
else fail "pkg-config --modversion bsched is '$got', bsched/VERSION says $version"; fi
cflags=$("$PKG_CONFIG" --cflags bsched 2>&1)
incdir=$(for f in $cflags; do case $f in -I*) echo "${f#-I}" ;; esac; done)
if [ -n "$incdir" ] && [ "$(realpath -m "$incdir")" = "$inst/include" ] && \
   [[ " $cflags " == *" -DBSCHED_MAX_PROCS=64 "* ]]; then
    ok "pkg-config --cflags names the installed include folder (found from bsched.pc's place) and -DBSCHED_MAX_PROCS=64"
else fail "pkg-config --cflags bsched gave '$cflags'"; fi
mkdir -p "$out/pkgconfig"
case_run "pkg-config: the Makefile consumer builds warning-free from pkg-config's flags alone" "$out/pkgconfig.log" \
    make --no-print-directory -C $here/pkgconfig OUT="$out/pkgconfig" EXPECT_MAX_PROCS=64 CFLAGS="$CFLAGS" PKG_CONFIG="$PKG_CONFIG"
case_run "pkg-config: the consumer plans Table 2 and sees capacity 64" "$out/pkgconfig-run.log" \
    "$out/pkgconfig/consumer"
unset PKG_CONFIG_PATH

# --- cross builds through toolchain files --------------------------------------
# cross NAME TOOLCHAIN PREFIX 'what readelf must print' READELF-OPTION
cross() {
    local name=$1 tc=$2 prefix=$3 want=$4 opt=$5 dir=$out/$1
    case_run "$name: the freestanding image builds warning-free with add_subdirectory and links with -nostdlib" "$dir.log" \
        cross_build $here/firmware "$dir" "-DCMAKE_TOOLCHAIN_FILE=$root/$here/toolchains/$tc"
    local lib=$dir/bsched/libbsched.a
    if [ -f "$lib" ] && "${prefix}readelf" "$opt" "$lib" 2>&1 | grep -q "$want" && \
       [ "$("${prefix}readelf" "$opt" "$lib" | grep -c "$want")" -eq "$("${prefix}ar" t "$lib" | wc -l)" ]; then
        ok "$name: every object of libbsched.a is built for it ($want)"
    else
        fail "$name: libbsched.a is not all built for it ($want)"
    fi
    local undef
    undef=$("${prefix}nm" -u "$lib" 2>&1 | grep -v -e ':$' -e '^$')
    if [ -f "$lib" ] && [ -z "$undef" ]; then ok "$name: libbsched.a calls nothing outside itself (nm -u is empty)"
    else fail "$name: libbsched.a needs: $(echo $undef)"; fi
}
cross cpu32 cpu32.cmake m68k-linux-gnu- "Flags: .*cpu32" -h
cross cortex-m4 cortex-m4.cmake arm-none-eabi- "Tag_CPU_arch: v7E-M" -A

# --- the manifests that carry a version ---------------------------------------
if python3 - "$version" <<'PY'
import json, os, sys
d = json.load(open("bsched/library.json"))
assert d["version"] == sys.argv[1], d["version"]
assert d["name"] == "bsched"
for f in d["build"]["srcFilter"]:
    assert os.path.isfile(os.path.join("bsched", f[2:-1])), f
PY
then ok "library.json is JSON, says version $version and builds files that exist"
else fail "library.json: wrong version or a source that does not exist"; fi
if grep -qx "  cmake: zephyr" bsched/zephyr/module.yml && grep -qx "  kconfig: zephyr/Kconfig" bsched/zephyr/module.yml && \
   [ -f bsched/zephyr/CMakeLists.txt ] && [ -f bsched/zephyr/Kconfig ] && grep -q 'bsched\.c' bsched/zephyr/CMakeLists.txt; then
    ok "zephyr/module.yml names its CMakeLists.txt and Kconfig, and they exist"
else fail "zephyr/module.yml or the files it names"; fi
if grep -q "^## \[$version\] - " bsched/CHANGELOG.md; then ok "CHANGELOG.md has an entry for $version"
else fail "CHANGELOG.md has no '## [$version] - DATE' entry"; fi

# --- the proof bundle names its sources by SHA-256 ----------------------------
name=bsched-$version
case "$dist_tar" in */$name.tar.gz) ok "the bundle is named for bsched/VERSION ($name.tar.gz)" ;;
    *) fail "the bundle $dist_tar is not $name.tar.gz" ;; esac
mkdir -p "$out/dist" && tar -xzf "$dist_tar" -C "$out/dist"
b=$out/dist/$name
if [ -f "$b/SOURCES.sha256" ] && (cd "$b" && sha256sum --quiet -c SOURCES.sha256) > "$out/dist-check.log" 2>&1; then
    ok "every file SOURCES.sha256 lists is in the bundle with its digest ($(wc -l < "$b/SOURCES.sha256") files)"
else fail "the bundle's files do not match its SOURCES.sha256" "$out/dist-check.log"; fi
if [ -f "$b/SOURCES.sha256" ] && diff <(cd "$b" && find bsched -type f | LC_ALL=C sort) \
        <(sed 's/^[0-9a-f]\{64\}  //' "$b/SOURCES.sha256" | LC_ALL=C sort) > "$out/dist-list.log" 2>&1; then
    ok "SOURCES.sha256 lists every file of the bundle's bsched/, no more"
else fail "SOURCES.sha256 and the bundle's bsched/ differ" "$out/dist-list.log"; fi
if [ -f "$b/SOURCES.sha256" ] && sha256sum --quiet -c "$b/SOURCES.sha256" > "$out/dist-tree.log" 2>&1; then
    ok "every digest in SOURCES.sha256 is that of the tree's file"
else fail "SOURCES.sha256 does not match the tree (make dist again?)" "$out/dist-tree.log"; fi
# The check above must be able to fail: one byte changed in a copy of bsched.c.
cp -r "$b" "$out/dist/tampered" && printf ' ' >> "$out/dist/tampered/bsched/bsched.c"
if (cd "$out/dist/tampered" && sha256sum --quiet -c SOURCES.sha256) > /dev/null 2>&1; then
    fail "a bundle with bsched.c changed by one byte still passes its SOURCES.sha256"
else ok "a bundle with bsched.c changed by one byte fails its SOURCES.sha256"; fi
