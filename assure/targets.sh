#!/usr/bin/env bash
# bsched.c on every target and integer size: compiles warning-free (-Werror) with
# -Wall -Wextra -Wpedantic -Wconversion and reports the text size of each object.
#   assure/targets.sh RESULT-FILE "HOST_CFLAGS"
set -uo pipefail
cd "$(dirname "$0")/.."
result=$1; host_cflags=$2
out=build/assure/targets; mkdir -p "$out" "$(dirname "$result")"
warn="-std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror"
free="$warn -Os -ffreestanding"
# name | compiler | size tool | flags   (int width in the name)
configs=(
  "host-gcc-x86_64 (int 32, ptr 64)|gcc|size|$host_cflags"
  "host-gcc-x86_64 MAX_PROCS=65535|gcc|size|$host_cflags -DBSCHED_MAX_PROCS=65535"
  "host-clang-x86_64 (int 32, ptr 64)|clang|size|$warn -O2"
  "host-clang-x86_64 MAX_PROCS=65535|clang|size|$warn -O2 -DBSCHED_MAX_PROCS=65535"
  "cpu32 m68k (int 32, big-endian)|m68k-linux-gnu-gcc|m68k-linux-gnu-size|$free -mcpu=cpu32"
  "cpu32 m68k MAX_PROCS=65535|m68k-linux-gnu-gcc|m68k-linux-gnu-size|$free -mcpu=cpu32 -DBSCHED_MAX_PROCS=65535"
  "cortex-m0 thumb (int 32)|arm-none-eabi-gcc|arm-none-eabi-size|$free -mcpu=cortex-m0 -mthumb"
  "cortex-m4 thumb-2 (int 32)|arm-none-eabi-gcc|arm-none-eabi-size|$free -mcpu=cortex-m4 -mthumb"
  "rv32imac ilp32 (int 32)|riscv64-unknown-elf-gcc|riscv64-unknown-elf-size|$free -march=rv32imac -mabi=ilp32"
  "avr atmega2560 (int 16, size_t 16)|avr-gcc|avr-size|$free -mmcu=atmega2560"
  "avr atmega2560 MAX_PROCS=1000|avr-gcc|avr-size|$free -mmcu=atmega2560 -DBSCHED_MAX_PROCS=1000"
)
pass=0; fail=0; i=0
printf '%-40s %-24s %s\n' "target" "compiler" "text bytes (bsched.o)"
for c in "${configs[@]}"; do
    IFS='|' read -r name cc sizetool flags <<<"$c"
    i=$((i + 1)); obj="$out/bsched-$i.o"
    if msg=$($cc $flags -Ibsched -c -o "$obj" bsched/bsched.c 2>&1) && [ -z "$msg" ]; then
        text=$($sizetool "$obj" | awk 'NR == 2 { print $1 }')
        printf '%-40s %-24s %s\n' "$name" "$($cc -dumpversion | sed "s/^/$(basename $cc) /")" "$text"
        pass=$((pass + 1))
    else
        printf '%-40s %-24s FAILED\n%s\n' "$name" "$cc" "$msg"
        fail=$((fail + 1))
    fi
done
echo "$pass passed, $fail failed" > "$result"
echo "flags: $free (+ target flags); host: HOST_CFLAGS / $warn -O2"
[ "$fail" -eq 0 ]
