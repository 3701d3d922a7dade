#!/usr/bin/env python3
"""Every firmware image uses only instructions the CPU32 has.

  cpu32_isa.py [--objdump CMD] [--suite NAME] [--expect-bad OBJ]... ELF...

The CPU32 (MC68332) runs the 68000 instruction set plus most of the 68020's,
but not all of it (CPU32RM, appendix on the 68020 differences): no bit-field
instructions, no CAS/CAS2, CALLM/RTM, PACK/UNPK, no coprocessor or FPU
instructions, and no memory-indirect addressing modes. GCC's -mcpu=cpu32 emits
none of these, but code linked in from elsewhere can (Debian's m68k libgcc is
built for the 68020 with a 68881), and the board model rightly traps them, so a
program dies only when it first reaches such a routine.

Each ELF is disassembled whole (every executable section) and must hold none.
Each OBJ of --expect-bad must hold at least one: it shows the scan can fail.
With --suite, writes build/results/NAME.txt ('P passed, F failed').
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Mnemonics (size suffix removed) of the 68020 instructions the CPU32 lacks.
FORBIDDEN = re.compile(r"(bf(chg|clr|exts|extu|ffo|ins|set|tst)|cas2?|callm|rtm|pack|unpk|"
                       r"f[a-z]+|cp[a-z]+)$")
# Memory-indirect addressing, in objdump's MIT syntax: "%a0@(4)@(8)".
MEMORY_INDIRECT = re.compile(r"@\([^)]*\)@")


# GCC's m68k switch: "jmp %pc@(TABLE,%dN:w)" followed by the table, 16-bit offsets
# from TABLE to each case. The table is data in .text; objdump decodes it as
# instructions, which may look like anything.
JUMP_TABLE = re.compile(r"%pc@\(([0-9a-f]+)(?: <[^>]*>)?,%d[0-7]:w\)")


def jump_tables(lines, code):
    """Address ranges of the jump tables: from TABLE up to the nearest case, the
    first address an entry points at (the table ends where its code begins)."""
    ranges = []
    for _, mnemonic, operands in lines:
        m = JUMP_TABLE.search(operands) if mnemonic == "jmp" else None
        if not m:
            continue
        start = end = int(m.group(1), 16)
        limit = start + 0x10000
        while end < limit and end in code and end + 1 in code:
            offset = (code[end] << 8) | code[end + 1]
            offset -= 0x10000 if offset & 0x8000 else 0
            if offset > 0:
                limit = min(limit, start + offset)
            end += 2
        ranges.append((start, end))
    return ranges


def decode(objdump, path, *window):
    """objdump's decoding of path (or of the address window [start, stop)):
    (address, function, mnemonic, operands) in order, and the code bytes."""
    args = [objdump, "-d", path]
    if window:
        args[2:2] = ["--start-address=0x%x" % window[0], "--stop-address=0x%x" % window[1]]
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    function = "?"
    decoded, code = [], {}
    for line in out.splitlines():
        head = re.match(r"^[0-9a-f]+ <([^>]+)>:$", line)
        if head:
            function = head.group(1)
            continue
        fields = line.split("\t")
        if len(fields) >= 2 and re.match(r"^\s*[0-9a-f]+:$", fields[0]):
            address = int(fields[0].strip()[:-1], 16)
            for i, word in enumerate(fields[1].split()):   # "303b 0806": 16-bit words
                code[address + 2 * i] = int(word[:2], 16)
                code[address + 2 * i + 1] = int(word[2:4], 16)
            parts = fields[2].split(None, 1) if len(fields) >= 3 else []
            if parts:
                decoded.append((address, function, parts[0], parts[1] if len(parts) > 1 else ""))
    return decoded, code


def instructions(objdump, path):
    """(address, function, mnemonic, operands) of every instruction in every code
    section, jump tables left out. Decoding the table as instructions may run
    past its end, and then the code after it comes out of step (an operand
    word taken for an opcode); that code is decoded again from the table's
    end, up to where both decodings meet."""
    decoded, code = decode(objdump, path)
    tables = jump_tables([(a, m, o) for a, _, m, o in decoded], code)
    starts = {a for a, _, _, _ in decoded}
    redone = {}
    for _, end in tables:
        if end in starts or end not in code:
            continue
        again, _ = decode(objdump, path, end, end + 64)
        meet = next((a for a, _, _, _ in again if a in starts), end + 64)
        redone[end] = (meet, [i for i in again if i[0] < meet])
    for end, (meet, fresh) in redone.items():
        decoded = [i for i in decoded if not end <= i[0] < meet] + fresh
    decoded.sort()
    for address, function, mnemonic, operands in decoded:
        if not any(start <= address < end for start, end in tables):
            yield "%x" % address, function, mnemonic, operands


def forbidden(objdump, path):
    """(count of instructions, the forbidden ones as 'function+address: text')."""
    count, bad = 0, []
    for address, function, mnemonic, operands in instructions(objdump, path):
        count += 1
        if FORBIDDEN.match(mnemonic.split(".")[0]) or MEMORY_INDIRECT.search(operands):
            bad.append(f"{function} {address}: {mnemonic} {operands}".rstrip())
    return count, bad


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--objdump", default="m68k-linux-gnu-objdump")
    ap.add_argument("--suite")
    ap.add_argument("--expect-bad", action="append", default=[], metavar="OBJ")
    ap.add_argument("elfs", nargs="+", metavar="ELF")
    a = ap.parse_args()
    passed = failed = 0
    for path in a.elfs:
        name = os.path.relpath(path, ROOT)
        if not os.path.isfile(path):
            print(f"FAILED {name}: missing")
            failed += 1
            continue
        count, bad = forbidden(a.objdump, path)
        if count < 50:
            print(f"FAILED {name}: only {count} instructions disassembled")
            failed += 1
        elif bad:
            print(f"FAILED {name}: {len(bad)} instructions the CPU32 lacks, first: {bad[:8]}")
            failed += 1
        else:
            print(f"ok {name}: {count} instructions, all CPU32")
            passed += 1
    for path in a.expect_bad:
        name = os.path.relpath(path, ROOT)
        count, bad = forbidden(a.objdump, path) if os.path.isfile(path) else (0, [])
        if bad:
            print(f"ok {name}: the scan finds what the CPU32 lacks ({len(bad)}, e.g. {bad[0]})")
            passed += 1
        else:
            print(f"FAILED {name}: expected instructions the CPU32 lacks, found none in {count}")
            failed += 1
    print(f"{passed} passed, {failed} failed")
    if a.suite:
        os.makedirs(os.path.join(ROOT, "build/results"), exist_ok=True)
        with open(os.path.join(ROOT, "build/results", a.suite + ".txt"), "w") as f:
            f.write(f"{passed} passed, {failed} failed\n")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
