import pytest

from iotest_board import IoTestBoard


@pytest.fixture(scope="module")
def board():
    b = IoTestBoard()
    try:
        yield b
    finally:
        b.close()
