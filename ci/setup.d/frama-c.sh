# Frama-C WP with Why3 and the SMT solvers for `make prove` (bsched/proofs/wp/).
# The Why3 configuration (cvc5 with our driver, z3-qi) lives in $BSCHED_TOOLS,
# not in ~/.why3.conf; bsched/proofs/wp/why3-config.sh writes it (the
# standalone bundle of `make dist` runs the same script).
apt_install frama-c-base why3 z3 cvc4 cvc5
"$BSCHED_ROOT/bsched/proofs/wp/why3-config.sh" "$BSCHED_TOOLS/why3-v5"
