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

Usage: kmeasure.py [ELF] [QEMU]   (defaults: build/kernel/target/ktest-measure.elf,
$BSCHED_QEMU). Prints the figures; exit 1 if a path was never seen.
"""
import ctypes
import os
import signal
import re
import select
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
TRACE = re.compile(r"^Trace \d+: \S+ \[[0-9a-f]+/([0-9a-f]+)/")

# What differs between the boards the kernel runs on: the QEMU machine, the
# -icount setting (each board's `make run` value), the one the kernel suite
# and the traces use, the binutils prefix, and the first instruction of the
# tick interrupt (where the tick span starts). The stm32f405's suite runs its
# virtual CPU at 64 ns per instruction instead of make run's 8: what it checks
# is counted in ticks and instructions, never in instructions per tick, and
# eight times fewer instructions per tick make its 10000-tick drift test and
# the traced spinner eight times shorter to emulate.
BOARDS = {
    "robocube": {"machine": "robocube", "icount": "shift=8,sleep=off",
                 "test_icount": "shift=8,sleep=off",
                 "cross": "m68k-linux-gnu-", "tick_entry": "k_isr_entry"},
    "stm32f405": {"machine": "netduinoplus2", "icount": "shift=3,sleep=off",
                  "test_icount": "shift=6,sleep=off",
                  "cross": "arm-none-eabi-", "tick_entry": "armv7m_systick"},
}
BOARD = BOARDS[os.environ.get("K_BOARD", "robocube")]



def _die_with_parent():
    """preexec_fn: the kernel sends SIGKILL to the child when this process dies,
    so a killed or crashed test run never leaves an emulator spinning (under
    -icount sleep=off an idle guest keeps a host core busy)."""
    ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)   # PR_SET_PDEATHSIG

def symbols(elf, cross=BOARD["cross"]):
    out = subprocess.run([cross + "nm", str(elf)], check=True, capture_output=True,
                         text=True).stdout
    table = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3:
            table[parts[2]] = int(parts[0], 16)
    return table


def run_until_result(cmd, seconds, marker=rb"KTEST RESULT [^\r\n]*\r?\n"):
    """Runs QEMU (cmd) until the console shows a KTEST RESULT line (or the
    regex `marker`) or `seconds` pass; returns (console bytes, stderr bytes)."""
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, preexec_fn=_die_with_parent)
    out = b""
    deadline = time.monotonic() + seconds
    try:
        while not re.search(marker, out):
            left = deadline - time.monotonic()
            if left <= 0 or proc.poll() is not None:
                break
            ready, _, _ = select.select([proc.stdout], [], [], min(left, 0.2))
            if ready:
                chunk = os.read(proc.stdout.fileno(), 65536)
                if not chunk:
                    break
                out += chunk
    finally:
        proc.kill()
        _, err = proc.communicate()
    return out, err


def trace_pcs(qemu, elf, seconds=60.0, marker=rb"KTEST RESULT [^\r\n]*\r?\n"):
    with tempfile.TemporaryDirectory() as tmp:
        log = Path(tmp) / "exec.log"
        out, _ = run_until_result(
            [qemu, "-M", BOARD["machine"], "-kernel", str(elf), "-display", "none",
             "-monitor", "none", "-serial", "stdio", "-icount", BOARD["test_icount"],
             "-singlestep", "-d", "exec,nochain", "-D", str(log)], seconds, marker)
        pcs = []
        with open(log, errors="replace") as f:
            for line in f:
                m = TRACE.match(line)
                if m:
                    pcs.append(int(m.group(1), 16))
        return pcs, out.decode("latin-1")


def spans(pcs, start, end, must_pass=None, stop_at=None, after_range=None):
    """Instruction counts from each `start` PC to the next `end` PC."""
    found = []
    i = 0
    n = len(pcs)
    while i < n:
        if pcs[i] == start and (after_range is None or
                                (i > 0 and after_range[0] <= pcs[i - 1] < after_range[1])):
            j = i + 1
            passed = must_pass is None
            while j < n and pcs[j] != end and (stop_at is None or pcs[j] != stop_at or j == i):
                if must_pass is not None and pcs[j] == must_pass:
                    passed = True
                j += 1
            if j < n and pcs[j] == end and passed:
                found.append(j - i)
            i = j
        else:
            i += 1
    return found


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
    elf = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build/kernel/target/ktest-measure.elf"
    qemu = sys.argv[2] if len(sys.argv) > 2 else os.environ.get("BSCHED_QEMU", "")
    r = measure(qemu, elf)
    print(f"traced {r['traced']} instructions")
    print(summary("tick interrupt with a context switch", r["tick_switch"]))
    print(summary("semaphore hand-off between two threads", r["sem_handoff"]))
    return 0 if r["tick_switch"] and r["sem_handoff"] else 1


if __name__ == "__main__":
    sys.exit(main())
