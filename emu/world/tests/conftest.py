"""Fixtures of the ecosystem tests (suite `eco`, make check-eco).

Paths come from the environment set by apps/ecosystem/app.mk: BSCHED_QEMU (the board
binary), ECO_ELF (the ecosystem firmware), ECO_HOST_LIB (the program built
for the host)."""
import os

import pytest

WORLD = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROOT = os.path.dirname(os.path.dirname(WORLD))


def _path(var, default):
    path = os.environ.get(var) or os.path.join(ROOT, default)
    if not os.path.exists(path):
        pytest.skip(f"{path} missing (run make check-eco)")
    return path


@pytest.fixture
def qemu():
    return _path("BSCHED_QEMU", "build/emu/qemu-system-m68k")


@pytest.fixture
def eco_elf():
    return _path("ECO_ELF", "build/firmware/ecosystem/ecosystem.elf")


@pytest.fixture
def host_lib():
    return _path("ECO_HOST_LIB", "build/world/libeco_host.so")


@pytest.fixture
def arena():
    from world import load_arena
    return load_arena(os.path.join(WORLD, "arenas", "default.json"))
