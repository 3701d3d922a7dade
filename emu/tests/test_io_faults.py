"""Fault injection of the I2C side (emu/IO.md section 2.1): a chip that stops
acknowledging ("nack" on a PCF8591 / PCF8574A) and a bus held low
("bus-stuck" on a PCF8584), both set over QMP."""

import pytest

from io_support import ACK, ES0, I2C_A, IO, PIN, STA, board  # noqa: F401

ADC_ADDR = [0x48 + i for i in range(6)]
BIO_ADDR = [0x38, 0x39]
CHIPS = [(f"{IO}/adc{i}", a) for i, a in enumerate(ADC_ADDR)] + \
        [(f"{IO}/bio{i}", a) for i, a in enumerate(BIO_ADDR)]


@pytest.mark.parametrize("path,addr", CHIPS)
def test_nack_chip_ignores_its_address_until_cleared(board, path, addr):
    board.i2c_init(I2C_A)
    assert board.get(path, "nack") == 0
    board.set(path, "nack", 1)
    assert board.i2c_write(I2C_A, addr, [0xFF]) == [False]
    assert board.i2c_read(I2C_A, addr, 1) is None          # read address refused too
    other = ADC_ADDR[0] if addr != ADC_ADDR[0] else ADC_ADDR[1]
    assert board.i2c_write(I2C_A, other, [0x00]) == [True, True]   # the others still answer
    board.set(path, "nack", 0)
    assert board.i2c_write(I2C_A, addr, [0xFF]) == [True, True]


def test_nack_is_range_checked_and_survives_reset(board):
    with pytest.raises(Exception):
        board.set(f"{IO}/adc0", "nack", 2)
    board.set(f"{IO}/adc0", "nack", 1)
    board.m.system_reset()
    assert board.get(f"{IO}/adc0", "nack") == 1


def test_stuck_bus_reads_busy_and_refuses_start(board):
    board.i2c_init(I2C_A)
    board.set(f"{IO}/i2c-a", "bus-stuck", 1)
    assert board.readb(I2C_A + 1) & 0x01 == 0            # BB: busy
    board.writeb(I2C_A, ADC_ADDR[0] << 1)
    board.writeb(I2C_A + 1, PIN | ES0 | STA | ACK)
    board.step(1_000_000)
    assert board.readb(I2C_A + 1) & PIN                  # nothing was sent
    board.set(f"{IO}/i2c-a", "bus-stuck", 0)
    assert board.readb(I2C_A + 1) & 0x01 == 1
    assert board.i2c_write(I2C_A, ADC_ADDR[0], [0]) == [True, True]


def test_stuck_bus_stalls_the_byte_on_the_wire_and_reset_releases_it(board):
    board.i2c_init(I2C_A)
    board.writeb(I2C_A, ADC_ADDR[0] << 1)
    board.writeb(I2C_A + 1, PIN | ES0 | STA | ACK)       # byte on the wire
    board.set(f"{IO}/i2c-a", "bus-stuck", 1)
    board.step(1_000_000)
    assert board.readb(I2C_A + 1) & PIN                  # never completes
    board.writeb(I2C_A + 1, PIN)                         # software reset: ES0 = 0
    board.set(f"{IO}/i2c-a", "bus-stuck", 0)
    board.step(1_000_000)
    board.i2c_init(I2C_A)
    assert board.readb(I2C_A + 1) == 0x81                # PIN, bus free
    assert board.i2c_write(I2C_A, ADC_ADDR[1], [0]) == [True, True]


def test_stalled_byte_completes_when_released(board):
    board.i2c_init(I2C_A)
    board.set(f"{IO}/i2c-a", "bus-stuck", 0)
    board.writeb(I2C_A, ADC_ADDR[2] << 1)
    board.writeb(I2C_A + 1, PIN | ES0 | STA | ACK)
    board.set(f"{IO}/i2c-a", "bus-stuck", 1)
    board.step(500_000)
    assert board.readb(I2C_A + 1) & PIN
    board.set(f"{IO}/i2c-a", "bus-stuck", 0)
    assert not board.readb(I2C_A + 1) & PIN              # done, acknowledged
    assert not board.readb(I2C_A + 1) & 0x08
    board.i2c_stop(I2C_A)
