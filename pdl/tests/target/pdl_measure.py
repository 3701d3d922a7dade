#!/usr/bin/env python3
"""PDL figures on the emulated RoboCube (apps/pdl_bench), all from the
deterministic instruction count (-icount shift=8,sleep=off):

  run_bench(qemu, elf)      console of an untraced run: CPU load at f0 = 1024 Hz
                            with 20 processes and 40 quantities (idle-loop
                            method, see apps/pdl_bench/bench.c), stack, overruns
  cycle_costs(qemu, elf)    instruction counts of every PDL cycle of the sweep
                            (N = 5, 10, 20, 30 processes, Q = 2N quantities) from a
                            QEMU exec trace (robocube_emu.exectrace), split in phases:
                            begin (clock, dt, sensors), processes, end (commit,
                            actuators), and fitted per process run and per commit
  footprint(map)            the runtime's flash (.text/.rodata) and RAM (.data/.bss)
                            from the linker map

Usage: pdl_measure.py [--cycles-json] [ELF [QEMU]]  prints everything (make pdl-bench);
--cycles-json only the traced sweep's cycles, as JSON (bench/bench_cpus.py).
"""
import argparse
import json
import os
import re
import statistics
import sys
from collections import defaultdict
from pathlib import Path

from robocube_emu import launch
from robocube_emu.exectrace import run_until_result, symbols, trace_pcs
from robocube_emu.linkmap import input_sections

ROOT = Path(__file__).resolve().parents[3]
# The board (robocube_emu.launch.BOARDS, $K_BOARD): the RoboCube by default, or stm32f405.
BOARD = launch.board()
ICOUNT = ["-icount", BOARD["icount"]]
SWEEP = (5, 10, 20, 30)
# 2^shift ns per instruction (RoboCube 256, stm32f405 8), 1024 Hz tick
INSTR_PER_TICK = 1e9 / 1024 / 2 ** int(re.search(r"shift=(\d+)", ICOUNT[1]).group(1))


def run_bench(qemu, elf, seconds=120.0):
    cmd = launch.command(["-serial", "stdio"], kernel=elf, qemu=qemu, machine=BOARD["machine"],
                         icount=BOARD["icount"])
    out, err = run_until_result(cmd, seconds, rb"PDL-BENCH RESULT [^\r\n]*\r?\n")
    return out.decode("latin-1").replace("\r\n", "\n")


def facts(console, kind):
    """key=value pairs of the 'PDL-BENCH <kind> ...' lines, one dict per line."""
    found = []
    for line in console.splitlines():
        if line.startswith(f"PDL-BENCH {kind} "):
            found.append({k: int(v) for k, v in re.findall(r"(\w+)=(-?\d+)", line)})
    return found


def fit(points):
    """Least squares y = a + b x over (x, y) pairs; returns (a, b)."""
    n = len(points)
    mx = sum(x for x, _ in points) / n
    my = sum(y for _, y in points) / n
    sxx = sum((x - mx) ** 2 for x, _ in points)
    if sxx == 0:
        return my, 0.0
    b = sum((x - mx) * (y - my) for x, y in points) / sxx
    return my - b * mx, b


def cycle_costs(qemu, elf, seconds=300.0):
    sym = symbols(elf, BOARD["cross"])
    pcs, console = trace_pcs(qemu, elf, seconds, rb"PDL-BENCH SWEEP DONE",
                              machine=BOARD["machine"], icount=BOARD["icount"])
    # Interrupt entries: a cycle that took one is left out.
    vectors = {a for n, a in sym.items() if n.startswith("cpu32_vector") or
               n in ("armv7m_systick", "k_arch_irq_entry", "armv7m_pendsv")}
    bodies = {a for n, a in sym.items() if re.fullmatch(r"bench_p\d+", n)}
    start, run, end = sym["pdl_board_cycle"], sym["pdl_cycle_run"], sym["pdl_cycle_end"]
    ticks, marker = sym["k_ticks"], sym["bench_config_start"]
    cycles = []
    config = -1
    first_of_config = False
    i, n = 0, len(pcs)
    while i < n:
        pc = pcs[i]
        if pc == marker:
            config += 1
            first_of_config = True
        if pc != start or config < 0:
            i += 1
            continue
        # one cycle: start -> run -> end -> the thread's k_ticks() after it
        i1 = pcs.index(run, i)
        i2 = pcs.index(end, i1)
        i3 = pcs.index(ticks, i2)
        span = pcs[i:i3]
        clean = not any(p in vectors for p in span)
        runs = sum(1 for p in pcs[i1:i2] if p in bodies)
        if clean and not first_of_config:
            cycles.append({"n": SWEEP[config], "runs": runs, "commits": 2 * runs,
                           "begin": i1 - i, "processes": i2 - i1, "end": i3 - i2,
                           "total": i3 - i})
        first_of_config = False
        i = i3
    return cycles, console


def summarise(cycles):
    """The figures the README quotes."""
    per_n = {}
    for n in SWEEP:
        tot = [c["total"] for c in cycles if c["n"] == n]
        if tot:
            per_n[n] = {"cycles": len(tot), "mean": statistics.mean(tot),
                        "min": min(tot), "max": max(tot),
                        "runs": statistics.mean(c["runs"] for c in cycles if c["n"] == n)}
    a_run, b_run = fit([(c["runs"], c["processes"]) for c in cycles])
    a_end, b_end = fit([(c["commits"], c["end"]) for c in cycles])
    a_tot_n, b_tot_n = fit([(c["n"], c["total"] - c["processes"] - c["end"] + a_run + a_end)
                            for c in cycles])
    begin = statistics.mean(c["begin"] for c in cycles)
    return {"per_n": per_n, "per_process_run": b_run, "per_commit": b_end,
            "fixed": begin + a_run + a_end, "begin": begin, "run_fixed": a_run,
            "end_fixed": a_end, "fixed_per_declared_process": b_tot_n}


def footprint(map_path):
    """Bytes of the PDL runtime (objects built from pdl/*.c) by region."""
    sizes = defaultdict(int)
    for section, _, size, path in input_sections(map_path, ("text", "rodata", "data", "bss")):
        if ("/obj/pdl/" in path or "libpdl.a(" in path) and size:
            kind = section.split(".")[1]
            sizes["flash" if kind in ("text", "rodata") else "ram"] += size
            sizes[kind] += size
    return dict(sizes)


def report(console, summary, sizes):
    load = facts(console, "load")[0]
    over = facts(console, "overload")[0]
    lines = []
    for n, s in summary["per_n"].items():
        lines.append(f"cycle with {n} processes, {2 * n} quantities: {s['mean']:.0f} instructions "
                     f"(mean of {s['cycles']} cycles, min {s['min']}, max {s['max']}; "
                     f"{s['runs']:.2f} processes and {2 * s['runs']:.1f} commits per cycle)")
    lines.append(f"per process run (call + a body of 2 value() + 2 add_value()): "
                 f"{summary['per_process_run']:.1f} instructions")
    lines.append(f"per quantity committed: {summary['per_commit']:.1f} instructions")
    lines.append(f"fixed per cycle (clock, dt, sensors, loops, actuator scan): "
                 f"{summary['fixed']:.0f} instructions")
    lines.append(f"CPU load at f0 = {load['f0_mhz'] / 1000:.0f} Hz, 20 processes (pv 0..4), "
                 f"40 quantities: {load['load_permille'] / 10:.1f} % "
                 f"(idle loop {load['spins_pdl']} vs {load['spins_idle']} turns in 256 ticks; "
                 f"= {load['load_permille'] / 1000 * INSTR_PER_TICK:.0f} instructions per tick "
                 f"incl. the kernel's wake-up and switches), overruns {load['overruns']}")
    lines.append(f"cycle thread stack: {load['stack_used']} of {load['stack_size']} bytes used")
    lines.append(f"overloaded program (20-tick process at 64 Hz): {over['cycles']} cycles, "
                 f"{over['overruns']} overruns counted and reported")
    lines.append(f"runtime footprint (pdl/*.c as linked in pdl_bench): flash {sizes.get('flash', 0)} "
                 f"bytes (.text {sizes.get('text', 0)}, .rodata {sizes.get('rodata', 0)}), "
                 f"RAM {sizes.get('ram', 0)} bytes (.data {sizes.get('data', 0)}, "
                 f".bss {sizes.get('bss', 0)}, incl. the 2048-byte cycle thread stack)")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("elf", nargs="?", type=Path, default=ROOT / "build/firmware/pdl_bench/pdl_bench.elf")
    ap.add_argument("qemu", nargs="?",
                    default=os.environ.get("BSCHED_QEMU", str(ROOT / "build/emu/qemu-system-m68k")))
    ap.add_argument("--cycles-json", action="store_true",
                    help="only the traced sweep: every clean cycle's counts as JSON "
                         "(bench/bench_cpus.py reads it)")
    a = ap.parse_args()
    qemu, elf = a.qemu, a.elf
    if a.cycles_json:
        cycles, _ = cycle_costs(qemu, elf)
        print(json.dumps(cycles))
        return 0 if cycles else 1
    console = run_bench(qemu, elf)
    cycles, _ = cycle_costs(qemu, elf)
    text = report(console, summarise(cycles), footprint(Path(elf).with_suffix(".map")))
    print(text)
    return 0 if "PDL-BENCH RESULT PASS" in console else 1


if __name__ == "__main__":
    sys.exit(main())
