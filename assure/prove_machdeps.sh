#!/usr/bin/env bash
# prove_machdeps.sh BUILD MODEL...: the full WP run (make prove: same gate, same step
# limits) once per Frama-C machine model, each under the heavy lock, into BUILD/wp-MODEL/
# (log: BUILD/wp-MODEL.log). Prints and writes to BUILD/wp-machdeps.txt one line per
# model: goals, proven, WP's wall time (without the wait for the lock), verdict.
# Exits 1 when any model's run fails.
set -uo pipefail
build=${1:?usage: prove_machdeps.sh BUILD MODEL...}; shift
summary=$build/wp-machdeps.txt
: > "$summary"
rc=0
for model in "$@"; do
    out=$build/wp-$model
    echo "== WP, -machdep $model (log: $out.log)"
    rm -f "$out/report.json"
    flock /tmp/bsched-heavy.lock make --no-print-directory prove WP_OUT="$out" \
        WP_MACHDEP_FLAGS="-machdep $model" > "$out.log" 2>&1
    r=$?
    [ $r -eq 0 ] || { rc=1; tail -8 "$out.log"; }
    line=$(python3 - "$out/report.json" "$model" "$r" <<'PY' 2>/dev/null
import json, sys
report = json.load(open(sys.argv[1]))
goals = report["goals"]
proven = sum(g["status"] == "Valid" for g in goals)
print("%-7s %4d goals, %4d proven, WP %4.0f s, %s" % (
    sys.argv[2], len(goals), proven, report.get("wall_seconds") or 0,
    "PASS" if sys.argv[3] == "0" else "FAIL"))
PY
) || line="$model: no report (Frama-C did not finish; see $out.log), FAIL"
    echo "$line" | tee -a "$summary"
done
echo "== summary ($summary)"
cat "$summary"
exit $rc
