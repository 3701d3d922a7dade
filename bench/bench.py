#!/usr/bin/env python3
"""make bench: instructions per minor cycle, Fig. 7 (the reference engine
bsched_fig7_step) against the library's bsched_step, on the host (callgrind)
and on the emulated CPU32 (QEMU).

Host: bsched-bench N CYCLES runs under valgrind --tool=callgrind; the inclusive
instruction counts (Ir) of bsched_init, bsched_fig7_start, bsched_fig7_step and
bsched_step come from callgrind_annotate --inclusive=yes, divided by the
number of calls.

CPU32: bench-cpu32.elf runs on qemu-system-m68k -M robocube under
-singlestep -d exec,nochain, with -dfilter restricted to the library's
functions (every text symbol of bsched.c and bsched_fig7.c, and memcpy and
memset, should the compiler call them) and bench_mark(). One log line is one
executed instruction; the lines between two bench_mark() calls are a phase
(bench_image.h: five per case). The log is read from a FIFO, never stored.

Prints one line per case and platform, ending with the ratio, and writes them
to --out. Exit 1 if a case is missing or the two dispatchers disagreed.
"""
import argparse
import os
import re
import select
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

CASES = [9, 64, 256, 1024, 4096]
CROSS = "m68k-linux-gnu-"
BENCH_PROCS = 4096  # BSCHED_MAX_PROCS of both bench programs (bench.mk)
LIB_FUNCS = ("bsched_init", "bsched_fig7_start", "bsched_fig7_step", "bsched_step")


def host_case(binary, n, cycles):
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "callgrind.out"
        run = subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
                              str(binary), str(n), str(cycles)],
                             capture_output=True, text=True, check=True)
        fields = run.stdout.split()
        ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", str(out)],
                             capture_output=True, text=True, check=True).stdout
    cost = {}
    for line in ann.splitlines():
        m = re.match(r"^\s*([\d,]+)\s+\([^)]*\)\s+(\S+):(\w+)(\s|$)", line)
        if m and m.group(3) in LIB_FUNCS and m.group(3) not in cost:
            cost[m.group(3)] = int(m.group(1).replace(",", ""))
    missing = [f for f in LIB_FUNCS if f not in cost]
    if missing:
        raise RuntimeError(f"host N={n}: no callgrind cost for {missing}")
    return {"n": n, "maxpv": int(fields[1]), "perfect": int(fields[2]),
            "load": int(fields[4]) / cycles, "state": int(fields[5]), "fig7_state": int(fields[6]),
            "init": cost["bsched_init"], "fig7_start": cost["bsched_fig7_start"],
            "fig7": cost["bsched_fig7_step"] / cycles, "step": cost["bsched_step"] / cycles}


def symbols(path, defined_text_only=True, cross=CROSS):
    out = subprocess.run([cross + "nm", "-S", str(path)], capture_output=True, text=True,
                         check=True).stdout
    table = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[2] in "tT":
            table[parts[3]] = (int(parts[0], 16), int(parts[1], 16))
        elif len(parts) == 3 and not defined_text_only:
            table[parts[2]] = (int(parts[0], 16), 0)
    return table


def cpu32_run(elf, qemu, objs, cycles, seconds=900, machine="robocube",
              icount="shift=8,sleep=off", cross=CROSS):
    """The image's phases on a board: the RoboCube by default, or (machine,
    icount, cross) another one (the stm32f405's, bench/bench_cpus.py)."""
    elf_syms = symbols(elf, cross=cross)
    names = set()
    for obj in objs:
        names.update(symbols(obj, cross=cross))
    names.update(("memcpy", "memset"))
    ranges = [elf_syms[name] for name in sorted(names) if name in elf_syms]
    mark_pc, mark_size = elf_syms["bench_mark"]
    ranges.append(elf_syms["bench_mark"])
    dfilter = ",".join(f"0x{a:x}+0x{s:x}" for a, s in ranges)
    marker = f"/{mark_pc:08x}/"
    # bench_mark's own instructions are logged too (its range is in the filter)
    # but belong to no phase.
    mark_body = tuple(f"/{pc:08x}/" for pc in range(mark_pc + 2, mark_pc + mark_size, 2))
    with tempfile.TemporaryDirectory() as tmp:
        fifo = Path(tmp) / "exec.fifo"
        os.mkfifo(fifo)
        counts = []
        def reader():
            current = 0
            started = False
            with open(fifo, "r", errors="replace") as log:
                for line in log:
                    if not line.startswith("Trace"):
                        continue
                    if marker in line:
                        if started:
                            counts.append(current)
                        started = True
                        current = 0
                    elif not any(pc in line for pc in mark_body):
                        current += 1
        thread = threading.Thread(target=reader, daemon=True)
        thread.start()
        proc = subprocess.Popen([qemu, "-M", machine, "-kernel", str(elf), "-display", "none",
                                 "-monitor", "none", "-serial", "stdio", "-icount",
                                 icount, "-singlestep", "-d", "exec,nochain",
                                 "-dfilter", dfilter, "-D", str(fifo)],
                                stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE)
        console = b""
        deadline = time.monotonic() + seconds
        try:
            while b"bench done" not in console:
                left = deadline - time.monotonic()
                if left <= 0 or proc.poll() is not None:
                    break
                ready, _, _ = select.select([proc.stdout], [], [], min(left, 0.5))
                if ready:
                    chunk = os.read(proc.stdout.fileno(), 65536)
                    if not chunk:
                        break
                    console += chunk
        finally:
            time.sleep(0.5)
            proc.kill()
            proc.communicate()
            thread.join(timeout=60)
    text = console.decode("latin-1")
    if "bench done" not in text:
        raise RuntimeError(f"CPU32 image did not finish; console:\n{text}")
    results = {}
    for m in re.finditer(r"bench case (\d+): N=(\d+) maxpv=(\d+) perfect=(\d+) load=(\d+) (\w+)", text):
        c, n = int(m.group(1)), int(m.group(2))
        phases = counts[5 * c: 5 * c + 5]
        if len(phases) < 4:
            raise RuntimeError(f"CPU32 N={n}: only {len(phases)} phases traced")
        results[n] = {"n": n, "maxpv": int(m.group(3)), "perfect": int(m.group(4)),
                      "load": int(m.group(5)) / cycles, "same": m.group(6) == "same",
                      "init": phases[0], "fig7_start": phases[1],
                      "fig7": phases[2] / cycles, "step": phases[3] / cycles}
    sizes = re.search(r"struct bsched (\d+) bytes \(BSCHED_MAX_PROCS (\d+)\), struct bsched_fig7 (\d+)", text)
    return results, (int(sizes.group(1)), int(sizes.group(2)), int(sizes.group(3)))


def line(platform, r, procs):
    ratio = r["fig7"] / r["step"]
    pvs = "pv 1..4 (Table 1)" if r["n"] == 9 else "pv 3..12 uniform"
    # State bytes per process at capacity `procs`: the library's struct bsched
    # alone; Fig. 7 needs it (the plan) and its own struct bsched_fig7 (waits, ran).
    return (f"{platform:5} N={r['n']:<5} {pvs:17} due/cycle {r['load']:6.1f}  "
            f"bsched_init {r['init']:>9,} instr (fig7_start {r['fig7_start']:>7,})  "
            f"state {r['state'] / procs:5.2f} B/proc (fig7 {(r['state'] + r['fig7_state']) / procs:5.2f})  "
            f"fig7 {r['fig7']:>9,.1f}  bsched_step {r['step']:>7,.1f} instr/cycle  ratio {ratio:6.1f}x")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--host", required=True)
    ap.add_argument("--elf", required=True)
    ap.add_argument("--qemu", required=True)
    ap.add_argument("--cycles", type=int, default=256)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    elf = Path(args.elf)
    objs = [elf.parent / "cpu32/bsched/bsched.c.o", elf.parent / "cpu32/bsched/proofs/ref/bsched_fig7.c.o"]
    lines = [f"# instructions per minor cycle over {args.cycles} cycles from cycle 0; "
             f"state at BSCHED_MAX_PROCS = {BENCH_PROCS}; ratio = fig7 / bsched_step"]
    ok = True
    for n in CASES:
        r = host_case(args.host, n, args.cycles)
        lines.append(line("host", r, BENCH_PROCS))
        print(lines[-1], flush=True)
    cpu, (state, procs, fig7_state) = cpu32_run(elf, args.qemu, objs, args.cycles)
    for n in CASES:
        if n not in cpu:
            print(f"cpu32 N={n}: missing", file=sys.stderr)
            ok = False
            continue
        r = dict(cpu[n], state=state, fig7_state=fig7_state)
        ok = ok and r["same"]
        lines.append(line("cpu32", r, procs) + ("" if r["same"] else "  DIFFERENT"))
        print(lines[-1], flush=True)
    Path(args.out).write_text("\n".join(lines) + "\n")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
