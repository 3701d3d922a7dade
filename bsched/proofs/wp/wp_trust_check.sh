#!/usr/bin/env bash
# wp_trust_check.sh OUT_DIR RESULT_FILE SOURCE...: suite wp-trust. What make check's
# proof (suite wp: make prove, then wp_goals.py check) cannot be talked into, shown on
# copies of the proof sources (SOURCE..., paths from the repository's root) in which
# only reverse_bits's contract is changed, each proved as make prove does, of
# reverse_bits alone:
#   1. forged: a false postcondition. Its prover results are recorded in a WP cache
#      (-wp-cache update) and forged to "valid"; an offline replay of that cache
#      (-wp-cache offline) then passes the false contract, so the forgery is real.
#      make prove on the copy, offered the forged cache through Frama-C's own
#      environment variables and a session whose line names a prover for the false
#      goal, still fails and names the goal.
#   2. deleted: a postcondition removed. make prove passes (fewer goals, all proven);
#      the record's check fails and names the goal that is gone.
#   3. weakened: a postcondition that claims less, still true. make prove passes;
#      the record's check fails and names bsched/bsched.c.
# Needs in the environment: WP_PROVERS, WP_STEPS, WP_STEPS_Z3, WHY3CONFIG.
set -uo pipefail
out=${1:?usage: wp_trust_check.sh OUT_DIR RESULT_FILE SOURCE...}
result=${2:?}; shift 2
sources=("$@")
[ ${#sources[@]} -gt 0 ] || { echo "wp_trust_check.sh: no sources named" >&2; exit 2; }
: "${WP_PROVERS:?}" "${WP_STEPS:?}" "${WP_STEPS_Z3:?}" "${WHY3CONFIG:?}"
root=$(cd "$(dirname "$0")/../../.." && pwd)
here=$root/bsched/proofs/wp
# The false goal has no proof, so each prover runs until its limit; a short wall-clock
# backstop bounds that (make prove's own, 600 s, would cost minutes): the verdict asked
# for, not proven, does not depend on which limit stops the prover.
timeout=20
goal=typed_reverse_bits_ensures_forged
pass=0; fail=0
ok() { pass=$((pass + 1)); echo "ok: $*"; }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
rm -rf "$out" && mkdir -p "$out"

# copy NAME [SED_EXPR]: the sources in $out/NAME, reverse_bits's contract edited by
# SED_EXPR if given (then fails unless the edit changed bsched.c).
copy() {
    local dir=$out/$1 src
    for src in "${sources[@]}"; do
        mkdir -p "$dir/$(dirname "$src")" && cp "$root/$src" "$dir/$src"
    done
    [ $# -lt 2 ] && return 0
    sed -i "$2" "$dir/bsched/bsched.c"
    ! cmp -s "$root/bsched/bsched.c" "$dir/bsched/bsched.c"
}
# prove NAME [VAR=VALUE...]: make prove of reverse_bits on the copy NAME with the copy's
# session if it has one, else the repository's (its log in $out/NAME.prove.log, its
# report in $out/NAME/wp/report.json); returns make's status.
prove() {
    local name=$1 session=$out/$1/session.tsv; shift
    [ -f "$session" ] || session=$here/session.tsv
    env "$@" make -C "$root" --no-print-directory prove WP_FILE="$out/$name/bsched/bsched.c" \
        WP_FCT=reverse_bits WP_MIN_GOALS=1 WP_TIMEOUT=$timeout WP_OUT="$out/$name/wp" \
        WP_SESSION_TSV="$session" > "$out/$name.prove.log" 2>&1
}
# record_check NAME: the record's check of the copy's run; its output in $out/NAME.check.log.
record_check() {
    python3 "$here/wp_goals.py" check "$out/$1/wp/report.json" "$here" --root "$out/$1" \
        --spec "${sources[@]}" --functions reverse_bits > "$out/$1.check.log" 2>&1
}
# frama NAME CACHE_MODE: WP of reverse_bits on the copy with the cache $out/cache;
# its log in $out/NAME.CACHE_MODE.log.
frama() {
    ( cd "$out/$1" && frama-c -cpp-extra-args="-I$out/$1/bsched" -wp -wp-rte -wp-prover "$WP_PROVERS" \
        -wp-timeout $timeout -wp-steps "$WP_STEPS" -wp-verbose 1 -wp-cache "$2" -wp-cache-dir "$out/cache" \
        -wp-fct reverse_bits bsched/bsched.c ) > "$out/$1.$2.log" 2>&1
}

# 1. forged
if ! copy forged 's/^\(    ensures below_period: \\result < pow2(bits);\)$/\1\n    ensures forged: \\result < 1;/'; then
    bad "forged: reverse_bits's postcondition was not found to edit"
else
    frama forged update
    # Every recorded result that is not a proof becomes one, as a forger would write it.
    forged=$(grep -L '"verdict": "valid"' "$out"/cache/*.json 2>/dev/null | wc -l)
    sed -i 's/"verdict": "[a-z]*", "time": [0-9.]*/"verdict": "valid", "time": 0.5, "steps": 1000/' "$out"/cache/*.json
    frama forged offline
    if grep -q "Goal $goal : Valid.*(cached)" "$out/forged.offline.log"; then
        ok "forged: $forged forged cache entries pass the false postcondition in an offline replay"
    else
        bad "forged: the forged cache did not pass the false goal in an offline replay (the test shows nothing):"
        grep "$goal" "$out/forged.offline.log"
    fi
    # A session that names a prover for the false goal, as if it had proved it.
    { grep '^#' "$here/session.tsv"; printf '%s\tCVC4:1.8\t0.10\n' "$goal"; } > "$out/forged/session.tsv"
    if prove forged FRAMAC_WP_CACHE=offline FRAMAC_WP_CACHEDIR="$out/cache"; then
        bad "forged: make prove passed the false postcondition with the forged cache beside it"
    elif grep -q "$goal" "$out/forged.prove.log" \
        && python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); sys.exit(not any(g["goal"]==sys.argv[2] and g["status"]!="Valid" for g in r["goals"]))' \
            "$out/forged/wp/report.json" "$goal"; then
        ok "forged: make prove fails the false postcondition and names it, the forged cache and session beside it"
    else
        bad "forged: make prove failed, but not on $goal:"; tail -20 "$out/forged.prove.log"
    fi
fi

# caught_by_record NAME SED_EXPR WHAT NAMED: a copy edited by SED_EXPR (WHAT: how the
# postcondition changed) that make prove proves, and whose record check must fail
# naming NAMED (a goal or a file).
caught_by_record() {
    local name=$1 edit=$2 what=$3 named=$4
    if ! copy "$name" "$edit"; then
        bad "$name: reverse_bits's postcondition was not found to change"
    elif ! prove "$name"; then
        bad "$name: make prove failed on the copy with a postcondition $what:"; tail -20 "$out/$name.prove.log"
    elif record_check "$name"; then
        bad "$name: the record's check passed with a postcondition $what"; cat "$out/$name.check.log"
    elif grep -q "$named" "$out/$name.check.log"; then
        ok "$name: make prove passes, the record's check fails and names $named"
    else
        bad "$name: the record's check failed without naming $named:"; cat "$out/$name.check.log"
    fi
}

# 2. deleted, 3. weakened
caught_by_record deleted '/^    ensures below_period: \\result < pow2(bits);$/d' deleted \
    typed_reverse_bits_ensures_below_period
caught_by_record weakened 's/^\(    ensures below_period: \\result\) < pow2(bits);$/\1 <= pow2(bits);/' weakened \
    "bsched/bsched.c: "

# And the unchanged sources pass the same check, so the three failures above are theirs.
copy same
if prove same && record_check same; then
    ok "unchanged: make prove and the record's check pass on an unchanged copy"
else
    bad "unchanged: an unchanged copy fails:"; tail -5 "$out/same.prove.log"; cat "$out/same.check.log"
fi

mkdir -p "$(dirname "$result")"
echo "$pass passed, $fail failed" > "$result"
echo "wp-trust: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
