#!/usr/bin/env bash
# The bsched unit tests on a big-endian target: built for s390x with Debian's
# cross gcc and Debian's s390x libcmocka (ci/setup.d/assure.sh), run under qemu-user.
#   assure/bigendian.sh OUT-DIR RESULT-FILE
# Every bsched/tests/test_*.c program, with the sources it needs (assure/mutants.py tests).
set -uo pipefail
cd "$(dirname "$0")/.."
out=$1; result=$2
root=${BSCHED_TOOLS:-${XDG_CACHE_HOME:-$HOME/.cache}/bsched}/s390x/root
lib=$root/usr/lib/s390x-linux-gnu
mkdir -p "$out" "$(dirname "$result")"
pass=0; fail=0
while IFS='|' read -r t src incs extra; do
    exe=$out/$t
    # shellcheck disable=SC2086
    if ! s390x-linux-gnu-gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Wconversion -Werror -Ibsched $incs \
            -I"$root/usr/include" -DBSCHED_MAX_PROCS=4096 -o "$exe" "$src" $extra bsched/bsched.c \
            -L"$lib" -lcmocka; then
        echo "FAILED: $t does not build for s390x"; fail=$((fail + 1)); continue
    fi
    file -b "$exe" | grep -q 'MSB' || { echo "FAILED: $exe is not big-endian"; fail=$((fail + 1)); continue; }
    res=$(QEMU_LD_PREFIX=/usr/s390x-linux-gnu qemu-s390x -E LD_LIBRARY_PATH="$lib" "$exe" 2>&1); rc=$?
    echo "$res" | grep -E '^\[ *(PASSED|FAILED|  OK|==========)' | tail -3
    read -r p f <<< "$(echo "$res" | ci/cmocka-suite --count)"
    [ "$rc" -ne 0 ] && [ "$f" -eq 0 ] && f=1
    pass=$((pass + ${p:-0})); fail=$((fail + ${f:-0}))
    echo "$t on s390x ($(file -b "$exe" | cut -d, -f1-2)): ${p:-0} passed, ${f:-0} failed"
done < <(assure/mutants.py tests)
echo "$pass passed, $fail failed" > "$result"
[ "$fail" -eq 0 ]
