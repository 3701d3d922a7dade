#!/usr/bin/env bash
# HTML reports of finished CBMC runs with cbmc-viewer (PyPI, pinned in
# ci/requirements.txt):  report.sh TOOLS-DIR SOURCE-ROOT RUN-DIR...
# Each RUN-DIR (build/cbmc/<run>/) needs harness.goto, cbmc.log and command.txt
# from a `make` of its harness; the report goes to RUN-DIR/html/html/index.html.
# Nothing is re-checked: the property list comes from `cbmc --show-properties`
# with the run's own flags, the results and traces from its cbmc.log (text).
set -euo pipefail
tools=$1 srcdir=$2; shift 2
bin="$tools/cbmc/bin"
viewer=${CBMC_VIEWER:-$srcdir/build/venv/bin/cbmc-viewer}
[ -x "$viewer" ] || { echo "report.sh: no cbmc-viewer at $viewer: run ci/setup base" >&2; exit 2; }
status=0
for dir in "$@"; do
    run=$(basename "$dir")
    if [ ! -f "$dir/harness.goto" ] || [ ! -f "$dir/cbmc.log" ] || [ ! -f "$dir/command.txt" ]; then
        echo "cbmc-report: $run: no finished run, skipped" >&2
        continue
    fi
    rm -rf "$dir/html" "$dir/viewer"
    mkdir -p "$dir/viewer"
    # cbmc-viewer's reachability analysis (goto-analyzer) needs an entry point in
    # the binary; the runs use cbmc --function harness instead.
    "$bin/goto-cc" --function harness -o "$dir/viewer/entry.goto" "$dir/harness.goto"
    # The run's flags without the program, the solver and --trace.
    read -r -a words < "$dir/command.txt"
    flags=()
    skip=0
    for ((i = 1; i < ${#words[@]} - 1; i++)); do
        w=${words[i]}
        if [ $skip -eq 1 ]; then skip=0; continue; fi
        case "$w" in
            --trace) ;;
            --external-sat-solver|--sat-solver) skip=1 ;;
            *) flags+=("$w") ;;
        esac
    done
    "$bin/cbmc" --show-properties --xml-ui "${flags[@]}" "$dir/harness.goto" > "$dir/viewer/property.xml" 2>/dev/null
    if PATH="$bin:$PATH" "$viewer" --result "$dir/cbmc.log" --property "$dir/viewer/property.xml" \
            --goto "$dir/viewer/entry.goto" --srcdir "$srcdir" --reportdir "$dir/html" \
            > "$dir/viewer/viewer.log" 2>&1; then
        echo "cbmc-report: $run: $dir/html/html/index.html"
    else
        echo "cbmc-report: $run: cbmc-viewer failed, see $dir/viewer/viewer.log" >&2
        status=1
    fi
done
exit $status
