# Shared helpers for ci/setup.d/*.sh (sourced, not run).

# Runs a command as root: directly when we are root, else through sudo.
as_root() {
    if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

# apt_install PKG...: installs the Debian packages that are not installed yet.
# 'apt-get update' runs at most once per ci/setup call, and only when something is missing.
apt_install() {
    local missing=() p
    for p in "$@"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q '^install ok installed$' || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "ci/setup: installing Debian packages: ${missing[*]}" >&2
    if [ -z "${BSCHED_APT_UPDATED:-}" ]; then
        as_root apt-get update -q >&2
        export BSCHED_APT_UPDATED=1
    fi
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
}
