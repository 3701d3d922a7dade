"""PCF8584 I2C controllers and the I/O board behind them (6 x PCF8591,
2 x PCF8574A on bus A), driven through the controller registers the way a
firmware driver does, checked through the host interface (QOM properties)."""

import pytest

from io_support import (ACK, ENI, ES0, ES1, ES2, I2C_A, I2C_B, IO, PIN,  # noqa: F401
                        STA, STO, board)

ADC_ADDR = [0x48 + i for i in range(6)]
BIO_ADDR = [0x38, 0x39]


@pytest.mark.parametrize("base", [I2C_A, I2C_B])
def test_register_selection_and_readback(board, base):
    b = board
    b.writeb(base + 1, PIN)                       # ES0 = 0: S1 reads back control
    assert b.readb(base + 1) & 0x7F == 0
    b.writeb(base, 0x55)                          # S0' own address
    b.writeb(base + 1, PIN | ES1)
    assert b.readb(base + 1) & 0x7F == ES1
    b.writeb(base, 0x1C)                          # S2 clock
    b.writeb(base + 1, PIN | ES2)
    assert b.readb(base) == 0x0F                  # S3 reset value (68000 mode)
    b.writeb(base, 0x40 + (base >> 9 & 1))        # S3 vector
    b.writeb(base + 1, PIN)
    assert b.readb(base) == 0x55
    b.writeb(base + 1, PIN | ES1)
    assert b.readb(base) == 0x1C
    b.writeb(base + 1, PIN | ES2)
    assert b.readb(base) == 0x40 + (base >> 9 & 1)
    b.writeb(base + 1, PIN | ES0 | ACK)
    assert b.readb(base + 1) == 0x81              # PIN, bus free (BB = 1)


def test_absent_address_is_not_acknowledged(board):
    board.i2c_init(I2C_A)
    assert board.i2c_write(I2C_A, 0x20, [1]) == [False]
    assert board.readb(I2C_A + 1) & 0x01          # bus released after STOP
    board.i2c_init(I2C_B)                         # the I/O board is on bus A
    assert board.i2c_write(I2C_B, ADC_ADDR[0], [0]) == [False]


def test_bus_busy_between_start_and_stop(board):
    board.i2c_init(I2C_A)
    assert board.i2c_start(I2C_A, BIO_ADDR[0] << 1)
    assert board.readb(I2C_A + 1) & 0x01 == 0     # BB active low: busy
    board.i2c_stop(I2C_A)
    assert board.readb(I2C_A + 1) & 0x01 == 1


def test_pin_stays_set_during_the_byte(board):
    board.i2c_init(I2C_A)
    board.writeb(I2C_A, BIO_ADDR[0] << 1)
    board.writeb(I2C_A + 1, PIN | ES0 | STA | ACK)
    assert board.readb(I2C_A + 1) & PIN           # 9 SCL clocks not over yet
    board.step(50_000)
    assert board.readb(I2C_A + 1) & PIN
    board.step(60_000)
    assert not board.readb(I2C_A + 1) & PIN
    board.i2c_stop(I2C_A)


def adc_read(board, addr, control):
    assert board.i2c_write(I2C_A, addr, [control]) == [True, True]
    data = board.i2c_read(I2C_A, addr, 2)
    return data[1]


@pytest.mark.parametrize("ain", range(24))
def test_every_analog_input(board, ain):
    chip, ch = divmod(ain, 4)
    board.i2c_init(I2C_A)
    for other in range(4):                        # distinct values on the chip
        board.set(IO, f"ain{chip * 4 + other}", (17 * other + 3 * chip + 5) & 0xFF)
    board.set(IO, f"ain{ain}", 200 - ain)
    assert board.get(IO + f"/adc{chip}", f"ain{ch}") == 200 - ain
    assert adc_read(board, ADC_ADDR[chip], ch) == 200 - ain


def test_first_byte_is_previous_conversion(board):
    board.i2c_init(I2C_A)
    board.set(IO, "ain0", 11)
    board.set(IO, "ain1", 22)
    board.i2c_write(I2C_A, ADC_ADDR[0], [0x00])
    assert board.i2c_read(I2C_A, ADC_ADDR[0], 2) == [0x80, 11]   # power-on result first
    board.i2c_write(I2C_A, ADC_ADDR[0], [0x01])
    assert board.i2c_read(I2C_A, ADC_ADDR[0], 2) == [11, 22]


def test_auto_increment(board):
    board.i2c_init(I2C_A)
    for k, v in enumerate([10, 20, 30, 40]):
        board.set(IO, f"ain{4 + k}", v)
    board.i2c_write(I2C_A, ADC_ADDR[1], [0x04])   # auto-increment from channel 0
    assert board.i2c_read(I2C_A, ADC_ADDR[1], 6)[1:] == [10, 20, 30, 40, 10]


@pytest.mark.parametrize("mode,channel,expect", [
    (0x10, 0, 100 - 60), (0x10, 1, 0x100 - 40), (0x10, 2, 0x100 - 60 + 50),  # vs AIN3
    (0x20, 0, 100), (0x20, 1, 20), (0x20, 2, 0x100 - 10),                     # mixed
    (0x30, 0, 80), (0x30, 1, 0x100 - 10),                                     # two differential
])
def test_input_modes(board, mode, channel, expect):
    board.i2c_init(I2C_A)
    for k, v in enumerate([100, 20, 50, 60]):
        board.set(IO, f"ain{8 + k}", v)
    assert adc_read(board, ADC_ADDR[2], mode | channel) == expect


def test_differential_clamps(board):
    board.i2c_init(I2C_A)
    board.set(IO, "ain12", 255)
    board.set(IO, "ain13", 0)
    assert adc_read(board, ADC_ADDR[3], 0x30) == 127
    board.set(IO, "ain12", 0)
    board.set(IO, "ain13", 255)
    assert adc_read(board, ADC_ADDR[3], 0x30) == 0x80           # -128


@pytest.mark.parametrize("chip", range(6))
def test_every_analog_output(board, chip):
    board.i2c_init(I2C_A)
    assert board.get(IO, f"aout{chip}-enabled") == 0
    assert board.i2c_write(I2C_A, ADC_ADDR[chip], [0x40, 0x33 + chip]) == [True] * 3
    assert board.get(IO, f"aout{chip}") == 0x33 + chip
    assert board.get(IO, f"aout{chip}-enabled") == 1
    for other in range(6):
        if other != chip:
            assert board.get(IO, f"aout{other}") == 0
    board.i2c_write(I2C_A, ADC_ADDR[chip], [0x00])              # output disabled
    assert board.get(IO, f"aout{chip}-enabled") == 0


@pytest.mark.parametrize("pin", range(16))
def test_every_binary_input(board, pin):
    chip, bit = divmod(pin, 8)
    board.i2c_init(I2C_A)
    board.set(IO, "bio-in", 0xFFFF & ~(1 << pin))                # pull one pin low
    assert board.i2c_read(I2C_A, BIO_ADDR[chip], 1) == [0xFF & ~(1 << bit)]
    assert board.i2c_read(I2C_A, BIO_ADDR[1 - chip], 1) == [0xFF]
    assert board.get(IO, "bio-pins") == 0xFFFF & ~(1 << pin)


@pytest.mark.parametrize("pin", range(16))
def test_every_binary_output(board, pin):
    chip, bit = divmod(pin, 8)
    board.i2c_init(I2C_A)
    assert board.get(IO, "bio-out") == 0xFFFF                    # reset: all high
    board.i2c_write(I2C_A, BIO_ADDR[chip], [0xFF & ~(1 << bit)])
    assert board.get(IO, "bio-out") == 0xFFFF & ~(1 << pin)
    assert board.get(IO + f"/bio{chip}", "output") == 0xFF & ~(1 << bit)


def test_quasi_bidirectional_read_and_int(board):
    board.i2c_init(I2C_A)
    board.i2c_write(I2C_A, BIO_ADDR[0], [0x0F])                  # upper nibble low
    board.set(IO + "/bio0", "input", 0xFE)                       # outside pulls P0 low
    assert board.get(IO + "/bio0", "int") == 1
    assert board.i2c_read(I2C_A, BIO_ADDR[0], 1) == [0x0E]
    assert board.get(IO + "/bio0", "int") == 0                   # read releases /INT


def test_repeated_start(board):
    board.i2c_init(I2C_A)
    board.set(IO, "ain21", 77)
    base = I2C_A
    assert board.i2c_start(base, ADC_ADDR[5] << 1)
    board.writeb(base, 0x01)                                     # control: channel 1
    board.i2c_wait(base)
    board.writeb(base + 1, ES0 | STA | ACK)                      # repeated START
    board.writeb(base, (ADC_ADDR[5] << 1) | 1)
    assert not board.i2c_wait(base) & 0x08
    board.readb(base)                                            # dummy read
    board.i2c_wait(base)
    board.writeb(base + 1, ES0)                                  # NACK the next byte
    board.readb(base)                                            # stale byte
    board.i2c_wait(base)
    board.i2c_stop(base)
    assert board.readb(base) == 77


@pytest.mark.parametrize("base,level", [(I2C_A, 3), (I2C_B, 1)])
def test_interrupt_with_s3_vector(board, base, level):
    b = board
    b.writeb(base + 1, PIN | ES2)
    b.writeb(base, 0x60)                                         # S3 vector
    b.i2c_init(base, enable_irq=True)
    assert b.irq()[0] != level
    b.writeb(base, BIO_ADDR[0] << 1)
    b.writeb(base + 1, PIN | ES0 | ENI | STA | ACK)
    b.i2c_wait(base)
    assert b.irq() == (level, 0x60)
    b.writeb(base + 1, PIN | ES0 | ENI | STO | ACK)              # STOP sets PIN
    assert b.irq()[0] != level


def test_i2c_interrupt_seen_by_qtest_intercept(board):
    b = board
    b.m.irq_intercept_out("/machine/intc")
    b.i2c_init(I2C_A, enable_irq=True)
    b.writeb(I2C_A, BIO_ADDR[1] << 1)
    b.writeb(I2C_A + 1, PIN | ES0 | ENI | STA | ACK)
    assert (True, 2) not in b.m.irq_events                       # byte still on the wire
    b.i2c_wait(I2C_A)
    assert (True, 2) in b.m.irq_events                           # IPL 3
    b.readb(I2C_A)                                               # reading S0 sets PIN
    assert b.m.irq_events[-1] == (False, 2)


def test_word_access_is_two_byte_cycles(board):
    """Dynamic bus sizing: a word read of the 8-bit port reads S0 then S1."""
    b = board
    b.writeb(I2C_A + 1, PIN | ES1)
    b.writew(I2C_A, 0x1CA0)              # S2 <- 0x1C, then S1 <- 0xA0 (still S2)
    assert b.readb(I2C_A) == 0x1C
    assert b.readw(I2C_A) == 0x1CA0      # S2, then S1 control read-back (ES0 = 0)
