"""Shared fixtures of the emu tests (board core and I/O).

machine      a robocube machine under qtest, software watchdog already off
raw_machine  the same straight out of reset (watchdog on, SYPCR unwritten)
build_elf    assembles a CPU32 test program into an ELF for the flash
"""
import os
import shutil
import subprocess

import pytest

import robocube_emu

CROSS = os.environ.get("BSCHED_M68K_PREFIX", "m68k-linux-gnu-")


@pytest.fixture
def machine():
    with robocube_emu.start() as m:
        yield m


@pytest.fixture
def raw_machine():
    with robocube_emu.start(disable_watchdog=False) as m:
        yield m


@pytest.fixture
def build_elf(tmp_path):
    """build_elf(source) -> path of an ELF linked at the flash (0xE00000).
    The source is GNU as syntax for -mcpu=cpu32; its first bytes are the
    vector table (flash offset 0)."""
    if not shutil.which(CROSS + "as"):
        pytest.fail(f"{CROSS}as not found: run ci/setup m68k")

    def build(source, name="prog"):
        src = tmp_path / f"{name}.S"
        obj = tmp_path / f"{name}.o"
        elf = tmp_path / f"{name}.elf"
        src.write_text(source)
        subprocess.run([CROSS + "as", "-mcpu=cpu32", "-o", str(obj), str(src)],
                       check=True, capture_output=True, text=True)
        # -N: one segment starting exactly at the flash, no ELF header in it.
        subprocess.run([CROSS + "ld", "-N", "-e", "0xE00000", "-Ttext=0xE00000",
                        "-o", str(elf), str(obj)],
                       check=True, capture_output=True, text=True)
        return elf
    return build
