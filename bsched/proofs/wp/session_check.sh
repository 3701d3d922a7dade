#!/usr/bin/env bash
# session_check.sh SESSION_TSV OUT_DIR RESULT_FILE: the proof session does what make
# prove relies on, on period_of's one prover goal (typed_period_of_ensures_is_pow2):
# the session names a prover for it, and replaying the session proves it with that
# prover alone (WP's JSON report lists no other prover for the goal). Also that the
# goal times of a log (the session's seconds column) are read right.
# That a goal whose script fails is then raced was checked by hand, 2026-11-27: a
# script naming CVC5 for word_slot's x_split, which CVC5 did not prove within that
# run's 20 s backstop, cost those 20 s, then the race proved the goal with Z3. WP
# ignores a script's own step limit, so no cheap failing script is at hand here.
# Needs in the environment: WP_PROVERS, WP_STEPS, WP_STEPS_Z3, WP_TIMEOUT, WHY3CONFIG.
set -uo pipefail
session=${1:?usage: session_check.sh SESSION_TSV OUT_DIR RESULT_FILE}
out=${2:?}; result=${3:?}
: "${WP_PROVERS:?}" "${WP_STEPS:?}" "${WP_STEPS_Z3:?}" "${WP_TIMEOUT:?}" "${WHY3CONFIG:?}"
root=$(cd "$(dirname "$0")/../../.." && pwd)
goal=typed_period_of_ensures_is_pow2
pass=0; fail=0
ok() { pass=$((pass + 1)); echo "ok: $*"; }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
# replay: installs the session as make prove does and replays it on period_of;
# prints the goal's provers from the JSON report as 'prover=verdict ...'
replay() {
    python3 "$root/bsched/proofs/wp/wp_session.py" install "$session" "$out/replay" \
        --steps "$WP_STEPS" --steps-z3 "$WP_STEPS_Z3" --timeout "$WP_TIMEOUT" || return 1
    nice frama-c -cpp-extra-args="-I$root/bsched" -wp -wp-rte -wp-prover "script,$WP_PROVERS" \
        -wp-timeout "$WP_TIMEOUT" -wp-steps "$WP_STEPS" -wp-cache none -wp-session "$out/replay" \
        -wp-report-json "$out/replay.json" -wp-fct period_of "$root/bsched/bsched.c" > "$out/replay.log" 2>&1
    python3 - "$out/replay.json" "${goal#typed_}" <<'PY'
import json, sys
props = json.load(open(sys.argv[1]))["wp:functions"]["period_of"][sys.argv[2]]
print(" ".join("%s=%s" % (p, "valid" if c.get("valid") else "not-valid")
               for p, c in sorted(props.items()) if p != "wp:main"))
PY
}
mkdir -p "$out"
recorded=$(awk -F'\t' -v g="$goal" '$1 == g { print $2 }' "$session")
if [ -n "$recorded" ]; then ok "the session names $recorded for $goal"
else bad "the session names no prover for $goal"; fi

provers=$(replay)
if [ -n "$recorded" ] && [ "$provers" = "$recorded=valid" ]; then
    ok "replayed: proven by $recorded alone ($provers)"
else
    bad "replayed: expected $recorded=valid alone, got '${provers:-no report}' ($out/replay.log)"
fi

# The seconds column comes from the goal lines' times; a minute or more is printed
# as 1'14s, which was once read as the Qed time before it (0.89 s for 74 s).
# Python run from stdin has the working folder first on its path: wp_report.py's.
if (cd "$root/bsched/proofs/wp" && python3 -) <<'PY'
import sys
from wp_report import seconds
cases = {" : Valid (Qed:888ms) (1'14s) (1168630)": 74.0, " : Valid (Qed:678ms) (43.9s) (967767)": 43.9,
         " : Valid (380ms)": 0.38, " : Valid (1h2')": 3720.0, " : Valid (Qed:45ms)": 0.045}
wrong = {line: seconds(line) for line, want in cases.items() if abs(seconds(line) - want) > 1e-9}
if wrong:
    sys.exit("wrong: %r" % wrong)
PY
then ok "goal times read as Frama-C prints them (ms, s, minutes, hours)"
else bad "goal times misread (wp_report.seconds)"; fi

mkdir -p "$(dirname "$result")"
echo "$pass passed, $fail failed" > "$result"
echo "wp-session: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
