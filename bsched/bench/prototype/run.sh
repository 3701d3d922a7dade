#!/usr/bin/env bash
# make bench-prototype: `make bench` on a design prototype of the minor cycle.
#   CROSS_CC=... CROSS_CFLAGS=... run.sh NAME BUILD QEMU
# Copies the tree of the prototypes' base commit to BUILD/prototype-NAME/, applies
# bsched/bench/prototype/step-NAME.patch there and runs `make bench` in that copy
# (its own build/ folder, this checkout's QEMU). The copy is thrown away and
# rebuilt on every run; the library and the firmware never see the patch.
set -euo pipefail
name=$1
build=$2
qemu=$3
root=$(cd "$(dirname "$0")/../../.." && pwd)
patch_file=$root/bsched/bench/prototype/step-$name.patch
if [ ! -f "$patch_file" ]; then
    echo "bench-prototype: no prototype '$name' (have: $(cd "$root/bsched/bench/prototype" && ls step-*.patch | sed 's/^step-//; s/\.patch$//' | tr '\n' ' '))" >&2
    exit 2
fi
# v7, v9 and v10 are against the tree before v11 landed in bsched.c (README.md
# here); a later patch names its own base in a first line "base: COMMIT" (patch
# skips the lines before the diff). The copy is that commit's tree, not the checkout's.
named_base=$(sed -n '1s/^base: *\([0-9a-f]\{7,40\}\) *$/\1/p' "$patch_file")
base=${PROTOTYPE_BASE:-${named_base:-ea02446}}
tree=$build/prototype-$name
rm -rf "$tree"
mkdir -p "$tree"
if ! git -C "$root" archive "$base" | tar -x -C "$tree"; then
    echo "bench-prototype: commit $base (the prototypes' base) is not in this clone's history" >&2
    exit 1
fi
if ! patch -d "$tree" -p1 --quiet --forward < "$patch_file"; then
    echo "bench-prototype: $patch_file does not apply to bsched/bsched.c of $base" >&2
    exit 1
fi
make -C "$tree" --no-print-directory bench BUILD="$tree/build" QEMU_M68K="$qemu"
# The text goal is measured as README.md states it: CROSS_CFLAGS (-Os, CPU32), default capacity.
# shellcheck disable=SC2086
${CROSS_CC:?} $CROSS_CFLAGS -c -o "$tree/build/bsched-cpu32.o" "$tree/bsched/bsched.c"
text=$(${CROSS_CC%gcc}size "$tree/build/bsched-cpu32.o" | awk 'NR == 2 {print $1}')
{ cat "$tree/build/bench/bench.txt"; echo "cpu32 bsched.o text ${text} B (-Os, BSCHED_MAX_PROCS default)"; } \
    > "$build/bench/prototype-$name.txt"
tail -1 "$build/bench/prototype-$name.txt"
echo "bench-prototype: $build/bench/prototype-$name.txt"
