"""make new-app: a new PDL program from the template (apps/pdl_hello), edited
as pdl/README.md "Write your first behaviour" says and with one more process
(the probe), runs its processes three ways: on the emulated board alone, on
the board in the arena (make run WORLD=default, twice: the same seed gives
the same trajectory digest) and on the host runtime in the arena (HOST=1);
each time main's report and the summary show the processes' runs. Bad names
are refused with one line and exit 2, and nothing is created.

Environment (make check-new-app): BSCHED_QEMU.
"""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

import robocube_emu

ROOT = Path(__file__).resolve().parents[3]
NAME = "zz_new_app_check"


def make(*args):
    return subprocess.run(["make", "--no-print-directory", "-C", str(ROOT), *args],
                          capture_output=True, text=True, timeout=600)


@pytest.fixture
def new_app():
    app, build = ROOT / "apps" / NAME, ROOT / "build" / "firmware" / NAME
    shutil.rmtree(app, ignore_errors=True)
    try:
        yield app
    finally:
        shutil.rmtree(app, ignore_errors=True)
        shutil.rmtree(build, ignore_errors=True)


# The process the test adds to the template: it counts its own runs into a
# quantity, so a run shows it ran both in main's report (its run count) and
# in the arena's summary.
PROBE = """
static struct pdl_quantity probe_count;
static void probe(void)
{
    add_value(probe_count, 1);
}
"""


def readme_behaviour():
    """pdl/README.md "Write your first behaviour": its C block, as the part
    before main and the lines for main."""
    text = (ROOT / "pdl" / "README.md").read_text()
    section = text.split("## Write your first behaviour", 1)[1].split("\n## ", 1)[0]
    block = re.search(r"```c\n(.*?)```", section, re.S).group(1)
    top, in_main = block.split("    /* in main, before run_pdl(): */\n")
    return top, in_main


def add_readme_behaviour(app):
    """Edits the new app as the README tells its reader to."""
    top, in_main = readme_behaviour()
    src = (app / "main.c").read_text()
    assert src.count("int main(void)\n{") == 1 and src.count("    r = run_pdl();") == 1
    src = src.replace("int main(void)\n{", top + "\nint main(void)\n{", 1)
    src = src.replace("    r = run_pdl();", in_main + "    r = run_pdl();", 1)
    (app / "main.c").write_text(src)


def add_probe(app):
    """Adds the probe process to the template's main.c."""
    src = (app / "main.c").read_text()
    src = src.replace("int main(void)\n{", PROBE + "\nint main(void)\n{", 1)
    src = src.replace("    r = run_pdl();",
                      "    add_quantity(&probe_count, 0, 1000000, 0);\n"
                      "    add_process_pv(probe, 2);\n    r = run_pdl();", 1)
    assert src.count("probe") == 5, src
    (app / "main.c").write_text(src)


REPORT = re.compile(r"t=(\d+) s wheels=(-?\d+),(-?\d+) runs: cruise=(\d+) avoid=(\d+) "
                    r"seek=(\d+) probe=(\d+)")


def arena_run(app_name, *extra):
    r = make("run", f"APP={app_name}", "SIM_SECONDS=4", "SEED=3", *extra)
    assert r.returncode == 0, r.stdout + r.stderr
    reports = REPORT.findall(r.stdout)
    runs = re.search(r"process runs: +cruise (\d+) avoid (\d+) seek (\d+) probe (\d+)", r.stdout)
    digest = re.search(r"trajectory sha256: ([0-9a-f]{64})", r.stdout)
    assert reports and runs and digest, r.stdout
    return r.stdout, reports, [int(n) for n in runs.groups()], digest.group(1)


def test_new_app_runs_its_processes_on_the_board(new_app):
    r = make("new-app", f"NAME={NAME}")
    assert r.returncode == 0, r.stderr
    assert (new_app / "main.c").read_text() == (ROOT / "apps/pdl_hello/main.c").read_text()
    assert (new_app / "app.mk").read_text().count("\n") == 1     # one comment line
    add_readme_behaviour(new_app)
    add_probe(new_app)
    r = make("firmware", f"APP={NAME}")
    assert r.returncode == 0, r.stdout + r.stderr
    # quiet build lines: one short line a file, no compiler command ...
    assert f"  CC      apps/{NAME}/main.c\n" in r.stdout, r.stdout
    assert f"  LD      build/firmware/{NAME}/{NAME}.elf\n" in r.stdout, r.stdout
    assert "m68k-linux-gnu-gcc" not in r.stdout, r.stdout
    # ... and with V=1 the full commands
    (new_app / "main.c").touch()
    r = make("firmware", f"APP={NAME}", "V=1")
    assert r.returncode == 0, r.stdout + r.stderr
    assert re.search(rf"m68k-linux-gnu-gcc .* -c -o \S+/{NAME}/obj/apps/{NAME}/main\.c\.o apps/{NAME}/main\.c",
                     r.stdout), r.stdout
    assert "  CC      " not in r.stdout, r.stdout
    elf = ROOT / "build" / "firmware" / NAME / f"{NAME}.elf"
    with robocube_emu.Machine(kernel=str(elf), extra_args=["-icount", "shift=8,sleep=off"]) as m:
        text = m.console.read_until(b"t=2 s", timeout=30).decode("latin-1")
        text += m.console.read_until(b"\n", timeout=10).decode("latin-1")
    lines = REPORT.findall(text)
    assert len(lines) == 2, text
    for second, left, right, cruise, avoid, seek, probe in lines:
        # 1024 Hz / 10 ticks = 102.4 Hz: about 102 cycles a second; cruise every
        # cycle, avoid every second one, the probe every fourth.
        cycles = int(cruise)
        assert 97 * int(second) <= cycles <= 107 * int(second), text
        assert int(avoid) == (cycles + 1) // 2 and int(probe) == (cycles + 3) // 4, text
        assert int(seek) == cycles, text
        # nothing connected: no infrared, so both wheels where cruise's pull
        # (400 - v) / 8 stops, 393
        assert int(left) == int(right) == 393, text

    # In the arena, on the board: the probe ran (its count in main's report
    # and in the summary), and the same seed gives the same trajectory twice.
    out, reports, runs, digest = arena_run(NAME, "WORLD=default")
    assert "emulated RoboCube, lockstep" in out
    assert runs[3] > 0 and abs(runs[0] - 4 * runs[3]) <= 4 and runs[2] == runs[0], out
    assert int(reports[-1][6]) > 0, out
    # the world moved the robot: the wheels differ once the infrared sees something,
    # or at least it travelled
    assert float(re.search(r"distance: +([0-9.]+) m", out).group(1)) > 0.2, out
    _, _, runs2, digest2 = arena_run(NAME, "WORLD=default")
    assert digest2 == digest and runs2 == runs

    # On the host, in the same arena: the probe ran there too, at the same rate.
    out, reports, runs, host_digest = arena_run(NAME, "HOST=1")
    assert "host fast mode" in out
    assert runs[3] > 0 and runs[0] == 4 * runs[3] and runs[2] == runs[0], out
    assert int(reports[-1][6]) > 0, out
    assert float(re.search(r"distance: +([0-9.]+) m", out).group(1)) > 0.2, out


@pytest.mark.parametrize("name, why", [
    ("", "lower-case C identifier"),
    ("Robot", "lower-case C identifier"),
    ("my-robot", "lower-case C identifier"),
    ("x" * 33, "lower-case C identifier"),
    ("pdl_hello", "exists already"),
    ("x'; touch pwned; '", "lower-case C identifier"),
])
def test_bad_names_are_refused(name, why):
    before = sorted(p.name for p in (ROOT / "apps").iterdir())
    r = make("new-app", f"NAME={name}")
    assert r.returncode == 2
    assert why in r.stderr.splitlines()[0], r.stderr
    assert sorted(p.name for p in (ROOT / "apps").iterdir()) == before
    assert not (ROOT / "pwned").exists()
