#!/usr/bin/env python3
"""make run in an arena: a robot program (the ecosystem's, or any PDL program:
make run APP=x WORLD=default) runs on the emulated RoboCube (real firmware,
QEMU in lockstep with the world) or, with --host, on the host against the
same world (fast mode). Shows a live view (a terminal) or progress lines (a
pipe), the robot's console lines as they come, then a summary, the picture
and the trajectory's sha256. Exit status 0 after a complete run (whatever the
robot did), 2 on bad input, 1 when the emulator or the program failed."""

import argparse
import json
import math
import os
import sys
import time

from record import Recorder, save_picture, summary_lines
from view import LiveView, PlainProgress
from world import ArenaError, World, load_arena

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_ARENA = os.path.join(HERE, "arenas", "default.json")
STEP_MS = 7.8125


MAX_SECONDS = 86400.0          # a virtual day
MAX_SEED = 2**32 - 1           # the robot program's seed is 32 bits (hostmode.py)


class OneLineParser(argparse.ArgumentParser):
    """Bad options: one line on stderr naming the problem and the usage, exit 2
    (argparse's own form is a usage block and a second line)."""

    def error(self, message):
        usage = " ".join(self.format_usage().split())
        self.exit(2, f"{self.prog}: {message} ({usage})\n")


def _seconds(text):
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number of seconds") from None
    if not (math.isfinite(v) and 0 < v <= MAX_SECONDS):
        raise argparse.ArgumentTypeError(f"{text}: out of range (0, {MAX_SECONDS:g}]")
    return v


def _seed(text):
    try:
        v = int(text, 10)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a whole number") from None
    if not 0 <= v <= MAX_SEED:
        raise argparse.ArgumentTypeError(f"{text}: out of range 0..{MAX_SEED}")
    return v


def _step_ms(text):
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number of milliseconds") from None
    if not 0.1 <= v <= 1000:
        raise argparse.ArgumentTypeError(f"{text}: out of range 0.1 .. 1000")
    return v


def parse_args(argv):
    ap = OneLineParser(prog="run.py", description=__doc__.split("\n")[0])
    ap.add_argument("--seconds", type=_seconds, default=120.0,
                    help=f"virtual seconds, up to {MAX_SECONDS:g} (default 120)")
    ap.add_argument("--seed", type=_seed, default=1,
                    help=f"sensor-noise seed 0..{MAX_SEED} (default 1)")
    ap.add_argument("--arena", default=DEFAULT_ARENA, help="arena file (JSON, arena.schema.json)")
    ap.add_argument("--host", action="store_true", help="fast mode: the program on the host")
    ap.add_argument("--elf", help="firmware image (emulated mode)")
    ap.add_argument("--qemu", default=os.environ.get("BSCHED_QEMU"), help="qemu-system-m68k")
    ap.add_argument("--host-lib", help="the program as a host library (fast mode): "
                    "libeco_host.so or a PDL program's libNAME_host.so")
    ap.add_argument("--step-ms", type=_step_ms, default=STEP_MS,
                    help=f"lockstep step (default {STEP_MS} ms: one kernel tick, see cosim.py)")
    ap.add_argument("--out", default="build/run", help="folder for ecosystem.png and summary.json")
    ap.add_argument("--view", choices=("auto", "live", "plain", "none"), default="auto")
    ap.add_argument("--trace", help="write every step's pose (t_ns x y th soc) to this file")
    a = ap.parse_args(argv)
    if a.host and not a.host_lib:
        ap.error("--host needs --host-lib")
    if not a.host and not (a.elf and a.qemu):
        ap.error("the emulated mode needs --elf and --qemu")
    for path in (a.elf, a.qemu, a.host_lib):
        if path and not os.path.exists(path):
            ap.error(f"{path}: no such file")
    if a.host:
        import ctypes
        try:
            ctypes.CDLL(os.path.abspath(a.host_lib))
        except OSError as e:
            ap.error(f"--host-lib {a.host_lib}: not a loadable library ({e})")
    return a


# The ecosystem firmware's processes, in id order, for its status line
# (apps/ecosystem/eco_program.h).
ECO_PROCESSES = ["bump", "avoid", "cruise", "photo", "dock", "wander", "compete", "battery",
                 "motors"]


def program_name(a):
    """The program's name from its image (NAME.elf) or host library (libNAME_host.so)."""
    base = os.path.basename(a.host_lib if a.host else a.elf)
    if base == "libeco_host.so":
        return "ecosystem"
    for prefix, suffix in (("lib", "_host.so"), ("", ".elf")):
        if base.startswith(prefix) and base.endswith(suffix):
            return base[len(prefix):len(base) - len(suffix)]
    return base


def main(argv=None):
    a = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        arena = load_arena(a.arena)
    except ArenaError as e:
        print(f"run.py: {e}", file=sys.stderr)
        return 2
    world = World(arena, a.seed)
    try:
        trace = open(a.trace, "w") if a.trace else None
        os.makedirs(a.out, exist_ok=True)
    except OSError as e:
        print(f"run.py: {e.filename}: {e.strerror}", file=sys.stderr)
        return 2
    rec = Recorder(world, trace=trace)
    mode = "host fast mode" if a.host else "emulated RoboCube, lockstep"
    program = program_name(a)
    view = a.view
    if view == "auto":
        view = "live" if sys.stdout.isatty() else "plain"
    title = f"{program}: {os.path.basename(a.arena)}, seed {a.seed}, {mode}"
    print(f"{title}: {a.seconds:g} s of virtual time", flush=True)
    shown = {"live": lambda: LiveView(title), "plain": PlainProgress,
             "none": None}[view]
    shown = shown() if shown else None
    wall0 = time.monotonic()
    first_line = []

    def on_console(line):
        """The robot's console, live: above the live view, or between the progress lines."""
        if not first_line:
            first_line.append(time.monotonic() - wall0)
        text = f"robot: {line}"
        if isinstance(shown, LiveView):
            shown.console_line(text)
        elif view != "none":
            print(text, flush=True)

    def on_runs(runs):
        rec.runs = runs

    on_step = shown.update if shown else None
    try:
        if shown:
            shown.__enter__()
        if a.host:
            from hostmode import run_host
            run_host(world, rec, a.host_lib, a.seed, a.seconds, a.step_ms / 1000.0, on_step,
                     on_console, on_runs)
            err = ""
        else:
            from cosim import run_emulated
            names = ECO_PROCESSES
            err = run_emulated(world, rec, a.qemu, a.elf, names, a.seconds,
                               int(round(a.step_ms * 1e6)), on_step, on_console, on_runs)
    except KeyboardInterrupt:
        print("run.py: interrupted", file=sys.stderr)
        return 1
    except Exception as e:                   # the emulator or QMP failed
        print(f"run.py: {type(e).__name__}: {e}", file=sys.stderr)
        return 1
    finally:
        if shown:
            if isinstance(shown, LiveView):
                shown.update(world, rec, force=True)
            shown.__exit__(None, None, None)
    wall = time.monotonic() - wall0
    if trace:
        trace.close()
    s = rec.summary()
    s.update({"program": program, "mode": "host" if a.host else "emulated", "seed": a.seed,
              "arena": a.arena, "wall_s": round(wall, 2),
              "real_time_factor": round(world.t / wall, 2) if wall else None,
              "first_console_line_s": round(first_line[0], 2) if first_line else None,
              "program_status_lines": rec.status_lines})
    png = os.path.join(a.out, "ecosystem.png")
    with open(os.path.join(a.out, "summary.json"), "w") as f:
        json.dump(s, f, indent=1)
    # QEMU warns once that no virtual timer is armed: that is the machine
    # sitting paused (-S, and at each lockstep stop), not a problem.
    err = "\n".join(ln for ln in (err or "").splitlines()
                    if "icount sleep disabled and no active timers" not in ln)
    if err.strip():
        print("emulator stderr:\n" + err.strip(), file=sys.stderr, flush=True)
    # The summary and the digest first: drawing is the last thing that can fail.
    print("\n".join(summary_lines(s, mode, program)))
    print(f"  wall time:       {wall:.1f} s ({s['real_time_factor']}x real time)")
    print(f"trajectory sha256: {s['trajectory_sha256']}", flush=True)
    try:
        save_picture(rec, png, title)
    except Exception as e:                   # matplotlib, the disk: the run itself is kept
        print(f"run.py: picture not drawn: {type(e).__name__}: {e}", file=sys.stderr)
        return 1
    print(f"picture: {os.path.abspath(png)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
