"""Host interface of the I/O side: every documented QOM property exists with
the documented access, values round-trip, bad values are refused; the fast
binary outputs at 0xFE0000."""

import pytest

from io_support import FASTBIN, IO, TPU, board  # noqa: F401

READ_WRITE = ([(IO, f"ain{i}") for i in range(24)] +
              [(IO, "bio-in")] +
              [(f"{IO}/bio{i}", "input") for i in range(2)] +
              [(f"{IO}/adc{i}", f"ain{k}") for i in range(6) for k in range(4)] +
              [(TPU, "inputs")] + [(TPU, f"ch{c}-pin") for c in range(16)] +
              [(f"{IO}/motor{m}", p) for m in range(3)
               for p in ("encoder", "model-enabled", "max-speed", "time-constant-ms")] +
              [(f"{IO}/adc{i}", "nack") for i in range(6)] +
              [(f"{IO}/bio{i}", "nack") for i in range(2)] +
              [(f"{IO}/i2c-{x}", "bus-stuck") for x in "ab"])
READ_ONLY = ([(IO, f"aout{i}") for i in range(6)] +
             [(IO, f"aout{i}-enabled") for i in range(6)] +
             [(IO, p) for p in ("bio-out", "bio-pins", "fastbin", "duart-opr")] +
             [(f"{IO}/bio{i}", p) for i in range(2) for p in ("output", "pins", "int", "i2c-address")] +
             [(f"{IO}/adc{i}", p) for i in range(6) for p in ("aout", "aout-enabled", "control", "i2c-address")] +
             [(TPU, p) for p in ("pins", "tcr1-hz")] +
             [(TPU, f"ch{c}-{p}") for c in range(16) for p in ("duty", "pwm-high", "pwm-period")] +
             [(f"{IO}/motor{m}", p) for m in range(3)
              for p in ("speed", "duty", "direction", "dir-bits", "pwm-channel",
                        "encoder-a-channel", "encoder-b-channel")] +
             [(f"{IO}/i2c-{x}", p) for x in "ab" for p in ("vector", "irq-level")])


def test_every_property_readable(board):
    for path, prop in READ_WRITE + READ_ONLY:
        assert isinstance(board.get(path, prop), int), (path, prop)
    assert (len(READ_WRITE), len(READ_ONLY)) == (90, 123)        # the table in emu/IO.md


def test_read_only_properties_refuse_writes(board):
    for path, prop in READ_ONLY:
        with pytest.raises(Exception):
            board.set(path, prop, 0)


@pytest.mark.parametrize("path,prop", [(IO, "ain0"), (IO, "ain23"), (IO + "/bio1", "input")])
def test_range_checked(board, path, prop):
    board.set(path, prop, 255)
    assert board.get(path, prop) == 255
    with pytest.raises(Exception):
        board.set(path, prop, 256)
    with pytest.raises(Exception):
        board.set(path, prop, -1)
    assert board.get(path, prop) == 255


def test_analog_aliases_hit_the_chip(board):
    for i in range(24):
        board.set(IO, f"ain{i}", i * 10)
    for i in range(24):
        assert board.get(f"{IO}/adc{i // 4}", f"ain{i % 4}") == i * 10


def test_i2c_addresses_and_levels(board):
    assert [board.get(f"{IO}/adc{i}", "i2c-address") for i in range(6)] == list(range(0x48, 0x4E))
    assert [board.get(f"{IO}/bio{i}", "i2c-address") for i in range(2)] == [0x38, 0x39]
    assert board.get(IO + "/i2c-a", "irq-level") == 3
    assert board.get(IO + "/i2c-b", "irq-level") == 1


def test_fastbin_outputs(board):
    assert board.get(IO, "fastbin") == 0
    for bit in range(16):
        board.writew(FASTBIN, 1 << bit)
        assert board.get(IO, "fastbin") == 1 << bit
    board.writeb(FASTBIN, 0xA5)                                  # high byte lane
    assert board.get(IO, "fastbin") == 0xA500
    board.writeb(FASTBIN + 1, 0x3C)
    assert board.get(IO, "fastbin") == 0xA53C


def test_system_reset_keeps_host_inputs(board):
    b = board
    b.writew(0xFFFE08, 0x0480)                                   # TPU TICR
    b.writew(FASTBIN, 0x1234)
    b.set(IO, "ain0", 9)
    b.set(IO, "bio-in", 0x00FF)
    b.set(TPU, "inputs", 0x0100)
    b.i2c_init(0xFFE200)
    b.i2c_write(0xFFE200, 0x48, [0x40, 0x77])
    b.i2c_write(0xFFE200, 0x39, [0x0F])
    assert b.get(IO, "aout0") == 0x77
    b.m.system_reset()
    b.m.writeb(0xFFFA21, 0x00)                                   # watchdog off again
    assert b.readw(0xFFFE08) == 0
    assert b.get(IO, "fastbin") == 0
    assert b.get(IO, "aout0") == 0 and b.get(IO, "aout0-enabled") == 0
    assert b.get(IO, "bio-out") == 0xFFFF
    assert b.readb(0xFFE201) == 0x80                             # PCF8584 back to reset
    assert b.get(IO, "ain0") == 9                                # outside world unchanged
    assert b.get(IO, "bio-in") == 0x00FF
    assert b.get(TPU, "inputs") == 0x0100
