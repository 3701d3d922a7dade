#!/usr/bin/env bash
# Every host unit suite (HOST_UNIT_CHECKS) rebuilt with ASan+UBSan into its own
# BUILD tree and run: make BUILD=OUT HOST_CFLAGS="... -fsanitize=..." check-SUITE.
# A sanitizer report or a failed test fails the suite, except a suite listed in
# assure/sanitize-known.txt (`suite | finding`): an open finding in another part,
# reported on every run, never counted as passed.
#   assure/sanitize.sh OUT "HOST_CFLAGS" "SUITES" RESULT-FILE
set -uo pipefail
cd "$(dirname "$0")/.."
out=$1; cflags=$2; suites=$3; result=$4
san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# Warnings are the plain build's gate; GCC 12 reports extra -Wconversion warnings on code
# that UBSan instruments (shifts), so -Werror would fail builds for no run-time reason.
cflags=$(echo " $cflags " | sed 's/ -Werror / /g')
mkdir -p "$out" "$(dirname "$result")"
# Suites that run Python use $(BUILD)/venv: the same environment as the main build.
[ -e build/venv ] && ln -sfn "$(readlink -f build/venv)" "$out/venv"
pass=0; fail=0; known=0
for s in $suites; do
    log=$out-$s.log
    rm -f "$out/results/$s.txt"
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
        make --no-print-directory BUILD="$out" HOST_CFLAGS="$cflags $san" "check-$s" > "$log" 2>&1
    rc=$?
    line=$(cat "$out/results/$s.txt" 2>/dev/null)
    sp=$(echo "$line" | sed -n 's/^\([0-9]*\) passed.*/\1/p'); sf=$(echo "$line" | sed -n 's/.*, \([0-9]*\) failed/\1/p')
    sp=${sp:-0}; sf=${sf:-0}
    reports=$(grep -cE "ERROR: (Address|Leak)Sanitizer|runtime error:" "$log")
    [ "$reports" -gt 0 ] && sf=$((sf + reports))
    [ "$rc" -ne 0 ] && [ "$sf" -eq 0 ] && sf=1
    finding=$(sed -n "s/^$s *| *//p" assure/sanitize-known.txt 2>/dev/null)
    if [ "$sf" -gt 0 ] && [ -n "$finding" ]; then
        echo "sanitize $s: KNOWN FINDING, not counted ($sp passed, $sf failed): $finding"
        grep -m3 -E "ERROR: (Address|Leak)Sanitizer|runtime error:|Segmentation" "$log" | sed 's/^/    /'
        known=$((known + 1)); continue
    fi
    if [ "$sf" -gt 0 ]; then
        grep -E -A8 "ERROR: (Address|Leak)Sanitizer|runtime error:" "$log" | head -30
        [ "$reports" -eq 0 ] && tail -15 "$log"
    fi
    echo "sanitize $s: $sp passed, $sf failed (ASan+UBSan; log $log)"
    pass=$((pass + sp)); fail=$((fail + sf))
done
echo "sanitize: $pass passed, $fail failed, $known suites with a known open finding"
echo "$pass passed, $fail failed" > "$result"
[ "$fail" -eq 0 ]
