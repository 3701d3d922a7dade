#!/usr/bin/env bash
# wp_cache_check.sh CACHE_DIR OUT_DIR RESULT_FILE REPLAY_COMMAND: suite wp-replay.
#   1. REPLAY_COMMAND (make wp-replay-run) re-checks every goal from the committed cache
#      and passes: the cache covers the goals of the current code and spec.
#   2. The replay of reverse_bits alone, on a copy of bsched/ in another folder, passes
#      with the committed cache (the cache does not depend on where the tree is).
#   3. The same on a copy whose reverse_bits has a changed postcondition and a new
#      one fails, naming both goals and saying to run make prove: a stale cache is
#      noticed, never taken as a proof.
# Needs in the environment: WP_PROVERS, WP_STEPS, WP_TIMEOUT, WHY3CONFIG.
set -uo pipefail
cache=${1:?usage: wp_cache_check.sh CACHE_DIR OUT_DIR RESULT_FILE REPLAY_COMMAND}
out=${2:?}; result=${3:?}; replay=${4:?}
: "${WP_PROVERS:?}" "${WP_STEPS:?}" "${WP_TIMEOUT:?}" "${WHY3CONFIG:?}"
root=$(cd "$(dirname "$0")/../../.." && pwd)
here=$root/bsched/proofs/wp
pass=0; fail=0
ok() { pass=$((pass + 1)); echo "ok: $*"; }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
rm -rf "$out" && mkdir -p "$out"

start=$(date +%s)
if $replay > "$out/replay.log" 2>&1; then
    ok "make wp-replay: $(grep '^wp-replay: ' "$out/replay.log" | tail -1) ($(( $(date +%s) - start )) s)"
else
    bad "make wp-replay failed ($out/replay.log):"; tail -30 "$out/replay.log"
fi

# replay_copy NAME: WP on reverse_bits of the copy in $out/NAME (offline, committed cache),
# then the gate and wp_cache.py check --subset; prints their output, returns check's status.
replay_copy() {
    local dir=$out/$1
    ( cd "$dir" && frama-c -cpp-extra-args="-I$dir/bsched" -wp -wp-rte -wp-prover "$WP_PROVERS" \
        -wp-timeout "$WP_TIMEOUT" -wp-steps "$WP_STEPS" -wp-verbose 1 -wp-cache offline \
        -wp-cache-dir "$root/$cache/entries" -wp-fct reverse_bits -wp-report-json "$dir/wp.json" \
        bsched/bsched.c > "$dir/wp.log" 2>&1 ) || return 2
    python3 "$here/wp_report.py" "$dir/wp.log" "$dir/wp.json" "$dir/report.json" --min-goals 1 > "$dir/gate.log"
    python3 "$here/wp_cache.py" check "$dir/report.json" "$dir/wp.log" "$root/$cache" --subset
}
for copy in same changed; do
    mkdir -p "$out/$copy/bsched"
    cp -r "$root/bsched/bsched.c" "$root/bsched/bsched.h" "$root/bsched/spec" "$out/$copy/bsched/"
done
if replay_copy same > "$out/same.out" 2>&1; then
    ok "reverse_bits replayed from the cache in another folder: $(tail -1 "$out/same.out")"
else
    bad "reverse_bits of an unchanged copy not replayed from the cache:"; cat "$out/same.out"
fi

# A changed postcondition (its goal's task changes) and a new one (a goal the cache's
# proof never had; Qed may prove it, the goal list still differs).
sed -i 's/^\(    ensures reversal: \\result == fig6_map(bits, x)\);$/\1 \&\& \\result >= 0;\n    ensures added_goal: \\result <= \\result;/' \
    "$out/changed/bsched/bsched.c"
if ! grep -q 'added_goal' "$out/changed/bsched/bsched.c"; then
    bad "the postcondition of reverse_bits was not found to change"
else
    replay_copy changed > "$out/changed.out" 2>&1; rc=$?
    if [ $rc -eq 1 ] && grep -q 'typed_reverse_bits_ensures_reversal' "$out/changed.out" \
        && grep -q 'typed_reverse_bits_ensures_added_goal' "$out/changed.out" \
        && grep -q 'run make prove' "$out/changed.out"; then
        ok "a changed and a new goal fail the replay, named, with the advice to run make prove"
    else
        bad "a stale cache was not reported (status $rc):"; cat "$out/changed.out"
    fi
fi

mkdir -p "$(dirname "$result")"
echo "$pass passed, $fail failed" > "$result"
echo "wp-replay: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
