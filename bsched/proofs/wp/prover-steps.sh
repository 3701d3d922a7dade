#!/usr/bin/env bash
# prover-steps.sh VAR SCALE STEPS PROGRAM ARG...: runs PROGRAM with "@STEPS@" in its
# arguments replaced by the step limit for this prover: the value of the environment
# variable VAR if set (wp.mk exports it), else STEPS x SCALE.
# Why3 1.5.1 gives every prover the same step limit (-wp-steps, %S in command_steps),
# but the provers count in different units: Z3's rlimit units are ~13x cheaper than
# cvc4's and cvc5's resource units (make wp-calibrate). One limit for all would give
# cvc4 and cvc5 a far larger allowance than they need, and every goal they cannot
# prove (a mutant, the negative check) would cost minutes. why3-config.sh routes Z3's
# command_steps through this script, so Z3 gets its own limit.
set -euo pipefail
var=$1 scale=$2 steps=$3
shift 3
limit=${!var:-$((steps * scale))}
args=()
for a in "$@"; do args+=("${a//@STEPS@/$limit}"); done
exec "${args[@]}"
