import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "emu", "tests"))

from iotest_board import IoTestBoard  # noqa: E402


@pytest.fixture(scope="module")
def board():
    b = IoTestBoard()
    try:
        yield b
    finally:
        b.close()
