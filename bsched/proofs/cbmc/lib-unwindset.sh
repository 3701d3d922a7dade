#!/usr/bin/env bash
# Prints the CBMC unwind set for the loops of bsched.c in a goto binary:
#   lib-unwindset.sh GOTO-INSTRUMENT BINARY.goto N P
# Loop ids (bsched_init.7, ...) change whenever bsched.c is restructured, so
# instead of hard-coding them each loop is bounded by what its header line
# iterates over (the loop header is read from the source line CBMC reports):
#   BSCHED_MAX_PV  priority classes           -> 32 iterations
#   minpv          classes minpv..maxpv <= P  -> P + 1
#   maxpv, bits, bit  priority values <= P    -> P (bit: the carry of the
#                  bit-reversed counter halves a bit below 2^maxpv each turn)
#   count, n, class_size, ran, slot  processes <= N -> N (slot: the walk over
#                  a class's members in order[])
# (CBMC's bound is iterations + 1.) A loop matching none of these stops the run
# with an error rather than getting a guessed bound; and --unwinding-assertions
# turns a bound that is too small into a failed property.
set -euo pipefail
goto_instrument=$1 binary=$2 n=$3 p=$4
set_entries=()
while read -r loop file line; do
    text=$(sed -n "${line}p" "$file")
    if [[ $text =~ BSCHED_MAX_PV ]]; then
        bound=33
    elif [[ $text =~ (^|[^A-Za-z0-9_])minpv([^A-Za-z0-9_]|$) ]]; then
        bound=$((p + 2))
    elif [[ $text =~ (^|[^A-Za-z0-9_])(maxpv|bits|bit)([^A-Za-z0-9_]|$) ]]; then
        bound=$((p + 1))
    elif [[ $text =~ (^|[^A-Za-z0-9_])(count|n|class_size|ran|slot)([^A-Za-z0-9_]|$) ]]; then
        bound=$((n + 1))
    else
        echo "lib-unwindset.sh: no bound rule for the loop $loop at $file:$line:" >&2
        echo "    $text" >&2
        exit 1
    fi
    set_entries+=("$loop:$bound")
done < <("$goto_instrument" --show-loops "$binary" | awk '
    /^Loop / { loop = $2; sub(/:$/, "", loop) }
    /^ +file / && $2 ~ /bsched\.c$/ { print loop, $2, $4 }')
[ ${#set_entries[@]} -gt 0 ] || { echo "lib-unwindset.sh: no loops of bsched.c found in $binary" >&2; exit 1; }
(IFS=,; echo "${set_entries[*]}")
