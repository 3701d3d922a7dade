"""The CPU32 compiler runtime and C library on the emulated board, against the host.

apps/rtcheck computes rt_vectors.c's vectors on the board (conversions between
integers and float/double, signed and unsigned, 32 and 64 bits, with edge values;
float and double arithmetic and comparisons, NaN included; 64-bit multiplication,
shifts, division and modulo by small divisors and by divisors of 2^32 and more)
and prints each result's bits; the host runs the same file natively. Then
rt_libc.c through newlib (printf's conversions, snprintf, string.h, stdlib.h,
float libm), and dt() and (float)value(q) from a running PDL process. Before the CPU32 runtime, the
first int-to-float conversion stopped the board with an illegal-instruction or
line-F exception.

Environment (make check-rtcheck): BSCHED_QEMU, FW_DIR, RTCHECK_HOST.
"""
import os
import re
import struct
import subprocess
from pathlib import Path

import pytest

import robocube_emu

ROOT = Path(__file__).resolve().parents[3]
FW = Path(os.environ.get("FW_DIR", ROOT / "build" / "firmware"))
HOST = Path(os.environ.get("RTCHECK_HOST", ROOT / "build" / "tests" / "rtcheck_host"))
ICOUNT = "shift=8,sleep=off"
PDL_HZ = 100
CHECK_CYCLES = 8
VALUE_START = -16777215


@pytest.fixture(scope="module")
def board_lines():
    elf = FW / "rtcheck" / "rtcheck.elf"
    assert elf.is_file(), f"missing {elf} (make firmware APP=rtcheck)"
    lines = []
    with robocube_emu.Machine(kernel=str(elf), extra_args=["-icount", ICOUNT]) as m:
        while not lines or lines[-1] != "RT end":
            line = m.console.read_until(b"\n", timeout=30).decode("latin-1").rstrip("\r\n")
            # A CPU exception report ends in "*** halted": fail at once, with the report.
            assert not line.startswith("*** EXCEPTION"), line
            lines.append(line)
    return [line for line in lines if line.startswith(("RT ", "RTP ", "RTM "))]


@pytest.fixture(scope="module")
def host_lines():
    assert HOST.is_file(), f"missing {HOST}"
    out = subprocess.run([str(HOST)], check=True, capture_output=True, text=True).stdout
    return [line.rstrip() for line in out.splitlines()]


def f32(x):
    """x rounded to the nearest float32 (ties to even), as a Python float."""
    return struct.unpack(">f", struct.pack(">f", x))[0]


def f32_bits(x):
    return struct.unpack(">I", struct.pack(">f", x))[0]


def vector_lines(lines):
    return [line for line in lines if line.startswith("RT ")
            and not re.match(r"RT (dt|value_float|end|libc|malloc)\b", line)]


def test_vectors_match_host(board_lines, host_lines):
    board, host = vector_lines(board_lines), vector_lines(host_lines)
    assert host[-1].startswith("RT done ") and int(host[-1].split()[2]) > 100
    assert len(board) == len(host), (len(board), len(host))
    wrong = [(h, b) for h, b in zip(host, board) if h != b]
    assert not wrong, f"{len(wrong)} of {len(host)} differ (host, board): {wrong[:10]}"


def test_printf_string_and_stdlib_match_host(board_lines, host_lines):
    """newlib's printf (%d %u %ld %lld %x %o %s %c %f %e %g, widths, flags),
    snprintf, string.h, strtol/atoi/abs/qsort: the same text as the host's C library."""
    board = [line for line in board_lines if line.startswith("RTP ")]
    host = [line for line in host_lines if line.startswith("RTP ")]
    assert len(host) > 30 and len(board) == len(host), (len(board), len(host))
    wrong = [(h, b) for h, b in zip(host, board) if h != b]
    assert not wrong, f"{len(wrong)} of {len(host)} differ (host, board): {wrong[:6]}"
    kinds = {line.split()[1] for line in host}
    assert {"d", "u", "ld", "lld", "f", "s", "snprintf", "string", "stdlib", "qsort", "puts"} <= kinds
    count = [line for line in board_lines if line.startswith("RT libc ")]
    assert count and int(count[0].split()[2]) == len(host) + len(
        [line for line in host_lines if line.startswith("RTM ")])


def test_float_libm_within_two_ulp_of_host(board_lines, host_lines):
    """sinf, cosf, atan2f, sqrtf, fabsf: neither C library rounds all of them
    correctly, so each result may differ from the host's by 2 units in the last place;
    sqrtf and fabsf are exact in IEEE 754 and must be equal."""
    board = [line.split() for line in board_lines if line.startswith("RTM ")]
    host = [line.split() for line in host_lines if line.startswith("RTM ")]
    assert len(host) == 35 and len(board) == len(host)
    for (_, name, index, hbits), (_, bname, bindex, bbits) in zip(host, board):
        assert (name, index) == (bname, bindex)
        h, b = int(hbits, 16), int(bbits, 16)
        allowed = 0 if name in ("sqrtf", "fabsf") else 2
        assert (h >> 31) == (b >> 31) and abs(h - b) <= allowed, (name, index, hbits, bbits)


def test_vectors_cover_what_the_issue_names(host_lines):
    names = {line.split()[1] for line in vector_lines(host_lines)[:-1]}
    for needed in ("i32_to_float", "u32_to_float", "float_to_i32", "float_to_u32",
                   "i64_div", "i64_mod", "u64_div", "u64_mod", "double_to_i32"):
        assert needed in names


def test_dt_is_float_seconds(board_lines):
    dts = [line.split() for line in board_lines if line.startswith("RT dt ")]
    assert len(dts) == CHECK_CYCLES
    period_us = 1_000_000 // PDL_HZ
    for _, _, cycle, bits, usecs in dts:
        us = int(usecs)
        # The cycle rate is whole kernel ticks, so the period is within a tick of 10 ms.
        assert abs(us - period_us) <= 1000, (cycle, us)
        expected = f32_bits(f32(us) * f32(1e-6))    # (float)us * 1e-6f, one rounding
        assert int(bits, 16) == expected, (cycle, bits, hex(expected), us)
    assert int(dts[0][4]) > 0


def test_float_of_an_integer_quantity(board_lines):
    vals = [line.split() for line in board_lines if line.startswith("RT value_float ")]
    assert len(vals) == CHECK_CYCLES
    for _, _, cycle, bits in vals:
        expected = f32_bits(float(VALUE_START - int(cycle)))   # rounds -16777217 to even
        assert int(bits, 16) == expected, (cycle, bits, hex(expected))


def test_malloc_and_console_input():
    """malloc from the board's heap (ENOMEM past it), and stdin: fgets and getchar
    read console lines, edited and echoed by the console driver."""
    elf = FW / "rtcheck" / "rtcheck.elf"
    with robocube_emu.Machine(kernel=str(elf), extra_args=["-icount", ICOUNT]) as m:
        text = m.console.read_until(b"RT input?", timeout=60).decode("latin-1")
        assert "RT malloc small=1 huge_refused=1 enomem=1" in text, text[-500:]
        m.console_write_taken(b"robot 42\r")
        m.console_write_taken(b"x\r")
        text = m.console.read_until(b"getchar=", timeout=20).decode("latin-1")
        text += m.console.read_until(b"\n", timeout=10).decode("latin-1")
    # getchar reads the next line's first character: 'x' (120).
    assert "RT input [robot 42] getchar=120" in text, text
