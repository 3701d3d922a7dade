"""make run refuses every bad value of its variables before it builds or
starts anything: one line on stderr naming the variable and how to use it,
exit status 2."""
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]


@pytest.mark.parametrize("args, says", [
    (["APP=no_such_app"], "APP=no_such_app: no such image"),
    (["APP=pdl_demo", "HOST=2"], "HOST='2': use HOST=1"),
    (["APP=pdl_demo", "HOST=yes"], "HOST='yes': use HOST=1"),
    (["APP=pdl_demo", "HOST=1 1"], "HOST='1 1': use HOST=1"),
    (["APP=pdl_demo", "WORLD=nowhere"], "WORLD='nowhere': no such arena"),
    (["APP=pdl_demo", "WORLD=default default"], "no such arena"),
    (["APP=pdl_demo", "WORLD=../default"], "no such arena"),
    (["APP=pdl_demo", "HOST=1", "WORLD=none"], "WORLD=none has no host mode"),
    (["APP=netnode", "HOST=1"], "APP=netnode cannot run on the host"),
    (["APP=ecosystem", "WORLD=none"], "WORLD=none does not apply"),
    (["APP=pdl_demo", "SEED=-5"], "SEED='-5': not a whole number"),
    (["APP=pdl_demo", "SEED=4294967296"], "SEED=4294967296: out of range"),
    (["APP=pdl_hello", "WORLD=default", "SEED=abc"], "SEED='abc': not a whole number"),
    (["APP=pdl_hello", "HOST=1", "SIM_SECONDS=0"], "SIM_SECONDS=0: out of range"),
    (["APP=pdl_demo", "SIM_SECONDS=1.5"], "SIM_SECONDS='1.5': not a whole number"),
    (["APP=pdl_demo", "SIM_SECONDS="], "SIM_SECONDS='': not a whole number"),
    (["APP=pdl_hello", "RUN_SECONDS=0"], "RUN_SECONDS=0: out of range"),
    (["APP=pdl_hello", "RUN_SECONDS=-3"], "RUN_SECONDS='-3': not a whole number"),
    (["APP=pdl_hello", "RUN_SECONDS=abc"], "RUN_SECONDS='abc': not a whole number"),
    (["APP=pdl_demo", "RUN_SECONDS=86401"], "RUN_SECONDS=86401: out of range"),
])
def test_bad_make_run_values(args, says):
    r = subprocess.run(["make", "--no-print-directory", "-C", str(ROOT), "run", *args],
                       capture_output=True, text=True, timeout=60, stdin=subprocess.DEVNULL)
    assert r.returncode == 2, r.stdout + r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and says in lines[0], r.stderr
    assert r.stdout == "", r.stdout            # nothing built, nothing run
