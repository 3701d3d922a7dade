"""Bad arena files and bad option values: each gets one line on stderr naming
the problem and exit status 2, never a traceback, and nothing is run. Also
what a run leaves when it is good: a --trace of plain numbers, and the summary
and the trajectory digest even when the picture cannot be drawn."""
import copy
import json
import os
import signal
import subprocess

import pytest

import run

from .conftest import ROOT, WORLD

DEFAULT = os.path.join(WORLD, "arenas", "default.json")
with open(DEFAULT) as _f:
    BASE = json.load(_f)


@pytest.fixture(autouse=True)
def bounded():
    """run.main runs in this process: a value that slipped through (inf
    seconds) would run for ever, so each test fails after 120 s instead."""
    def expired(signum, frame):
        raise TimeoutError("still running after 120 s")
    old = signal.signal(signal.SIGALRM, expired)
    signal.alarm(120)
    yield
    signal.alarm(0)
    signal.signal(signal.SIGALRM, old)


def edit(**changes):
    """The default arena with changes: key paths 'robot/axle_m' -> value (None deletes)."""
    def make():
        a = copy.deepcopy(BASE)
        for path, value in changes.items():
            *parents, last = path.split("__")
            d = a
            for p in parents:
                d = d[int(p)] if isinstance(d, list) else d[p]
            if value is None:
                del d[last]
            elif isinstance(d, list):
                d[int(last)] = value
            else:
                d[last] = value
        return json.dumps(a)
    return make


def raw(text):
    return lambda: text


# (id, arena text, what the one error line must name)
BAD_ARENAS = [
    ("not json", raw("{not json"), "not valid JSON"),
    ("empty file", raw(""), "not valid JSON"),
    ("a list", raw("[1, 2]"), "not of type 'object'"),
    ("missing size", edit(size=None), "'size' is a required property"),
    ("missing robot", edit(robot=None), "'robot' is a required property"),
    ("missing axle", edit(robot__axle_m=None), "'axle_m' is a required property"),
    ("missing battery key", edit(robot__battery__idle_w=None), "'idle_w' is a required"),
    ("zero axle", edit(robot__axle_m=0), "robot/axle_m"),
    ("zero capacity", edit(robot__battery__capacity_j=0), "robot/battery/capacity_j"),
    ("zero counts per metre", edit(robot__counts_per_m=0), "robot/counts_per_m"),
    ("zero light halfwidth", edit(robot__light_sensors__halfwidth_deg=0), "halfwidth_deg"),
    ("zero falloff", edit(robot__light_sensors__falloff_m=0), "falloff_m"),
    ("negative robot radius", edit(robot__radius=-0.12), "robot/radius"),
    ("size of three", edit(size=[4, 3, 1]), "size: [4, 3, 1] is too long"),
    ("size of one", edit(size=[4]), "size: [4] is too short"),
    ("size a string", edit(size="4x3"), "size: '4x3' is not of type 'array'"),
    ("size zero", edit(size=[0, 3]), "size/0"),
    ("start of two", edit(robot__start=[2.0, 0.6]), "robot/start"),
    ("start a number", edit(robot__start=2.0), "robot/start"),
    ("station a list", edit(station=[0.5, 0.5]), "station"),
    ("size infinite", raw(json.dumps(BASE).replace("[4.0, 3.0]", "[Infinity, 3.0]")),
     "Infinity is not a number"),
    ("size 1e999", raw(json.dumps(BASE).replace("[4.0, 3.0]", "[1e999, 3.0]")), "1e999"),
    ("size NaN", raw(json.dumps(BASE).replace("[4.0, 3.0]", "[NaN, 3.0]")), "NaN is not a number"),
    ("obstacle neither circle nor box", edit(obstacles=[{"disc": [1, 1, 0.1]}]), "obstacles/0"),
    ("circle of negative radius", edit(obstacles=[{"circle": [1, 1, -0.2]}]), "obstacles/0"),
    ("degenerate box", edit(obstacles=[{"box": [1, 1, 1, 2]}]), "obstacles/0/box"),
    ("wall of zero length", edit(walls=[[1, 1, 1, 1]]), "walls/0"),
    ("wall of three numbers", edit(walls=[[1, 1, 2]]), "walls/0"),
    ("unknown key", edit(robot__radus=0.1), "'radus' was unexpected"),
    ("analog input 24", edit(wiring__ain_battery=24), "wiring/ain_battery"),
    ("charge above 1", edit(robot__battery__start_soc=1.5), "start_soc"),
    ("start outside", edit(robot__start=[5.0, 0.6, 0.0]), "start is not inside"),
    ("start in the wall", edit(robot__start=[0.05, 0.6, 0.0]), "start is not inside"),
]


@pytest.mark.parametrize("text, names", [b[1:] for b in BAD_ARENAS], ids=[b[0] for b in BAD_ARENAS])
def test_bad_arena_is_one_error_line_and_exit_2(tmp_path, capsys, host_lib, text, names):
    arena = tmp_path / "arena.json"
    arena.write_text(text())
    out = tmp_path / "out"
    rc = run.main(["--host", "--host-lib", host_lib, "--arena", str(arena), "--seconds", "1",
                   "--view", "none", "--out", str(out)])
    cap = capsys.readouterr()
    assert rc == 2
    lines = cap.err.splitlines()
    assert len(lines) == 1, cap.err
    assert lines[0].startswith(f"run.py: {arena}: "), lines[0]
    assert names in lines[0], lines[0]
    assert cap.out == ""                    # nothing ran
    assert not out.exists()


def test_the_default_arena_passes_the_schema():
    from world import load_arena
    assert load_arena(DEFAULT)["size"] == [4.0, 3.0]


BAD_OPTIONS = [
    (["--seed", "-1"], "--seed"),
    (["--seed", "abc"], "--seed"),
    (["--seed", str(2**32)], "--seed"),
    (["--seed", "1.5"], "--seed"),
    (["--seconds", "inf"], "--seconds"),
    (["--seconds", "nan"], "--seconds"),
    (["--seconds", "0"], "--seconds"),
    (["--seconds", "-1"], "--seconds"),
    (["--seconds", "abc"], "--seconds"),
    (["--seconds", "1e9"], "--seconds"),
    (["--step-ms", "0"], "--step-ms"),
    (["--step-ms", "inf"], "--step-ms"),
    (["--view", "fancy"], "--view"),
]


@pytest.mark.parametrize("args, names", BAD_OPTIONS, ids=[" ".join(a) for a, _ in BAD_OPTIONS])
def test_bad_option_is_one_usage_line_and_exit_2(tmp_path, capsys, host_lib, args, names):
    with pytest.raises(SystemExit) as e:
        run.main(["--host", "--host-lib", host_lib, "--out", str(tmp_path / "out"), *args])
    cap = capsys.readouterr()
    assert e.value.code == 2
    lines = cap.err.splitlines()
    assert len(lines) == 1, cap.err
    assert lines[0].startswith("run.py: argument " + names), lines[0]
    assert "(usage: run.py " in lines[0]
    assert cap.out == ""


def bad_command_lines(tmp_path, host_lib):
    """Command lines wrong as a whole (not one option's value): what each must say."""
    text = tmp_path / "not_a_library.so"
    text.write_text("not a library\n")
    out = str(tmp_path / "out")
    return [
        (["--host", "--out", out], "--host needs --host-lib"),
        (["--out", out], "the emulated mode needs --elf and --qemu"),
        (["--elf", str(tmp_path / "none.elf"), "--qemu", "/bin/true", "--out", out],
         "none.elf: no such file"),
        (["--elf", str(text), "--qemu", str(tmp_path / "no-qemu"), "--out", out],
         "no-qemu: no such file"),
        (["--host", "--host-lib", str(tmp_path / "none.so"), "--out", out], "none.so: no such file"),
        (["--host", "--host-lib", str(text), "--out", out], "not a loadable library"),
        (["--host", "--host-lib", host_lib, "--out", out, "--frobnicate"],
         "unrecognized arguments: --frobnicate"),
        (["--host", "--host-lib", host_lib, "--out", out, "--step-ms", "abc"], "--step-ms"),
        (["--host", "--host-lib", host_lib, "--out", out, "--arena"], "--arena: expected one argument"),
    ]


def test_bad_command_line_is_one_usage_line_and_exit_2(tmp_path, capsys, host_lib):
    for args, says in bad_command_lines(tmp_path, host_lib):
        with pytest.raises(SystemExit) as e:
            run.main(args)
        cap = capsys.readouterr()
        assert e.value.code == 2, args
        lines = cap.err.splitlines()
        assert len(lines) == 1 and lines[0].startswith("run.py: ") and says in lines[0], (args, cap.err)
        assert "(usage: run.py " in lines[0] and cap.out == "", (args, cap.out)


@pytest.mark.parametrize("where", ["trace", "out"])
def test_unwritable_trace_or_out_is_one_line_and_exit_2(tmp_path, capsys, host_lib, where):
    blocker = tmp_path / "a_file"
    blocker.write_text("")
    paths = {"trace": str(tmp_path / "trace.txt"), "out": str(tmp_path / "out")}
    paths[where] = str(blocker / "below")         # under a file: cannot be made
    rc = run.main(["--host", "--host-lib", host_lib, "--seconds", "1", "--view", "none",
                   "--out", paths["out"], "--trace", paths["trace"]])
    cap = capsys.readouterr()
    assert rc == 2
    lines = cap.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("run.py: ") and "below" in lines[0], cap.err


def touching_an_obstacle(tmp_path):
    """The default arena with the robot's disc overlapping the round obstacle
    (at 2.0, 1.5, radius 0.18): the first step pushes it out."""
    a = copy.deepcopy(BASE)
    a["robot"]["start"] = [2.0, 1.75, 1.5708]
    path = tmp_path / "touching.json"
    path.write_text(json.dumps(a))
    return str(path)


def test_trace_holds_plain_numbers_after_collisions(tmp_path, capsys, host_lib):
    trace = tmp_path / "trace.txt"
    out = tmp_path / "out"
    rc = run.main(["--host", "--host-lib", host_lib, "--arena", touching_an_obstacle(tmp_path),
                   "--seconds", "4", "--view", "none", "--out", str(out), "--trace", str(trace)])
    capsys.readouterr()
    assert rc == 0
    with open(out / "summary.json") as f:
        s = json.load(f)
    assert s["collisions"]["obstacle"] >= 1    # the pose went through the collision code
    lines = trace.read_text().splitlines()
    assert len(lines) == 512                   # 4 s of 7.8125 ms steps
    for line in lines:
        t, *rest = line.split()
        int(t)
        assert len(rest) == 4 and all(float(v) == float(v) for v in rest), line


def test_summary_and_digest_survive_a_picture_that_cannot_be_drawn(tmp_path, capsys, host_lib):
    out = tmp_path / "out"
    (out / "ecosystem.png").mkdir(parents=True)     # a folder where the picture goes
    rc = run.main(["--host", "--host-lib", host_lib, "--seconds", "2", "--view", "none",
                   "--out", str(out)])
    cap = capsys.readouterr()
    assert rc == 1
    with open(out / "summary.json") as f:
        s = json.load(f)
    assert f"trajectory sha256: {s['trajectory_sha256']}" in cap.out
    assert "survived" in cap.out
    err = cap.err.splitlines()
    assert len(err) == 1 and err[0].startswith("run.py: picture not drawn: "), cap.err


MAKE_RUN_BAD = [
    ("SEED=-5", "SEED='-5': not a whole number"),
    ("SEED=abc", "SEED='abc': not a whole number"),
    ("SEED=4294967296", "SEED=4294967296: out of range 0..4294967295"),
    ("SIM_SECONDS=inf", "SIM_SECONDS='inf': not a whole number"),
    ("SIM_SECONDS=0", "SIM_SECONDS=0: out of range 1..86400"),
    ("SIM_SECONDS=", "SIM_SECONDS='': not a whole number"),
]


@pytest.mark.parametrize("option, names", MAKE_RUN_BAD, ids=[o for o, _ in MAKE_RUN_BAD])
def test_make_run_bad_value_is_one_line_and_exit_2(option, names):
    # a session of its own: on a timeout the whole group goes, the emulator too
    proc = subprocess.Popen(["make", "--no-print-directory", "run", option], cwd=ROOT,
                            stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        pytest.fail(f"make run {option} still running after 60 s")
    assert proc.returncode == 2
    lines = err.splitlines()
    assert len(lines) == 1, err
    assert f"make run: {names}" in lines[0] and "usage: make run " in lines[0], lines[0]
    assert "Traceback" not in out
