# Host compiler, make, cmocka for unit tests, Python with the pinned test tools.
apt_install build-essential pkg-config libcmocka-dev python3 python3-venv
venv="$BSCHED_TOOLS/venv"
req="$BSCHED_ROOT/ci/requirements.txt"
stamp="$venv/.requirements.sha256"
want=$(sha256sum "$req" | cut -d' ' -f1)
if [ ! -x "$venv/bin/python" ] || [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
    echo "ci/setup: creating Python environment in $venv" >&2
    rm -rf "$venv"
    # Debian's own python3, so a fresh bookworm machine needs nothing else.
    py=/usr/bin/python3; [ -x "$py" ] || py=python3
    "$py" -m venv "$venv"
    "$venv/bin/pip" install -q --disable-pip-version-check -r "$req" >&2
    echo "$want" > "$stamp"
fi
