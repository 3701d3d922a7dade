#!/usr/bin/env python3
"""The cost of net/auth.c on the emulated CPU32, from the deterministic
instruction count (robocube_emu.exectrace:
-icount shift=8,sleep=off -singlestep -d exec,nochain):

  costs(qemu, elf)    instructions of each measured call of auth_board.c,
                      from the called function's first instruction to the
                      label after the call (auth_board_after_*): seal and
                      open of a full 128-byte payload, of an ACK-sized one,
                      open of a forged full one; one count per round
  footprint(map)      flash bytes (.text, .rodata) of net/auth.c and of the
                      Mbed TLS objects the link kept, RAM bytes (.data, .bss)

Usage: auth_measure.py [ELF [QEMU]]   prints the figures (make net-auth-bench).
"""
import os
import sys
from collections import defaultdict
from pathlib import Path

from robocube_emu import launch
from robocube_emu.exectrace import run_until_result, spans, symbols, trace_pcs
from robocube_emu.linkmap import input_sections

ROOT = Path(__file__).resolve().parents[3]

DONE = rb"AUTH-BOARD DONE[^\r\n]*\r?\n"
# call name -> (function entered, label after the call)
CALLS = {
    "seal 128": ("auth_seal", "auth_board_after_seal_full"),
    "open 128": ("auth_open", "auth_board_after_open_full"),
    "seal ACK": ("auth_seal", "auth_board_after_seal_ack"),
    "open ACK": ("auth_open", "auth_board_after_open_ack"),
    "open 128 forged": ("auth_open", "auth_board_after_open_forged"),
}
ICOUNT_NS = 256          # -icount shift=8: 256 ns of virtual time per instruction


def console(qemu, elf, seconds=60.0):
    cmd = launch.command(["-serial", "stdio"], kernel=elf, qemu=qemu)
    out, _ = run_until_result(cmd, seconds, DONE)
    return out.decode("latin-1").replace("\r\n", "\n")


def costs(qemu, elf, seconds=120.0):
    sym = symbols(elf)
    pcs, text = trace_pcs(qemu, elf, seconds, DONE)
    found = {}
    for name, (func, label) in CALLS.items():
        # stop_at: a span that meets the function's entry again before the
        # label belongs to another call of the same function.
        found[name] = spans(pcs, sym[func], sym[label], stop_at=sym[func])
    return found, text


def footprint(map_path):
    sizes = defaultdict(int)
    for section, _, size, path in input_sections(
            map_path, ("text", "rodata", "data", "bss")):
        if not size:
            continue
        kind = section.split(".")[1]
        region = "flash" if kind in ("text", "rodata") else "ram"
        if path.endswith("/auth.o"):
            sizes[("auth.c", region)] += size
        elif "libmbedcrypto.a(" in path:
            sizes[("mbedtls", region)] += size
            sizes[(path.split("(")[1].rstrip(")"), region)] += size
    return dict(sizes)


def report(found, sizes):
    lines = []
    for name, counts in found.items():
        if counts:
            lines.append(f"{name}: {counts[0]} instructions ({len(counts)} rounds, "
                         f"min {min(counts)}, max {max(counts)}; "
                         f"{counts[0] * ICOUNT_NS / 1e6:.2f} ms of virtual time at 256 ns each)")
        else:
            lines.append(f"{name}: not observed")
    flash = sizes.get(("auth.c", "flash"), 0) + sizes.get(("mbedtls", "flash"), 0)
    ram = sizes.get(("auth.c", "ram"), 0) + sizes.get(("mbedtls", "ram"), 0)
    parts = ", ".join(f"{k[0]} {v}" for k, v in sorted(sizes.items())
                      if k[1] == "flash" and k[0].endswith(".o"))
    lines.append(f"flash added: {flash} bytes (net/auth.c {sizes.get(('auth.c', 'flash'), 0)}, "
                 f"Mbed TLS {sizes.get(('mbedtls', 'flash'), 0)}: {parts}); "
                 f"RAM {ram} bytes (.data + .bss)")
    return "\n".join(lines)


def main():
    elf = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build/net/auth/board/auth_board.elf"
    qemu = sys.argv[2] if len(sys.argv) > 2 else os.environ.get(
        "BSCHED_QEMU", str(ROOT / "build/emu/qemu-system-m68k"))
    found, _ = costs(qemu, elf)
    print(report(found, footprint(Path(elf).with_suffix(".map"))))
    return 0 if all(found.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
