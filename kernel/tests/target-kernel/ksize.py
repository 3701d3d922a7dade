#!/usr/bin/env python3
"""Kernel footprint from a linker map: bytes of code and constants (.text*,
.rodata*) that the link kept in flash, grouped by origin. Usage:
    ksize.py build/kernel/target/ktest-measure.map
Groups: kernel core (kernel/k_*.c), CPU32 port + board glue
(kernel/arch/cpu32/k_*.c, switch.S), bsched.c, the firmware base it runs on
(startup, fault reporter, polled console, PIT), the formatter kprintf.c that
k_printf uses (counted with the kernel), the test program."""
import sys
from collections import defaultdict

from robocube_emu.linkmap import input_sections

FLASH_LO, FLASH_HI = 0xE00000, 0xF00000


def group_of(path):
    if "/build/kernel/target/obj/kernel/arch/" in path:
        return "kernel CPU32 port + board glue"
    if "/build/kernel/target/obj/kernel/" in path:
        return "kernel core"
    if path.endswith("/bsched/bsched.c.o"):
        return "bsched.c"
    if path.endswith("/kernel/lib/kprintf.c.o"):
        return "kernel formatter (kernel/lib/kprintf.c)"
    if "/build/firmware/obj/" in path:
        return "firmware base (startup, faults, polled console, PIT)"
    return "test program"


def main(map_path):
    sizes = defaultdict(int)
    for _, addr, size, path in input_sections(map_path):
        if FLASH_LO <= addr < FLASH_HI and size:
            sizes[group_of(path)] += size
    for g in sorted(sizes):
        print(f"{sizes[g]:7d}  {g}")
    kernel = (sizes["kernel core"] + sizes["kernel CPU32 port + board glue"] +
              sizes["kernel formatter (kernel/lib/kprintf.c)"])
    print(f"{kernel:7d}  kernel total")
    print(f"{kernel + sizes['bsched.c']:7d}  kernel + bsched.c (goal < 16384)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
