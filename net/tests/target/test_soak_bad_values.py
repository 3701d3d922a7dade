"""make net-soak and tools/netpeer/soak.py refuse every bad value before
anything starts: one line naming it with the usage, exit status 2."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]


@pytest.mark.parametrize("args, says", [
    (["BOARDS=0"], "BOARDS=0: out of range 1..4"),
    (["BOARDS=5"], "BOARDS=5: out of range 1..4"),
    (["BOARDS=two"], "BOARDS='two': not a whole number"),
    (["HOSTS=9"], "HOSTS=9: out of range 0..8"),
    (["HOSTS=-1"], "HOSTS='-1': not a whole number"),
    (["MESSAGES=0"], "MESSAGES=0: out of range 1..10000"),
    (["MESSAGES=1e3"], "MESSAGES='1e3': not a whole number"),
    (["SEED=-5"], "SEED='-5': not a whole number"),
    (["SEED=4294967296"], "SEED=4294967296: out of range"),
    (["LOSS=1.5"], "LOSS=1.5: out of range 0..1"),
    (["LOSS=abc"], "LOSS='abc': not a number 0..1"),
    (["LOSS=."], "LOSS='.': not a number 0..1"),
    (["LOSS=0.1.2"], "LOSS='0.1.2': not a number 0..1"),
    (["LOSS="], "LOSS='': not a number 0..1"),
    (["CORRUPT=-0.1"], "CORRUPT='-0.1': not a number 0..1"),
    (["CORRUPT=nan"], "CORRUPT='nan': not a number 0..1"),
    (["BYTE_ERRORS=2"], "BYTE_ERRORS=2: out of range 0..1"),
    (["FEC=maybe"], "FEC='maybe': use FEC=1"),
    (["BOARDS=1", "HOSTS=0"], "at least 2 stations"),
])
def test_bad_make_net_soak_values(args, says):
    r = subprocess.run(["make", "--no-print-directory", "-C", str(ROOT), "net-soak", *args],
                       capture_output=True, text=True, timeout=60, stdin=subprocess.DEVNULL)
    assert r.returncode == 2, r.stdout + r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and says in lines[0] and "usage: make net-soak" in lines[0], r.stderr
    assert r.stdout == ""


@pytest.mark.parametrize("args, says", [
    (["--boards", "5"], "--boards: 5 is not a number of boards (1..4)"),
    (["--boards", "x"], "--boards: 'x' is not a number"),
    (["--hosts", "9"], "--hosts: 9 is not a number of host peers (0..8)"),
    (["--messages", "0"], "--messages: 0 is not a number of messages"),
    (["--loss", "nan"], "--loss: nan is not a probability"),
    (["--corrupt", "-1"], "--corrupt: -1 is not a probability"),
    (["--noise", "x"], "--noise: 'x' is not a number"),
    (["--byte-errors", "1.01"], "--byte-errors: 1.01 is not a probability"),
    (["--seed", "-1"], "--seed: -1 is not a seed"),
    (["--timeout", "0"], "--timeout: 0 is not a number of seconds"),
    (["--timeout", "inf"], "--timeout: inf is not a number of seconds"),
    (["--linger", "0"], "--linger: 0 is not a linger time"),
    (["--boards", "1", "--no-host"], "at least 2 stations"),
    (["--elf", "/nonexistent.elf"], "no such file"),
    (["--frobnicate"], "unrecognized arguments"),
])
def test_bad_soak_options(args, says):
    r = subprocess.run([sys.executable, str(ROOT / "tools" / "netpeer" / "soak.py"), *args],
                       capture_output=True, text=True, timeout=60, stdin=subprocess.DEVNULL,
                       env=dict(os.environ))
    assert r.returncode == 2, r.stdout + r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and says in lines[0] and "usage: soak.py" in lines[0], r.stderr
