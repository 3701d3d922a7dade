#!/usr/bin/env bash
# setup.sh COMPONENT...: what `make prove` and `make cbmc` of the bundle need.
# Installs nothing: checks that the tools are there (naming the Debian packages
# when not) and writes the Why3 configuration the WP job uses into
# $BSCHED_TOOLS/why3-v5 (bsched/proofs/wp/why3-config.sh).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
export BSCHED_TOOLS=${BSCHED_TOOLS:-${XDG_CACHE_HOME:-$HOME/.cache}/bsched}
for component in "$@"; do
    case $component in
        frama-c)
            command -v frama-c > /dev/null || {
                echo "setup.sh: frama-c not found (Debian: apt-get install frama-c-base why3 z3 cvc4 cvc5)" >&2
                exit 2
            }
            "$here/bsched/proofs/wp/why3-config.sh" "$BSCHED_TOOLS/why3-v5"
            ;;
        cbmc)
            [ -x "$BSCHED_TOOLS/cbmc/bin/cbmc" ] || command -v cbmc > /dev/null || {
                echo "setup.sh: cbmc not found (Debian trixie: apt-get install cbmc kissat; or the bsched repository's ci/setup cbmc)" >&2
                exit 2
            }
            ;;
        base | m68k) ;;
        *) echo "setup.sh: unknown component '$component'" >&2; exit 2 ;;
    esac
done
