# Host compiler, make, cmocka for unit tests, Python with the pinned test tools;
# cmake and pkg-config for the consumers of bsched's package (suite bsched-package).
apt_install build-essential cmake pkg-config libcmocka-dev python3 python3-venv
# One environment per requirements file content, $BSCHED_TOOLS/venvs/HASH, shared
# by the checkouts with the same pins: checkouts side by side with different pins
# never replace each other's environment under a running test.
req="$BSCHED_ROOT/ci/requirements.txt"
want=$(sha256sum "$req" | cut -c1-16)
venv="$BSCHED_TOOLS/venvs/$want"
venv_link="$BSCHED_ROOT/build/venv"
if [ ! -x "$venv/bin/python" ] || [ ! -f "$venv/.complete" ]; then
    mkdir -p "$BSCHED_TOOLS/venvs"
    exec 8>"$BSCHED_TOOLS/venvs/.lock"
    flock 8
    if [ ! -f "$venv/.complete" ]; then
        echo "ci/setup: creating Python environment in $venv" >&2
        rm -rf "$venv"
        # Debian's own python3, so a fresh bookworm machine needs nothing else.
        py=/usr/bin/python3; [ -x "$py" ] || py=python3
        "$py" -m venv "$venv"
        "$venv/bin/pip" install -q --disable-pip-version-check -r "$req" >&2
        touch "$venv/.complete"
    fi
    exec 8>&-
    # Keep the 4 newest environments.
    ls -1dt "$BSCHED_TOOLS"/venvs/*/ 2>/dev/null | tail -n +5 | xargs -r rm -rf
fi
rm -rf "$BSCHED_TOOLS/venv"   # the single environment of before
# build/venv is the checkout's own environment: an empty venv whose path file
# (site-packages/bsched.pth) adds the shared environment's packages and this
# checkout's Python packages, robocube_emu (emu/python) and netpeer (tools),
# so each checkout imports its own code and no script edits sys.path. The
# shared environment's commands (pytest, cbmc-viewer) are linked into its bin/.
[ -L "$venv_link" ] && rm -f "$venv_link"      # a link to the shared one, before
if [ ! -x "$venv_link/bin/python" ]; then
    rm -rf "$venv_link"
    mkdir -p "$(dirname "$venv_link")"
    "$(readlink -f "$venv/bin/python")" -m venv --without-pip "$venv_link"
fi
site=$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_path("purelib"))')
own_site=$("$venv_link/bin/python" -c 'import sysconfig; print(sysconfig.get_path("purelib"))')
pth="import site; site.addsitedir('$site')
$BSCHED_ROOT/emu/python
$BSCHED_ROOT/tools"
[ "$(cat "$own_site/bsched.pth" 2>/dev/null)" = "$pth" ] || printf '%s\n' "$pth" > "$own_site/bsched.pth"
for cmd in "$venv"/bin/*; do
    name=${cmd##*/}
    case $name in python*|activate*|Activate*|pip*) continue ;; esac
    [ "$(readlink "$venv_link/bin/$name" 2>/dev/null)" = "$cmd" ] || ln -sfn "$cmd" "$venv_link/bin/$name"
done
