# Frama-C WP with Why3 and the SMT solvers for `make prove` (bsched/proofs/wp/).
# Why3 1.5.1 predates cvc5, so cvc5 is registered by hand with our driver
# (bsched/proofs/wp/cvc5.drv). The Why3 configuration lives in $BSCHED_TOOLS,
# not in ~/.why3.conf; wp.mk points both why3 and Frama-C at it (WHY3CONFIG).
# A second Z3 entry, z3-qi (alternative "qi"), lowers Z3's eager quantifier
# instantiation threshold: WP states recursive logic definitions as
# quantified equations, and with the default threshold Z3 keeps unfolding them
# (class_count(n) -> class_count(n-1) -> ...) until it runs out of memory.
apt_install frama-c-base why3 z3 cvc4 cvc5
why3_dir="$BSCHED_TOOLS/why3"
why3_conf="$why3_dir/why3.conf"
# The driver is copied next to the configuration, so that checkouts in other
# folders (a clean clone, CI) share one configuration without re-detecting.
cvc5_driver="$why3_dir/cvc5.drv"
# The stamp names the driver's content and the solver versions: a changed driver
# or an upgraded solver re-runs the detection, anything else returns at once.
want="v4 $(sha256sum < "$BSCHED_ROOT/bsched/proofs/wp/cvc5.drv" | cut -c1-16) $(dpkg-query -W -f='${Version} ' why3 z3 cvc4 cvc5 2>/dev/null)"
if [ ! -f "$why3_conf" ] || [ "$(cat "$why3_dir/stamp" 2>/dev/null)" != "$want" ]; then
    echo "ci/setup: why3 config detect -> $why3_conf" >&2
    mkdir -p "$why3_dir"
    rm -f "$why3_conf"
    cp "$BSCHED_ROOT/bsched/proofs/wp/cvc5.drv" "$cvc5_driver"
    WHY3CONFIG="$why3_conf" why3 config detect >&2
    # Why3 turns a solver that exceeds its memory limit (default 1000 MB) into a
    # failure, and WP then stops trying the next prover on that goal. 4000 MB is
    # never reached within the per-goal timeout, so a slow prover times out and
    # the next one gets its turn.
    sed -i 's/^memlimit = .*/memlimit = 4000/' "$why3_conf"
    cvc5_version=$(cvc5 --version | sed -n 's/^This is cvc5 version \([^ ]*\).*/\1/p' | head -1)
    cat >> "$why3_conf" <<CONF

[prover]
name = "CVC5"
version = "$cvc5_version"
alternative = ""
command = "/usr/bin/cvc5 --stats --tlimit=%t000 --lang=smt2 %f"
command_steps = "/usr/bin/cvc5 --stats --rlimit=%S --lang=smt2 %f"
driver = "$cvc5_driver"
editor = ""
in_place = false
interactive = false
shortcut = "cvc5"
CONF
    z3_version=$(z3 -version | sed -n 's/^Z3 version \([^ ]*\).*/\1/p' | head -1)
    cat >> "$why3_conf" <<CONF

[prover]
name = "Z3"
version = "$z3_version"
alternative = "qi"
command = "/usr/bin/z3 -smt2 -T:%t sat.random_seed=42 nlsat.randomize=false smt.random_seed=42 smt.qi.eager_threshold=5 -st %f"
command_steps = "/usr/bin/z3 -smt2 sat.random_seed=42 nlsat.randomize=false smt.random_seed=42 smt.qi.eager_threshold=5 -st rlimit=%S %f"
driver = "z3_471"
editor = ""
in_place = false
interactive = false
shortcut = "z3-qi"
CONF
    echo "$want" > "$why3_dir/stamp"
fi
