# Sourced by ci/setup.d/m68k.sh.
# The compiler runtime (soft-float, 64-bit division and shifts, the helpers GCC
# calls): Debian's libgcc for m68k-linux-gnu is built for the 68020 with a 68881
# and uses bit-field and FPU instructions the CPU32 traps on. libgcc itself needs
# the target headers of a configured and built cross GCC (tm.h, insn-*.h) to
# compile; LLVM's compiler-rt builtins are plain C99 with no generated header, so
# they build here in seconds with the cross compiler for -mcpu=cpu32 -msoft-float.
# They come from bookworm's llvm-toolchain-14 source package (the LLVM of the
# clang-14 the fuzzers use), and the file list is the one compiler-rt's own
# CMakeLists.txt names GENERIC_SOURCES (the portable C implementations).
# compiler-rt has no m68k long double (96-bit extended, XFmode); for it the
# library takes GCC's own m68k routines, libgcc/config/m68k/fpgnulib.c compiled
# with EXTFLOAT as libgcc builds xfgnulib.c (Debian's gcc-12-source): they
# compute in double precision through the double routines above.
# Each result lives in $BSCHED_TOOLS/cpu32-rt/HASH (HASH: this script and the
# compiler's version), and each checkout links build/cpu32-rt to the one it wants.
# -fwrapv: compiler-rt 14 negates its signed argument (__floatsidf, __floatdidf:
# a = -a), which overflows for INT_MIN; clang happens to compile that as wanted,
# GCC uses the overflow's undefinedness and got -2^29 for (double)INT32_MIN
# (apps/rtcheck found it). With -fwrapv the negation wraps, as the code expects.
# -fstack-usage/-fcallgraph-info: each routine's frame and callees in ci/*.ci, so
# the worst-case stack analysis (assure/stack.py) walks into the runtime too.
rt_flags="-std=c11 -mcpu=cpu32 -msoft-float -Os -fwrapv -ffreestanding -fno-builtin -ffunction-sections
          -fstack-usage -fcallgraph-info=su"
rt_hash=$( { sha256sum < "$BSCHED_ROOT/ci/setup.d/m68k/runtime.sh"; m68k-linux-gnu-gcc --version | head -n1; } \
           | sha256sum | cut -c1-16)
rt_dir=$BSCHED_TOOLS/cpu32-rt/$rt_hash
rt_link=$BSCHED_ROOT/build/cpu32-rt

if [ ! -f "$rt_dir/libbuiltins.a" ]; then
    mkdir -p "$BSCHED_TOOLS/cpu32-rt"
    exec 7>"$BSCHED_TOOLS/cpu32-rt/.lock"
    flock 7
    if [ ! -f "$rt_dir/libbuiltins.a" ]; then
        rt_src=$BSCHED_TOOLS/cpu32-rt/src
        if [ ! -f "$rt_src/compiler-rt/lib/builtins/CMakeLists.txt" ]; then
            echo "ci/setup: fetching bookworm's llvm-toolchain-14 source for compiler-rt's builtins" >&2
            dl=$BSCHED_TOOLS/cpu32-rt/download
            fetch_debian_source llvm-toolchain-14 "$dl"
            orig=$(ls "$dl"/llvm-toolchain-14_*.orig.tar.xz 2>/dev/null | head -n1)
            if [ -z "$orig" ]; then
                echo "ci/setup: no llvm-toolchain-14 source found (got: $(ls "$dl"))" >&2
                exit 1
            fi
            rm -rf "$rt_src" && mkdir -p "$rt_src"
            tar -xJf "$orig" -C "$rt_src" --strip-components=1 --wildcards \
                '*/compiler-rt/lib/builtins/*' '*/compiler-rt/LICENSE.TXT'
            rm -rf "$dl"
        fi
        builtins=$rt_src/compiler-rt/lib/builtins
        sources=$(sed -n '/^set(GENERIC_SOURCES$/,/^)$/p' "$builtins/CMakeLists.txt" | grep -o '[a-z0-9_]*\.c')
        if [ "$(echo "$sources" | wc -l)" -lt 100 ]; then
            echo "ci/setup: compiler-rt's GENERIC_SOURCES list not found in $builtins/CMakeLists.txt" >&2
            exit 1
        fi
        echo "ci/setup: building the CPU32 compiler runtime (compiler-rt builtins) in $rt_dir" >&2
        rm -rf "$rt_dir.tmp" && mkdir -p "$rt_dir.tmp/obj"
        # GCC's limits.h would pull in a C library's; _LIBC_LIMITS_H_ keeps it freestanding.
        gcc_include=$(m68k-linux-gnu-gcc -print-file-name=include)
        for s in $sources; do
            # shellcheck disable=SC2086
            m68k-linux-gnu-gcc $rt_flags -nostdinc -isystem "$gcc_include" -D_LIBC_LIMITS_H_ \
                -c -o "$rt_dir.tmp/obj/${s%.c}.o" "$builtins/$s"
        done
        gcc_tar=$(ls /usr/src/gcc-12/gcc-12*.tar.xz 2>/dev/null | head -n1)
        if [ -z "$gcc_tar" ]; then
            echo "ci/setup: gcc-12-source installed, but no /usr/src/gcc-12/gcc-12*.tar.xz" >&2
            exit 1
        fi
        rm -rf "$rt_dir.tmp/gcc" && mkdir -p "$rt_dir.tmp/gcc"
        tar -xJf "$gcc_tar" -C "$rt_dir.tmp/gcc" --strip-components=1 --wildcards \
            '*/libgcc/config/m68k/fpgnulib.c' '*/COPYING.RUNTIME'
        # shellcheck disable=SC2086
        m68k-linux-gnu-gcc $rt_flags -nostdinc -isystem "$gcc_include" -D_LIBC_LIMITS_H_ -DEXTFLOAT \
            -Wno-implicit-function-declaration \
            -c -o "$rt_dir.tmp/obj/xfgnulib.o" "$rt_dir.tmp/gcc/libgcc/config/m68k/fpgnulib.c"
        m68k-linux-gnu-ar rcs "$rt_dir.tmp/libbuiltins.a" "$rt_dir.tmp"/obj/*.o
        mkdir -p "$rt_dir.tmp/ci"
        mv "$rt_dir.tmp"/obj/*.ci "$rt_dir.tmp/ci/"
        cp "$rt_src/compiler-rt/LICENSE.TXT" "$rt_dir.tmp/LICENSE.TXT"
        cp "$rt_dir.tmp/gcc/COPYING.RUNTIME" "$rt_dir.tmp/COPYING.RUNTIME"
        rm -rf "$rt_dir.tmp/obj" "$rt_dir.tmp/gcc" "$rt_dir"
        mv "$rt_dir.tmp" "$rt_dir"
        # Keep the 4 newest builds.
        ls -1dt "$BSCHED_TOOLS"/cpu32-rt/*/libbuiltins.a 2>/dev/null | tail -n +5 | xargs -r -n1 dirname | xargs -r rm -rf
    fi
    exec 7>&-
fi
mkdir -p "$(dirname "$rt_link")"
[ "$(readlink "$rt_link" 2>/dev/null)" = "$rt_dir" ] || ln -sfn "$rt_dir" "$rt_link"
