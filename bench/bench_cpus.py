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

The kernel and PDL parts run in a child process per board (K_BOARD selects
the board in robocube_emu.launch.BOARDS). Writes the table to --out.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
for sub in ("bench", "kernel/tests/target-kernel", "pdl/tests/target"):
    sys.path.insert(0, str(ROOT / sub))

BOARDS = ("robocube", "stm32f405")
CPU = {"robocube": "MC68332 (CPU32)", "stm32f405": "Cortex-M4 (STM32F405)"}
SIZES = (9, 256, 4096)


def child(board, ktest, pdl_bench, qemu):
    """In the child (K_BOARD set): the kernel and PDL figures, as JSON."""
    import kmeasure
    import pdl_measure
    k = kmeasure.measure(qemu, Path(ktest))
    cycles, _ = pdl_measure.cycle_costs(qemu, Path(pdl_bench))
    pdl20 = [c["total"] for c in cycles if c["n"] == 20]
    print(json.dumps({"tick": statistics.median(k["tick_switch"]),
                      "handoff": statistics.median(k["sem_handoff"]),
                      "pdl20": statistics.mean(pdl20), "pdl20_cycles": len(pdl20)}))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--child", choices=BOARDS)
    for b in BOARDS:
        ap.add_argument(f"--{b}-bench")
        ap.add_argument(f"--{b}-ktest")
        ap.add_argument(f"--{b}-pdl")
        ap.add_argument(f"--{b}-qemu")
    ap.add_argument("--cycles", type=int, default=256)
    ap.add_argument("--out")
    a = vars(ap.parse_args())
    if a["child"]:
        b = a["child"]
        child(b, a[f"{b}_ktest"], a[f"{b}_pdl"], a[f"{b}_qemu"])
        return 0

    import bench
    from robocube_emu import launch
    res = {}
    for b in BOARDS:
        cfg = launch.BOARDS[b]
        elf = Path(a[f"{b}_bench"])
        objs = [elf.parent / "bsched/bsched.c.o", elf.parent / "bsched/proofs/ref/bsched_fig7.c.o"] \
            if b == "stm32f405" else \
            [elf.parent / "cpu32/bsched/bsched.c.o", elf.parent / "cpu32/bsched/proofs/ref/bsched_fig7.c.o"]
        sched, _ = bench.cpu32_run(elf, a[f"{b}_qemu"], objs, a["cycles"], machine=cfg["machine"],
                                   icount=cfg["icount"], cross=cfg["cross"])
        env = dict(os.environ, K_BOARD=b)
        out = subprocess.run([sys.executable, __file__, "--child", b,
                              f"--{b}-ktest", a[f"{b}_ktest"], f"--{b}-pdl", a[f"{b}_pdl"],
                              f"--{b}-qemu", a[f"{b}_qemu"]],
                             env=env, check=True, capture_output=True, text=True).stdout
        res[b] = {"sched": sched, **json.loads(out.strip().splitlines()[-1])}
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
