# The C library of the firmware: newlib (Debian's newlib-source) built for the
# CPU32, soft-float, with nano malloc for size. Its full formatted I/O, not the
# nano one: nano's printf has no %lld (C99, and what 64-bit counters need). Its
# printf formats a long double as a double (__truncxfdf2, from the runtime's GCC
# part, ci/setup.d/m68k/runtime.sh). Sourced by ci/setup.d/m68k.sh. Picolibc would be smaller, but bookworm's picolibc source package
# cannot be fetched here; newlib-source ships its tarball in a binary package.
# The result (include/, lib/libc.a, lib/libm.a, ci/*.ci) lives in $BSCHED_TOOLS/newlib/HASH
# (HASH: this script's content, the cross compiler's and newlib-source's versions); each checkout links
# build/newlib to the one it wants. The system calls newlib needs (read, write,
# sbrk, _exit, ...) are the board's: drivers/libc_syscalls.c.
apt_install newlib-source make xz-utils

nl_hash=$( { sha256sum < "$BSCHED_ROOT/ci/setup.d/m68k/newlib.sh"; m68k-linux-gnu-gcc --version | head -n1;
             dpkg-query -W -f='${Version}' newlib-source; } | sha256sum | cut -c1-16)
nl_dir=$BSCHED_TOOLS/newlib/$nl_hash
nl_link=$BSCHED_ROOT/build/newlib

if [ ! -f "$nl_dir/lib/libc.a" ]; then
    mkdir -p "$BSCHED_TOOLS/newlib"
    exec 6>"$BSCHED_TOOLS/newlib/.lock"
    flock 6
    if [ ! -f "$nl_dir/lib/libc.a" ]; then
        tarball=$(ls /usr/src/newlib/newlib-*.tar.* 2>/dev/null | head -n1)
        if [ -z "$tarball" ]; then
            echo "ci/setup: newlib-source installed, but no /usr/src/newlib/newlib-*.tar.*" >&2
            exit 1
        fi
        work=$BSCHED_TOOLS/newlib/work
        rm -rf "$work" && mkdir -p "$work/src" "$work/build"
        tar -xf "$tarball" -C "$work/src" --strip-components=1
        echo "ci/setup: building newlib for the CPU32 in $nl_dir (log: $work/build/build.log; a few minutes)" >&2
        start=$(date +%s)
        gcc_include=$(m68k-linux-gnu-gcc -print-file-name=include)
        for t in CC:gcc AR:ar AS:as LD:ld NM:nm RANLIB:ranlib OBJDUMP:objdump READELF:readelf STRIP:strip; do
            export "${t%%:*}_FOR_TARGET=m68k-linux-gnu-${t#*:}"
        done
        # -U__linux__ (and the others GCC's m68k-linux-gnu predefines): newlib's
        # headers would take the board for a Linux system (sys/config.h gives Linux a
        # dynamic reentrancy structure). -nostdinc: no header of the build machine's
        # C libraries. -fwrapv: as the compiler runtime (ci/setup.d/m68k.sh).
        # -fstack-usage/-fcallgraph-info: the frames and callees of every routine in
        # ci/, for the worst-case stack analysis (assure/stack.py).
        export CFLAGS_FOR_TARGET="-mcpu=cpu32 -msoft-float -Os -g -ffunction-sections -fdata-sections \
-fwrapv -U__linux__ -U__gnu_linux__ -Ulinux -U__unix__ -Uunix -nostdinc -isystem $gcc_include \
-fstack-usage -fcallgraph-info=su"
        if ! (cd "$work/build" && "$work/src/configure" --target=m68k-elf --prefix="$nl_dir.tmp" \
                --disable-multilib --disable-nls --disable-newlib-supplied-syscalls \
                --enable-newlib-io-long-long --enable-newlib-io-c99-formats --enable-newlib-nano-malloc \
                --enable-newlib-reent-small --enable-lite-exit --enable-newlib-global-atexit \
                --disable-newlib-fvwrite-in-streamio --disable-newlib-wide-orient \
                --disable-newlib-unbuf-stream-opt > build.log 2>&1 &&
              nice make -j"$(nproc)" all-target-newlib >> build.log 2>&1 &&
              make install-target-newlib >> build.log 2>&1); then
            tail -n 30 "$work/build/build.log" >&2
            echo "ci/setup: newlib build failed, full log in $work/build/build.log" >&2
            exit 1
        fi
        rm -rf "$nl_dir"
        mkdir -p "$nl_dir"
        mv "$nl_dir.tmp/m68k-elf/include" "$nl_dir/include"
        mv "$nl_dir.tmp/m68k-elf/lib" "$nl_dir/lib"
        mkdir -p "$nl_dir/ci"
        (cd "$work/build/m68k-elf/newlib" && find . -name '*.ci' | while read -r ci; do
            cp "$ci" "$nl_dir/ci/$(echo "${ci#./}" | tr / _)"; done)
        cp "$work/src/COPYING.NEWLIB" "$nl_dir/"
        rm -rf "$nl_dir.tmp" "$work"
        echo "ci/setup: newlib built in $(( $(date +%s) - start )) s" >&2
        ls -1dt "$BSCHED_TOOLS"/newlib/*/lib/libc.a 2>/dev/null | tail -n +5 | xargs -r -n1 dirname \
            | xargs -r -n1 dirname | xargs -r rm -rf
    fi
    exec 6>&-
fi
mkdir -p "$(dirname "$nl_link")"
[ "$(readlink "$nl_link" 2>/dev/null)" = "$nl_dir" ] || ln -sfn "$nl_dir" "$nl_link"
