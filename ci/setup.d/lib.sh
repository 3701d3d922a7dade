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

# fetch_debian_source PACKAGE DIR: downloads bookworm's source package PACKAGE
# (its .dsc, orig and debian tarballs) into DIR, through a private apt
# configuration (its own sources list with deb-src entries, lists and cache
# under DIR/../apt-src): the system's apt sources stay untouched.
fetch_debian_source() {
    local package=$1 dir=$2 apt_dir
    apt_dir=$(dirname "$dir")/apt-src
    mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial"
    cat > "$apt_dir/sources.list" <<'SRC'
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian bookworm main
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian-security bookworm-security main
SRC
    local apt_opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list" -o Dir::Etc::SourceParts=/nonexistent
                    -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache"
                    -o APT::Sandbox::User=root -q)
    apt-get "${apt_opts[@]}" update >&2
    rm -rf "$dir" && mkdir -p "$dir"
    (cd "$dir" && apt-get "${apt_opts[@]}" source --download-only "$package" >&2)
}
