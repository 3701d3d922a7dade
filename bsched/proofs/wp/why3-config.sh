#!/usr/bin/env bash
# why3-config.sh WHY3_DIR: writes WHY3_DIR/why3.conf for `make prove` (wp.mk
# points Frama-C and why3 at it with WHY3CONFIG), once per driver and solver
# versions. Used by ci/setup frama-c and by the standalone bundle (make dist).
# Needs why3, z3, cvc4 and cvc5 (Debian: frama-c-base why3 z3 cvc4 cvc5).
# Why3 1.5.1 predates cvc5, so cvc5 is registered by hand with our driver
# (cvc5.drv, beside this script). A second Z3 entry, z3-qi (alternative "qi"),
# lowers Z3's eager quantifier instantiation threshold: WP states recursive
# logic definitions as quantified equations, and with the default threshold Z3
# keeps unfolding them (class_count(n) -> class_count(n-1) -> ...) until it runs
# out of memory.
# Step limits (make prove passes -wp-steps): each entry has a command_steps line,
# and both drivers here make Why3 report a goal cut by its step limit as such
# ("Step limit" in WP, not Unknown) and read the steps each proof used:
# cvc5.drv (cvc5 prints resourceUnitsUsed only with --stats-internal) and
# z3-qi.drv (Z3 answers only "unknown" at its rlimit unless asked the reason).
# CVC4 needs nothing: Why3's own cvc4 driver and command do both. Z3 counts in
# smaller units than cvc4/cvc5 and gets its own limit, WP_STEPS_Z3 (prover-steps.sh).
# WHY3_DIR's name carries the configuration's version (wp.mk: WHY3CONFIG), so
# that checkouts of different versions sharing $BSCHED_TOOLS do not rewrite each
# other's configuration.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
why3_dir=${1:?usage: why3-config.sh WHY3_DIR}
why3_conf="$why3_dir/why3.conf"
for tool in why3 z3 cvc4 cvc5; do
    command -v "$tool" > /dev/null || {
        echo "why3-config.sh: '$tool' not found (Debian: apt-get install frama-c-base why3 z3 cvc4 cvc5)" >&2
        exit 2
    }
done
# The driver is copied next to the configuration, so that checkouts in other
# folders (a clean clone, CI) share one configuration without re-detecting.
cvc5_driver="$why3_dir/cvc5.drv"
z3_driver="$why3_dir/z3-qi.drv"
prover_steps="$why3_dir/prover-steps.sh"
# The stamp names the driver's content and the solver versions: a changed driver
# or an upgraded solver re-runs the detection, anything else returns at once.
# (Package versions from dpkg where there is one; elsewhere the stamp names the
# driver only, and a solver upgrade needs rm WHY3_DIR/stamp.)
want="v5 $(cat "$here/cvc5.drv" "$here/z3-qi.drv" "$here/prover-steps.sh" | sha256sum | cut -c1-16) $(dpkg-query -W -f='${Version} ' why3 z3 cvc4 cvc5 2>/dev/null || true)"
if [ ! -f "$why3_conf" ] || [ "$(cat "$why3_dir/stamp" 2>/dev/null)" != "$want" ]; then
    echo "why3-config.sh: why3 config detect -> $why3_conf" >&2
    mkdir -p "$why3_dir"
    rm -f "$why3_conf"
    cp "$here/cvc5.drv" "$cvc5_driver"
    cp "$here/z3-qi.drv" "$z3_driver"
    cp "$here/prover-steps.sh" "$prover_steps"
    WHY3CONFIG="$why3_conf" why3 config detect >&2
    # Why3 turns a solver that exceeds its memory limit (default 1000 MB) into a
    # failure, and WP then stops trying the next prover on that goal. 4000 MB is
    # never reached within the per-goal timeout, so a slow prover times out and
    # the next one gets its turn.
    sed -i 's/^memlimit = .*/memlimit = 4000/' "$why3_conf"
    cvc5=$(command -v cvc5)
    z3=$(command -v z3)
    cvc5_version=$(cvc5 --version | sed -n 's/^This is cvc5 version \([^ ]*\).*/\1/p' | head -1)
    cat >> "$why3_conf" <<CONF

[prover]
name = "CVC5"
version = "$cvc5_version"
alternative = ""
command = "$cvc5 --stats --tlimit=%t000 --lang=smt2 %f"
command_steps = "$cvc5 --stats --stats-internal --rlimit=%S --lang=smt2 %f"
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
command = "$z3 -smt2 -T:%t sat.random_seed=42 nlsat.randomize=false smt.random_seed=42 smt.qi.eager_threshold=5 -st %f"
command_steps = "$prover_steps WP_STEPS_Z3 16 %S $z3 -smt2 sat.random_seed=42 nlsat.randomize=false smt.random_seed=42 smt.qi.eager_threshold=5 -st rlimit=@STEPS@ %f"
driver = "$z3_driver"
editor = ""
in_place = false
interactive = false
shortcut = "z3-qi"
CONF
    echo "$want" > "$why3_dir/stamp"
fi
