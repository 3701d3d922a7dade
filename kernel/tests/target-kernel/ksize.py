#!/usr/bin/env python3
"""Kernel footprint from a linker map: bytes of code and constants (.text*,
.rodata*) that the link kept in flash, grouped by origin. Usage:
    ksize.py build/kernel/target/ktest-measure.map
Groups: kernel core (kernel/k_*.c), CPU32 port + board glue
(kernel/arch/cpu32/k_*.c, switch.S), bsched.c, the firmware base it runs on
(startup, fault reporter, polled console, PIT), the formatter kprintf.c that
k_printf uses (counted with the kernel), the test program."""
import re
import sys
from collections import defaultdict

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


def input_sections(map_path, kinds=("text", "rodata")):
    """(section, address, size, object) for every input section of the given
    kinds the link kept, from a GNU ld map (objects in archives read
    'lib.a(obj.o)')."""
    text = open(map_path).read()
    body = text.split("Linker script and memory map", 1)[1]
    names = "|".join(kinds)
    pending = None
    for line in body.splitlines():
        m = re.match(rf"^ (\.(?:{names})\S*)\s*$", line)
        if m:
            pending = m.group(1)
            continue
        m = re.match(rf"^ (\.(?:{names})\S*)?\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+(\S+\.o\)?)\s*$", line)
        if m and (m.group(1) or pending):
            yield (m.group(1) or pending), int(m.group(2), 16), int(m.group(3), 16), m.group(4)
        pending = None


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
