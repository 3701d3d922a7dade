"""Every quantity type (int8, int16, int32, uint8, uint16, float) has the same
semantics on the board and on the host: apps/pdl_types runs 1000 cycles on
the emulated board and on the host runtime, and the values its processes saw
in every cycle (printed, the float as its bits) are equal line for line.

Environment (make check-pdl-target): BSCHED_QEMU, FW_DIR, PDL_TYPES_HOST.
"""
import os
import subprocess
from pathlib import Path

import robocube_emu

ROOT = Path(__file__).resolve().parents[3]
FW = Path(os.environ.get("FW_DIR", ROOT / "build" / "firmware"))
HOST = os.environ.get("PDL_TYPES_HOST", str(ROOT / "build" / "pdl" / "pdl_types_host"))
CYCLES = 1000


def typed_lines(text):
    return [ln.strip() for ln in text.splitlines() if ln.startswith("TYPES ")]


def test_every_type_agrees_on_board_and_host_for_1000_cycles():
    host = subprocess.run([HOST], capture_output=True, text=True, timeout=60)
    assert host.returncode == 0, host.stderr
    want = typed_lines(host.stdout)
    assert len(want) == CYCLES + 1 and want[-1] == "TYPES done", host.stdout[-500:]
    elf = FW / "pdl_types" / "pdl_types.elf"
    with robocube_emu.Machine(kernel=str(elf), extra_args=["-icount", "shift=8,sleep=off"]) as m:
        text = m.console.read_until(b"TYPES done", timeout=120).decode("latin-1")
    got = typed_lines(text)
    assert len(got) == len(want), text[-500:]
    for g, w in zip(got, want):
        assert g == w, f"board: {g}\nhost:  {w}"
    # the run reached every type's bounds and values between them
    cols = list(zip(*(ln.split()[2:] for ln in want[:-1])))
    for name, col, low, high in (("int8", cols[0], "-128", "127"),
                                 ("uint8", cols[3], "0", "255"),
                                 ("uint16", cols[4], "1000", "65535")):
        assert low in col and high in col, name
        assert len(set(col)) > 100, name
    for name, col in (("int16", cols[1]), ("int32", cols[2]), ("float", cols[5])):
        assert len(set(col)) > 100, name
