"""The ecosystem end to end, through run.py (what make run starts): the
robot program on the emulated board in lockstep with the world, and the same
program on the host (fast mode). Goals (emu/world/README.md): survival with recharges
and no wall collisions after the first minute, reproducible trajectories."""
import json
import os
import subprocess
import sys

import pytest

from .conftest import WORLD

RUN = os.path.join(WORLD, "run.py")
# make check runs a shorter survival span on the board; make eco-survival the full 600 s.
# The start charge lasts about 170 s of driving (90 % at 0.52 % a second,
# measured), so 180 s are not survived without a recharge: when the robot gets hungry
# (about 70 s in) and how long it then searches depends on the whole
# trajectory, which follows every instruction count (a 120 s span passed or
# failed with the console driver's cost).
SURVIVAL_S = float(os.environ.get("ECO_SURVIVAL_SECONDS", "180"))


def run(tmp_path, *args, expect=0):
    out = tmp_path / "out"
    p = subprocess.run([sys.executable, RUN, "--view", "plain", "--out", str(out), *args],
                       capture_output=True, text=True, timeout=1800)
    assert p.returncode == expect, p.stdout + p.stderr
    summary = None
    if expect == 0:
        with open(out / "summary.json") as f:
            summary = json.load(f)
        assert (out / "ecosystem.png").stat().st_size > 10_000
        assert f"trajectory sha256: {summary['trajectory_sha256']}" in p.stdout
    return p, summary


def emulated(tmp_path, qemu, elf, lib, seconds, seed, *extra):
    return run(tmp_path, "--elf", elf, "--qemu", qemu, "--host-lib", lib,
               "--seconds", str(seconds), "--seed", str(seed), *extra)


def first_difference(path_a, path_b):
    with open(path_a) as fa, open(path_b) as fb:
        for n, (la, lb) in enumerate(zip(fa, fb)):
            if la != lb:
                return f"step {n}: {la.strip()} / {lb.strip()}"
    return None


def test_same_seed_same_trajectory_other_seed_another(tmp_path, qemu, eco_elf, host_lib):
    ta, tb = tmp_path / "a.trace", tmp_path / "b.trace"
    p1, a = emulated(tmp_path / "a", qemu, eco_elf, host_lib, 20, 1, "--trace", str(ta))
    _, b = emulated(tmp_path / "b", qemu, eco_elf, host_lib, 20, 1, "--trace", str(tb))
    _, c = emulated(tmp_path / "c", qemu, eco_elf, host_lib, 20, 2)
    assert a["trajectory_sha256"] == b["trajectory_sha256"], first_difference(ta, tb)
    assert a["trajectory_sha256"] != c["trajectory_sha256"]
    assert a["distance_m"] > 1.0                   # the robot moved
    assert a["program_status_lines"] >= 70         # 4 status lines per second from the firmware
    assert "t=  10.0s" in p1.stdout                              # plain progress lines


def check_goals(s, seconds, min_recharges):
    assert s["alive"], s
    assert seconds - 0.01 <= s["survived_s"] <= seconds
    assert s["recharges"] >= min_recharges, s
    assert s["wall_collisions_after_60s"] == 0, s
    assert s["overruns"] == 0, s


def test_survival_host_fast_mode_ten_minutes(tmp_path, host_lib):
    _, s = run(tmp_path, "--host", "--host-lib", host_lib, "--seconds", "600", "--seed", "3")
    check_goals(s, 600, 2)
    assert s["competitor_hits"] >= 1
    assert s["real_time_factor"] > 5


def test_survival_emulated_and_alike_on_the_host(tmp_path, qemu, eco_elf, host_lib):
    """The program on the board survives; the same program on the host,
    same world and seed, behaves the same way qualitatively: it survives,
    finds the station when hungry and recharges as often, over a similar path."""
    _, e = emulated(tmp_path / "e", qemu, eco_elf, host_lib, SURVIVAL_S, 3)
    _, h = run(tmp_path / "h", "--host", "--host-lib", host_lib, "--seconds", str(SURVIVAL_S),
               "--seed", "3")
    minimum = 2 if SURVIVAL_S >= 600 else 1
    print("board:", json.dumps(e))
    print("host: ", json.dumps(h))
    check_goals(e, SURVIVAL_S, minimum)
    check_goals(h, SURVIVAL_S, minimum)
    assert abs(h["recharges"] - e["recharges"]) <= 1
    assert abs(h["distance_m"] - e["distance_m"]) < 0.4 * h["distance_m"]


def test_bad_input_is_refused(tmp_path, host_lib):
    p, _ = run(tmp_path, "--host", "--host-lib", host_lib, "--seconds", "-1", expect=2)
    assert "argument --seconds: -1: out of range" in p.stderr
    p, _ = run(tmp_path, "--host", "--host-lib", host_lib, "--arena", str(tmp_path / "no.json"),
               expect=2)
    assert "no.json" in p.stderr
    p, _ = run(tmp_path, "--elf", str(tmp_path / "none.elf"), "--qemu", "/bin/true", expect=2)
    assert "none.elf: no such file" in p.stderr
