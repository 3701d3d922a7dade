# Assurance tools (ASSURANCE.md): static analysis, cross compilers for the
# portability matrix, coverage, and a big-endian target for the unit tests.
#   cppcheck (MISRA C:2012 addon), clang + scan-build, lcov (make coverage),
#   gcc-arm-none-eabi (Cortex-M0/M4), gcc-riscv64-unknown-elf (rv32imac),
#   gcc-avr (16-bit int), gcc-s390x-linux-gnu + qemu-user (big-endian unit tests).
apt_install cppcheck clang clang-tools lcov gcc-arm-none-eabi gcc-riscv64-unknown-elf \
            gcc-avr avr-libc gcc-s390x-linux-gnu libc6-dev-s390x-cross qemu-user

# cmocka for s390x: Debian's own libcmocka built for s390x, unpacked with dpkg -x
# into $BSCHED_TOOLS/s390x/root through a private apt configuration (the system's
# dpkg architectures, sources and package state stay untouched), so the big-endian
# run uses the same cmocka as the host tests, not a hand-written substitute.
s390x_dir="$BSCHED_TOOLS/s390x"
s390x_pkgs="libcmocka0 libcmocka-dev"
if [ -f "$s390x_dir/root/usr/include/cmocka.h" ] && \
   [ "$(cat "$s390x_dir/.installed" 2>/dev/null)" = "$s390x_pkgs" ]; then
    return 0
fi
echo "ci/setup: fetching cmocka for s390x into $s390x_dir" >&2
apt_dir="$s390x_dir/apt"
rm -rf "$s390x_dir/root" "$s390x_dir/debs"
mkdir -p "$apt_dir/state/lists/partial" "$apt_dir/cache/archives/partial" \
         "$apt_dir/sources.list.d" "$apt_dir/preferences.d" "$s390x_dir/debs" "$s390x_dir/root"
cat > "$apt_dir/sources.list" <<'SRC'
deb [arch=s390x signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian bookworm main
SRC
: > "$apt_dir/state/status"
s390x_apt=(-o "Dir::Etc::sourcelist=$apt_dir/sources.list"
           -o "Dir::Etc::sourceparts=$apt_dir/sources.list.d"
           -o "Dir::Etc::preferencesparts=$apt_dir/preferences.d"
           -o "Dir::State=$apt_dir/state"
           -o "Dir::State::status=$apt_dir/state/status"
           -o "Dir::Cache=$apt_dir/cache"
           -o "APT::Architecture=s390x"
           -o "APT::Architectures::=s390x"
           -o "Debug::NoLocking=1"
           -o "APT::Sandbox::User=root")
apt-get -q "${s390x_apt[@]}" update >&2
( cd "$s390x_dir/debs" && apt-get -q "${s390x_apt[@]}" download $s390x_pkgs >&2 )
for deb in "$s390x_dir"/debs/*.deb; do
    dpkg -x "$deb" "$s390x_dir/root"
done
if [ ! -f "$s390x_dir/root/usr/include/cmocka.h" ]; then
    echo "ci/setup: assure: no cmocka.h in the unpacked s390x packages" >&2; exit 1
fi
echo "$s390x_pkgs" > "$s390x_dir/.installed"
