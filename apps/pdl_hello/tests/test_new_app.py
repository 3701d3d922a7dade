"""make new-app: a new PDL program from the template (apps/pdl_hello) builds and
runs on the emulated board at once: its main declares a quantity, adds two
processes and calls run_pdl(), and the cycle thread runs them. Bad names are
refused with one line and exit 2, and nothing is created.

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


def test_new_app_runs_its_processes_on_the_board(new_app):
    r = make("new-app", f"NAME={NAME}")
    assert r.returncode == 0, r.stderr
    assert (new_app / "main.c").read_text() == (ROOT / "apps/pdl_hello/main.c").read_text()
    assert (new_app / "app.mk").read_text().count("\n") == 1     # one comment line
    r = make("firmware", f"APP={NAME}")
    assert r.returncode == 0, r.stdout + r.stderr
    elf = ROOT / "build" / "firmware" / NAME / f"{NAME}.elf"
    with robocube_emu.Machine(kernel=str(elf), extra_args=["-icount", "shift=8,sleep=off"]) as m:
        text = m.console.read_until(b"t=2 s", timeout=30).decode("latin-1")
        text += m.console.read_until(b"\n", timeout=10).decode("latin-1")
    lines = re.findall(r"t=(\d) s heading=(-?\d+) cycles=(\d+) runs=(\d+) overruns=(\d+)", text)
    assert len(lines) == 2, text
    for second, heading, cycles, runs, overruns in lines:
        # 100 Hz: about 100 cycles a second; wander every cycle, settle every 4th.
        assert 95 * int(second) <= int(cycles) <= 105 * int(second), text
        assert int(runs) == int(cycles) + (int(cycles) + 3) // 4, text
        assert int(overruns) == 0 and 0 < int(heading) <= 1000, text


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
