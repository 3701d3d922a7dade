#!/usr/bin/env bash
# Static analysis of every host build (make all: the libraries, bsched-plan and
# every host test of every part), each into its own BUILD tree:
#   gcc -fanalyzer          (GCC 12's interprocedural analyzer)
#   clang scan-build        (the Clang Static Analyzer, default checkers)
# Findings in the GATE paths fail the suite; the others are listed and counted.
#   assure/analyze.sh OUT "HOST_CFLAGS" "GATE PATHS" RESULT-FILE
set -uo pipefail
cd "$(dirname "$0")/.."
out=$1; cflags=$2; gate=$3; result=$4
cflags=$(echo " $cflags " | sed 's/ -Werror / /g')   # findings are collected, not fatal
rm -rf "$out"; mkdir -p "$out" "$(dirname "$result")"
for b in gcc clang; do mkdir -p "$out/$b"; [ -e build/venv ] && ln -sfn "$(readlink -f build/venv)" "$out/$b/venv"; done
pass=0; fail=0

# gcc -fanalyzer
make --no-print-directory -k BUILD="$out/gcc" HOST_CFLAGS="$cflags -fanalyzer" all > "$out/gcc.log" 2>&1
gcc_rc=$?
grep -E 'warning: .*\[-Wanalyzer-' "$out/gcc.log" | sed "s|^$PWD/||" | sort -u > "$out/gcc-findings.txt"
# clang: scan-build puts its ccc-analyzer in $CC; the build uses HOST_CC.
scan-build -o "$out/scan-build" make --no-print-directory -k BUILD="$out/clang" \
    HOST_CC='$(CC)' HOST_CFLAGS="$cflags" all > "$out/clang.log" 2>&1
clang_rc=$?
grep -E 'warning: .*\[(core|unix|deadcode|security|nullability|optin|alpha|apiModeling)\.' "$out/clang.log" \
    | sed "s|^$PWD/||" | sort -u > "$out/clang-findings.txt"
# Judged false positives (assure/analyze-suppressions.txt: file | checker | reason).
suppress() {  # suppress FINDINGS-FILE: drops the suppressed lines, prints them
    local f=$1 file checker reason
    while IFS='|' read -r file checker reason; do
        file=$(echo $file); checker=$(echo $checker)
        case "$file" in ''|'#'*) continue ;; esac
        grep -F "$file:" "$f" | grep -F "[$checker]" | sed 's/^/    suppressed (false positive, see analyze-suppressions.txt): /'
        grep -vF "[$checker]" "$f" > "$f.keep"; grep -F "[$checker]" "$f" | grep -vF "$file:" >> "$f.keep" || true
        mv "$f.keep" "$f"
    done < assure/analyze-suppressions.txt
}
for tool in gcc clang; do
    suppress "$out/$tool-findings.txt"
    rcvar=${tool}_rc
    if [ "${!rcvar}" -ne 0 ]; then
        echo "FAILED: the $tool build did not complete (log $out/$tool.log)"; tail -5 "$out/$tool.log"
        fail=$((fail + 1)); continue
    fi
    total=$(wc -l < "$out/$tool-findings.txt")
    gated=0
    for g in $gate; do
        n=$(grep -c "^$g" "$out/$tool-findings.txt"); gated=$((gated + n))
    done
    echo "== $tool: $total findings ($gated in $gate)"
    sed 's/^/    /' "$out/$tool-findings.txt" | head -40
    for part in bsched kernel boards drivers net pdl tools apps; do
        n=$(grep -c "^$part/" "$out/$tool-findings.txt")
        [ "$n" -gt 0 ] && echo "    $part/: $n"
    done
    if [ "$gated" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); fi
done
built=$(grep -cE '(^| )(cc|gcc|clang|\S*ccc-analyzer) .* -o ' "$out/gcc.log")
echo "analyzed: every target of make all ($built compiler runs); reports: $out/scan-build"
echo "$pass passed, $fail failed" > "$result"
[ "$fail" -eq 0 ]
