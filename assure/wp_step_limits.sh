#!/usr/bin/env bash
# wp_step_limits.sh RESULT_FILE: every prover of make prove honours -wp-steps and says
# so. For each prover in WP_PROVERS, WP proves period_of's one prover goal
# (typed_period_of_ensures_is_pow2) twice:
#   - with -wp-steps 1: the goal must be reported as cut by the step limit
#     ("Step limit"), not as Unknown or Timeout (a verdict that names the limit is
#     what tells a too-small WP_STEPS from a wrong proof);
#   - with make prove's limits (WP_STEPS, WP_STEPS_Z3): the goal must be proven, with
#     its step count read from the prover's output (make wp-calibrate needs the counts).
# Z3 takes its limit from WP_STEPS_Z3 (prover-steps.sh), set to the same 1 in the first run.
# Needs in the environment: WP_PROVERS, WP_STEPS, WP_STEPS_Z3, WHY3CONFIG.
set -uo pipefail
result=${1:?usage: wp_step_limits.sh RESULT_FILE}
: "${WP_PROVERS:?}" "${WP_STEPS:?}" "${WP_STEPS_Z3:?}" "${WHY3CONFIG:?}"
root=$(cd "$(dirname "$0")/.." && pwd)
goal=typed_period_of_ensures_is_pow2
pass=0; fail=0
run() {  # run PROVER STEPS STEPS_Z3: prints the goal's log line
    WP_STEPS_Z3=$3 nice frama-c -cpp-extra-args="-I$root/bsched" -wp -wp-rte -wp-prover "$1" -wp-timeout 60 \
        -wp-steps "$2" -wp-verbose 1 -wp-cache none -wp-fct period_of "$root/bsched/bsched.c" 2>&1 |
        grep -E "Goal $goal( |$)|^  [A-Z][^:]*[0-9]: " | head -2
}
for prover in ${WP_PROVERS//,/ }; do
    line=$(run "$prover" 1 1)
    if echo "$line" | grep -q ": Step limit"; then
        pass=$((pass + 1)); echo "ok: $prover, -wp-steps 1: $line"
    else
        fail=$((fail + 1)); echo "FAILED: $prover, -wp-steps 1: the goal is not reported as cut by steps: ${line:-no line}"
    fi
    line=$(run "$prover" "$WP_STEPS" "$WP_STEPS_Z3")
    if echo "$line" | grep -qE ": Valid .*\([0-9]+\)$"; then
        pass=$((pass + 1)); echo "ok: $prover, make prove's limits: $line"
    else
        fail=$((fail + 1)); echo "FAILED: $prover, make prove's limits: not proven with a step count: ${line:-no line}"
    fi
done
mkdir -p "$(dirname "$result")"
echo "$pass passed, $fail failed" > "$result"
echo "wp-step-limits: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
