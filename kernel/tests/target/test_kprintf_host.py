"""The target's printf formatter (kernel/lib/kprintf.c) is plain C: build it
for the host and compare each case with what C printf prints for it."""
import os
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
BUILD = Path(os.environ.get("FW_DIR", ROOT / "build" / "firmware")) / "host"


def test_kprintf_formats_like_printf():
    BUILD.mkdir(parents=True, exist_ok=True)
    exe = BUILD / "kprintf_cases"
    cc = os.environ.get("HOST_CC", "cc")
    # UBSan: a va_arg of the wrong width or an overflow in the formatter aborts the run.
    subprocess.run([cc, "-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wshadow",
                    "-Werror", "-Wno-format-extra-args", "-fsanitize=undefined",
                    "-fno-sanitize-recover=all",
                    f"-I{ROOT}", "-o", str(exe),
                    str(ROOT / "kernel/tests/target/kprintf_cases.c"),
                    str(ROOT / "kernel/lib/kprintf.c")], check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    lines = out.splitlines()
    assert len(lines) == 22
    want = [
        ("%d", "0"), ("%d", "-1"), ("%d", "2147483647"), ("%d", "-2147483648"),
        ("%u", "4294967295"), ("%x", "deadbeef"), ("%X", "DEADBEEF"), ("%08x", "00001234"),
        ("%08lx", "00e00400"), ("%04x", "2704"), ("%5d|", "   42|"), ("%-5d|", "42   |"),
        ("%05d", "-0042"), ("%c%c", "ok"), ("%s", "p1.1"), ("%-6s|", "ab    |"),
        ("%6s|", "    ab|"), ("%*d", "   7"), ("100%%", "100%"), ("%lu ticks", "16 ticks"),
        ("cycle %lu: %s", "cycle 15: p1.2 p2.2"),
    ]
    for line, (fmt, text) in zip(lines, want):
        assert line.startswith(fmt + "|"), line
        body, count = line[len(fmt) + 1:].rsplit("|", 1)
        assert body == text, (fmt, body, text)
        assert int(count) == len(text), (fmt, count)
    assert lines[-1] == "trunc|trun|9"
