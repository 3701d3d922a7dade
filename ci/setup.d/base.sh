# Host compiler, make, cmocka for unit tests, Python with the pinned test tools.
apt_install build-essential pkg-config libcmocka-dev python3 python3-venv
# One environment per requirements file content, $BSCHED_TOOLS/venvs/HASH, and a
# link to it per checkout, build/venv: checkouts side by side with different pins
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
mkdir -p "$(dirname "$venv_link")"
[ "$(readlink "$venv_link" 2>/dev/null)" = "$venv" ] || ln -sfn "$venv" "$venv_link"
