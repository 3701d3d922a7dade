#!/usr/bin/env python3
"""The two CPUs side by side (make bench-cpus): the MC68332 of the RoboCube
and the Cortex-M4 of the stm32f405 board, in guest instructions counted from
QEMU's exec trace under -icount (deterministic, not wall-clock):

  bsched_step and Fig. 7 per minor cycle, N = 9, 256, 4096
      bench/bench.py's phase counter on each board's bench image
  tick interrupt that switches threads; semaphore hand-off between two threads
      kernel/tests/target-kernel/kmeasure.py on each board's ktest-measure.elf
  PDL cycle with 20 processes and 40 quantities
      pdl/tests/target/pdl_measure.py (cycle_costs) on each board's pdl_bench

The kernel and PDL figures come from those two scripts, each run as its own
process with K_BOARD naming the board (robocube_emu.launch.BOARDS), printing
JSON. Writes the table to --out.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

import bench  # bench/bench.py, beside this script
from robocube_emu import launch

ROOT = Path(__file__).resolve().parents[1]
KMEASURE = ROOT / "kernel/tests/target-kernel/kmeasure.py"
PDL_MEASURE = ROOT / "pdl/tests/target/pdl_measure.py"

BOARDS = ("robocube", "stm32f405")
CPU = {"robocube": "MC68332 (CPU32)", "stm32f405": "Cortex-M4 (STM32F405)"}
SIZES = (9, 256, 4096)


def measured(board, script, *args):
    """What SCRIPT (--json or --cycles-json) printed for BOARD, decoded."""
    r = subprocess.run([sys.executable, str(script), *map(str, args)],
                       env=dict(os.environ, K_BOARD=board), capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"bench_cpus: {script.name} on {board} failed (exit {r.returncode}):\n"
                 f"{r.stdout}{r.stderr}")
    return json.loads(r.stdout.strip().splitlines()[-1])


def kernel_and_pdl(board, ktest, pdl_bench, qemu):
    """The kernel and PDL figures of BOARD: medians of the kernel spans, the
    mean PDL cycle with 20 processes."""
    k = measured(board, KMEASURE, "--json", ktest, qemu)
    cycles = measured(board, PDL_MEASURE, "--cycles-json", pdl_bench, qemu)
    pdl20 = [c["total"] for c in cycles if c["n"] == 20]
    return {"tick": statistics.median(k["tick_switch"]),
            "handoff": statistics.median(k["sem_handoff"]),
            "pdl20": statistics.mean(pdl20), "pdl20_cycles": len(pdl20)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for b in BOARDS:
        ap.add_argument(f"--{b}-bench", required=True)
        ap.add_argument(f"--{b}-ktest", required=True)
        ap.add_argument(f"--{b}-pdl", required=True)
        ap.add_argument(f"--{b}-qemu", required=True)
    ap.add_argument("--cycles", type=int, default=256)
    ap.add_argument("--out")
    a = vars(ap.parse_args())

    res = {}
    for b in BOARDS:
        cfg = launch.BOARDS[b]
        elf = Path(a[f"{b}_bench"])
        objs = [elf.parent / "bsched/bsched.c.o", elf.parent / "bsched/proofs/ref/bsched_fig7.c.o"] \
            if b == "stm32f405" else \
            [elf.parent / "cpu32/bsched/bsched.c.o", elf.parent / "cpu32/bsched/proofs/ref/bsched_fig7.c.o"]
        sched, _ = bench.cpu32_run(elf, a[f"{b}_qemu"], objs, a["cycles"], machine=cfg["machine"],
                                   icount=cfg["icount"], cross=cfg["cross"])
        res[b] = {"sched": sched, **kernel_and_pdl(b, a[f"{b}_ktest"], a[f"{b}_pdl"], a[f"{b}_qemu"])}
        print(f"{b}: done", flush=True)

    rows = []
    for n in SIZES:
        rows.append((f"bsched_step per minor cycle, N = {n}",
                     *(f"{res[b]['sched'][n]['step']:,.1f}" for b in BOARDS)))
    for n in SIZES:
        rows.append((f"Fig. 7 per minor cycle, N = {n}",
                     *(f"{res[b]['sched'][n]['fig7']:,.1f}" for b in BOARDS)))
    rows.append(("tick interrupt that switches threads",
                 *(f"{res[b]['tick']:,.0f}" for b in BOARDS)))
    rows.append(("semaphore hand-off between two threads",
                 *(f"{res[b]['handoff']:,.0f}" for b in BOARDS)))
    rows.append(("PDL cycle, 20 processes, 40 quantities (mean)",
                 *(f"{res[b]['pdl20']:,.0f}" for b in BOARDS)))
    w = max(len(r[0]) for r in rows)
    head = f"{'instructions (QEMU -icount exec trace)':{w}}  {CPU['robocube']:>18}  {CPU['stm32f405']:>22}"
    lines = [head, "-" * len(head)] + [f"{r[0]:{w}}  {r[1]:>18}  {r[2]:>22}" for r in rows]
    lines.append(f"({a['cycles']} minor cycles per bsched case from cycle 0; kernel figures: "
                 "median of 20; the same sources, -Os, GCC 12 for both)")
    text = "\n".join(lines) + "\n"
    print(text)
    if a["out"]:
        Path(a["out"]).write_text(text)
    ok = all(r["same"] for b in BOARDS for r in res[b]["sched"].values())
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
