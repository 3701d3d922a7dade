#!/usr/bin/env python3
"""Counts guest instructions of two kernel paths on the emulated RoboCube.

Runs build/kernel/target/ktest-measure.elf under
    qemu-system-m68k -M robocube -icount shift=8,sleep=off \
        -singlestep -d exec,nochain -D <log>
so QEMU logs one line per executed instruction (one instruction per
translation block, no block chaining), then walks the PC sequence:

  tick+switch: from the first instruction of the kernel's interrupt entry
               (k_isr_entry, where the PIT vector is routed) taken while the
               low-priority spinner runs, to the label ktest_after_sleep in
               the woken high-priority thread: the move to the interrupt
               stack, PIT handler, k_tick, timer expiry, the scheduling
               decision at the outermost exit, the context switch and the
               woken thread's return out of k_sleep_ticks.
  sem hand-off: from ktest_before_post in the giver to ktest_after_wait in
               the taker: k_sem_post, waking, switch, return out of k_sem_wait.

K_BOARD=stm32f405 measures the same paths on the ARMv7-M port (qemu-system-arm
-M netduinoplus2; the tick span starts at the SysTick handler): see BOARDS.

Usage: kmeasure.py [--json] [ELF] [QEMU]   (defaults: build/kernel/target/ktest-measure.elf,
$BSCHED_QEMU). Prints the figures (--json: every span's count, as JSON); exit 1
if a path was never seen.
"""
import argparse
import json
import os
import statistics
import sys
from pathlib import Path

from robocube_emu import exectrace, launch
from robocube_emu.exectrace import spans

ROOT = Path(__file__).resolve().parents[3]
# The board (robocube_emu.launch.BOARDS): $K_BOARD, the RoboCube by default.
BOARD = launch.board()


def symbols(elf, cross=BOARD["cross"]):
    return exectrace.symbols(elf, cross)


def trace_pcs(qemu, elf, seconds=60.0, marker=rb"KTEST RESULT [^\r\n]*\r?\n"):
    return exectrace.trace_pcs(qemu, elf, seconds, marker, machine=BOARD["machine"],
                               icount=BOARD["test_icount"])


def measure(qemu, elf):
    sym = symbols(elf)
    pcs, console = trace_pcs(qemu, elf)
    spin = sym["ktest_spin_loop"]
    # The tick's first instruction (RoboCube: the kernel's entry, where the
    # PIT is routed; stm32f405: the SysTick handler) starts the span; ending
    # in the woken sleeper after a switch means it was the tick (the only
    # interrupt that wakes it).
    entry = sym[BOARD["tick_entry"]]
    tick = spans(pcs, entry, sym["ktest_after_sleep"],
                 must_pass=sym["k_arch_switch"], stop_at=entry,
                 after_range=(spin - 64, spin + 64))
    handoff = spans(pcs, sym["ktest_before_post"], sym["ktest_after_wait"],
                    must_pass=sym["k_arch_switch"])
    return {"tick_switch": tick, "sem_handoff": handoff, "traced": len(pcs),
            "console": console}


def summary(name, counts):
    if not counts:
        return f"{name}: not observed"
    return (f"{name}: {statistics.median(counts):.0f} instructions (median of {len(counts)}, "
            f"min {min(counts)}, max {max(counts)})")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("elf", nargs="?", type=Path, default=ROOT / "build/kernel/target/ktest-measure.elf")
    ap.add_argument("qemu", nargs="?", default=os.environ.get("BSCHED_QEMU", ""))
    ap.add_argument("--json", action="store_true",
                    help="print the counts of every span as one JSON object (bench/bench_cpus.py reads it)")
    a = ap.parse_args()
    r = measure(a.qemu, a.elf)
    if a.json:
        print(json.dumps({k: r[k] for k in ("tick_switch", "sem_handoff", "traced")}))
        return 0 if r["tick_switch"] and r["sem_handoff"] else 1
    print(f"traced {r['traced']} instructions")
    print(summary("tick interrupt with a context switch", r["tick_switch"]))
    print(summary("semaphore hand-off between two threads", r["sem_handoff"]))
    return 0 if r["tick_switch"] and r["sem_handoff"] else 1


if __name__ == "__main__":
    sys.exit(main())
