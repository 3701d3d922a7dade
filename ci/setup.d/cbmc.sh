# CBMC 6 (bounded model checker for C) for bsched/proofs/cbmc.
# Bookworm has no cbmc package, so we take Debian trixie's cbmc together with the
# trixie C/C++ runtime it was linked against, unpack the .debs with dpkg -x into
# $BSCHED_TOOLS/cbmc/root and start cbmc through that tree's own dynamic loader.
# The system libc and the system apt state are never touched: apt runs with a
# private sources list, state and cache under $BSCHED_TOOLS/cbmc/apt.
cbmc_dir="$BSCHED_TOOLS/cbmc"
# kissat: the external SAT solver of the balance and step harnesses (Makefile.common).
cbmc_pkgs="cbmc libc6 libstdc++6 libgcc-s1 minisat kissat"
cbmc_stamp="$cbmc_dir/.installed"
if [ -x "$cbmc_dir/bin/cbmc" ] && [ -x "$cbmc_dir/bin/goto-cc" ] && [ -x "$cbmc_dir/bin/kissat" ] && \
   [ "$(cat "$cbmc_stamp" 2>/dev/null)" = "$cbmc_pkgs" ]; then
    return 0
fi

echo "ci/setup: installing CBMC from Debian trixie into $cbmc_dir" >&2
apt_dir="$cbmc_dir/apt"
rm -rf "$cbmc_dir/root" "$cbmc_dir/bin" "$cbmc_dir/debs"
mkdir -p "$apt_dir/state/lists/partial" "$apt_dir/cache/archives/partial" \
         "$apt_dir/sources.list.d" "$apt_dir/preferences.d" \
         "$cbmc_dir/debs" "$cbmc_dir/root" "$cbmc_dir/bin"
cat > "$apt_dir/sources.list" <<'EOF'
deb [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian trixie main
EOF
: > "$apt_dir/state/status"
# Every directory apt reads or writes is private: the system's sources, package
# lists, dpkg status and archive cache stay as they are.
cbmc_apt=(-o "Dir::Etc::sourcelist=$apt_dir/sources.list"
          -o "Dir::Etc::sourceparts=$apt_dir/sources.list.d"
          -o "Dir::Etc::preferencesparts=$apt_dir/preferences.d"
          -o "Dir::State=$apt_dir/state"
          -o "Dir::State::status=$apt_dir/state/status"
          -o "Dir::Cache=$apt_dir/cache"
          -o "APT::Architecture=amd64"
          -o "Debug::NoLocking=1"
          -o "APT::Sandbox::User=root")
apt-get -q "${cbmc_apt[@]}" update >&2
( cd "$cbmc_dir/debs" && apt-get -q "${cbmc_apt[@]}" download $cbmc_pkgs >&2 )
for deb in "$cbmc_dir"/debs/*.deb; do
    dpkg -x "$deb" "$cbmc_dir/root"
done

# The loader and library directories of the unpacked tree (usrmerge: lib64 -> usr/lib64).
loader=""
for cand in "$cbmc_dir/root/usr/lib64/ld-linux-x86-64.so.2" "$cbmc_dir/root/lib64/ld-linux-x86-64.so.2" \
            "$cbmc_dir/root/usr/lib/x86_64-linux-gnu/ld-linux-x86-64.so.2" \
            "$cbmc_dir/root/lib/x86_64-linux-gnu/ld-linux-x86-64.so.2"; do
    if [ -e "$cand" ]; then loader=$cand; break; fi
done
if [ -z "$loader" ]; then
    echo "ci/setup: cbmc: no ld-linux-x86-64.so.2 in the unpacked trixie libc6" >&2
    exit 1
fi
# minisat puts libminisat.so.2 in usr/lib, the runtime libraries are in the multiarch dir.
libpath="$cbmc_dir/root/usr/lib/x86_64-linux-gnu:$cbmc_dir/root/usr/lib"
for tool in cbmc goto-cc goto-instrument goto-analyzer kissat; do
    [ -x "$cbmc_dir/root/usr/bin/$tool" ] || continue
    # The library path is given to the loader for this process only (no LD_LIBRARY_PATH),
    # so programs cbmc starts (the host preprocessor) keep using the system libc.
    cat > "$cbmc_dir/bin/$tool" <<EOF
#!/bin/sh
# $tool from Debian trixie, run with trixie's own loader and libraries ($cbmc_dir/root).
exec "$loader" --library-path "$libpath" "$cbmc_dir/root/usr/bin/$tool" "\$@"
EOF
    chmod +x "$cbmc_dir/bin/$tool"
done
version=$("$cbmc_dir/bin/cbmc" --version)
case "$version" in
    6.*) echo "ci/setup: cbmc $version installed" >&2 ;;
    *) echo "ci/setup: cbmc: expected version 6.x, got '$version'" >&2; exit 1 ;;
esac
if ! "$cbmc_dir/bin/kissat" --version >/dev/null 2>&1; then
    echo "ci/setup: cbmc: kissat does not start" >&2; exit 1
fi
echo "$cbmc_pkgs" > "$cbmc_stamp"
