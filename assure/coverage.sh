#!/usr/bin/env bash
# Branch coverage of every host unit suite: each suite rebuilt with --coverage
# into its own BUILD tree and run (make BUILD=OUT HOST_CFLAGS=... check-SUITE),
# then lcov per part (bsched.c, kernel/, drivers/, net/, pdl/, tools/) and an
# HTML report in OUT/html/index.html. bsched/bsched.c must be covered fully
# (every line and every branch).
#   assure/coverage.sh OUT "HOST_CFLAGS" "SUITES" RESULT-FILE
set -uo pipefail
cd "$(dirname "$0")/.."
out=$1; cflags=$2; suites=$3; result=$4
rc_opts=(--rc lcov_branch_coverage=1)
rm -rf "$out"; mkdir -p "$out" "$(dirname "$result")"
# Suites that run Python use $(BUILD)/venv: the same environment as the main build.
[ -e build/venv ] && ln -sfn "$(readlink -f build/venv)" "$out/venv"
pass=0; fail=0
for s in $suites; do
    if ! make --no-print-directory BUILD="$out" HOST_CFLAGS="$cflags" "check-$s" > "$out/$s.log" 2>&1; then
        echo "coverage: suite $s failed under --coverage (log $out/$s.log)"; fail=$((fail + 1))
    fi
done
# A test built with sanitizers (test_pdl_sanitized) has their checks compiled in as
# branches of the code under test, never taken while it is right: not coverage.
find "$out" -name '*_sanitized-*.gc*' -delete
lcov -q "${rc_opts[@]}" --capture --directory "$out" --base-directory "$PWD" --output-file "$out/all.info" \
    2> "$out/lcov.err" || { cat "$out/lcov.err"; echo "0 passed, 1 failed" > "$result"; exit 1; }
lcov -q "${rc_opts[@]}" --extract "$out/all.info" "$PWD/bsched/*" "$PWD/kernel/*" "$PWD/drivers/*" \
    "$PWD/net/*" "$PWD/pdl/*" "$PWD/tools/*" --output-file "$out/tree.info" 2>/dev/null
# Test code itself is not what is measured.
lcov -q "${rc_opts[@]}" --remove "$out/tree.info" "*/tests/*" --output-file "$out/code.info" 2>/dev/null
genhtml -q "${rc_opts[@]}" --branch-coverage --output-directory "$out/html" "$out/code.info" > /dev/null 2>&1
printf '%-22s %18s %22s\n' part "lines" "branches"
figure() {  # figure NAME PATTERN...
    local name=$1; shift
    lcov -q "${rc_opts[@]}" --extract "$out/code.info" "$@" --output-file "$out/part.info" 2>/dev/null || return 1
    lcov "${rc_opts[@]}" --summary "$out/part.info" 2>&1 | awk -v n="$name" '
        /lines\.\.\.\.\.\./ { l = $2 " " $3 " " $4 " " $5 " " $6 }
        /branches\.\.\./   { b = $2 " " $3 " " $4 " " $5 " " $6 }
        END { if (l == "") exit 1; printf "%-22s %-28s %s\n", n, l, b }'
}
for part in "bsched/bsched.c:$PWD/bsched/bsched.c" "kernel/:$PWD/kernel/*" "drivers/:$PWD/drivers/*" \
            "net/:$PWD/net/*" "pdl/:$PWD/pdl/*"; do
    figure "${part%%:*}" "${part#*:}" || printf '%-22s (no host-tested code)\n' "${part%%:*}"
done
lcov -q "${rc_opts[@]}" --extract "$out/code.info" "$PWD/bsched/bsched.c" --output-file "$out/bsched.info" 2>/dev/null
full=$(lcov "${rc_opts[@]}" --summary "$out/bsched.info" 2>&1 | grep -cE '(lines|branches)\.+: 100\.0%')
if [ "$full" -eq 2 ]; then
    echo "ok: bsched/bsched.c 100 % of lines and branches"; pass=$((pass + 1))
else
    echo "FAILED: bsched/bsched.c is not fully covered; uncovered (line: branch counts):"
    awk -F'[:,]' '/^SF:/ { f = ($2 ~ /bsched\/bsched\.c$/) } f && /^BRDA:/ && ($5 == "-" || $5 == 0) { print "    line " $2 }' \
        "$out/bsched.info" | sort -u | head -20
    fail=$((fail + 1))
fi
echo "HTML report: $out/html/index.html"
echo "$pass passed, $fail failed" > "$result"
[ "$fail" -eq 0 ]
