"""Helpers for the emu-io device tests: register-level drivers for the
PCF8584 and the TPU as firmware would use them, on top of the board
helper robocube_emu.Machine (qtest protocol + QMP)."""

import os

import pytest

import robocube_emu

IO = "/machine/robocube-io"
TPU = IO + "/tpu"
INTC = "/machine/intc"

I2C_A = 0xFFE200
I2C_B = 0xFFE000
TPU_BASE = 0xFFFE00
PRAM = 0xFFFF00
FASTBIN = 0xFE0000
DUART_OPR_SET = 0xFFE40E
DUART_OPR_RESET = 0xFFE40F

# TPU register offsets
TPUMCR, TICR, CIER, CFSR0, HSQR0, HSRR0, CPR0, CISR = 0x0, 0x8, 0xA, 0xC, 0x14, 0x18, 0x1C, 0x20
FN_QDEC, FN_DIO, FN_PWM, FN_ITC = 0x6, 0x8, 0x9, 0xA

# PCF8584 S1 bits
PIN, ES0, ES1, ES2, ENI, STA, STO, ACK = 0x80, 0x40, 0x20, 0x10, 0x08, 0x04, 0x02, 0x01
BYTE_NS = 120_000          # > 9 SCL clocks at 90 kHz (100 us)


class Board:
    """One robocube machine under qtest, with the I/O helpers."""

    def __init__(self, machine):
        self.m = machine

    # -- raw access -------------------------------------------------------
    def readb(self, a):
        return self.m.readb(a)

    def writeb(self, a, v):
        self.m.writeb(a, v)

    def readw(self, a):
        return self.m.readw(a)

    def writew(self, a, v):
        self.m.writew(a, v)

    def step(self, ns):
        self.m.clock_step(ns)

    def get(self, path, prop):
        return self.m.qom_get(path, prop)

    def set(self, path, prop, value):
        self.m.qom_set(path, prop, value)

    def irq(self):
        """(level, vector) the interrupt arbiter presents to the CPU."""
        return self.get(INTC, "level"), self.get(INTC, "vector")

    # -- PCF8584 driver ----------------------------------------------------
    def i2c_init(self, base, own=0x55, enable_irq=False):
        self.writeb(base + 1, PIN)              # S0' selected, serial interface off
        self.writeb(base, own)
        self.writeb(base + 1, PIN | ES1)        # S2
        self.writeb(base, 0x1C)                 # 12 MHz input, 90 kHz SCL
        self.writeb(base + 1, PIN | ES0 | ACK | (ENI if enable_irq else 0))

    def i2c_wait(self, base):
        """Waits for PIN = 0 (byte done); returns the status byte."""
        for _ in range(20):
            st = self.readb(base + 1)
            if not st & PIN:
                return st
            self.step(BYTE_NS // 4)
        raise AssertionError(f"PCF8584 at {base:#x}: PIN stuck at 1 (status {st:#04x})")

    def i2c_start(self, base, addr8):
        """START + address byte; returns True if the slave acknowledged."""
        self.writeb(base, addr8)
        self.writeb(base + 1, PIN | ES0 | STA | ACK)
        return not self.i2c_wait(base) & 0x08

    def i2c_stop(self, base):
        self.writeb(base + 1, PIN | ES0 | STO | ACK)

    def i2c_write(self, base, addr7, data):
        """Writes bytes; returns the list of per-byte ACKs (address first)."""
        acks = [self.i2c_start(base, addr7 << 1)]
        if acks[0]:
            for b in data:
                self.writeb(base, b)
                acks.append(not self.i2c_wait(base) & 0x08)
        self.i2c_stop(base)
        return acks

    def i2c_read(self, base, addr7, count):
        """Reads count bytes the way i2c-algo-pcf does (dummy read first,
        NACK before the last byte, STOP before reading it)."""
        if not self.i2c_start(base, (addr7 << 1) | 1):
            self.i2c_stop(base)
            return None
        out = []
        for i in range(count + 1):
            if i > 0:
                self.i2c_wait(base)
            if i == count - 1:
                self.writeb(base + 1, ES0)      # NACK the next (last) byte
            elif i == count:
                self.i2c_stop(base)
            b = self.readb(base)
            if i > 0:
                out.append(b)
        return out

    # -- TPU --------------------------------------------------------------
    def tpu_field4(self, reg0, ch, value):
        reg = TPU_BASE + reg0 + 2 * (3 - ch // 4)
        shift = (ch % 4) * 4
        self.writew(reg, (self.readw(reg) & ~(0xF << shift)) | (value << shift))

    def tpu_field2(self, reg0, ch, value):
        reg = TPU_BASE + reg0 + 2 * (1 - ch // 8)
        shift = (ch % 8) * 2
        self.writew(reg, (self.readw(reg) & ~(3 << shift)) | (value << shift))

    def tpu_hsr(self, ch, value):
        """Issues a host service request (only the channel's field is written)."""
        reg = TPU_BASE + HSRR0 + 2 * (1 - ch // 8)
        self.writew(reg, value << ((ch % 8) * 2))

    def param(self, ch, k):
        return self.readw(PRAM + 16 * ch + 2 * k)

    def set_param(self, ch, k, v):
        self.writew(PRAM + 16 * ch + 2 * k, v & 0xFFFF)

    def tpu_setup(self, ch, fn, params, hsq=0, hsr=2, prio=2):
        self.tpu_field4(CFSR0, ch, fn)
        self.tpu_field2(HSQR0, ch, hsq)
        for k, v in params.items():
            self.set_param(ch, k, v)
        self.tpu_hsr(ch, hsr)
        self.tpu_field2(CPR0, ch, prio)

    def tpu_start(self):
        """TPUMCR as CubeOS writes it: TCR1 = fsys/4/4."""
        self.writew(TPU_BASE + TPUMCR, 0x4ACD)

    def duart_opr(self, asserted_bits):
        """Makes OPR == asserted_bits (OPR-set / OPR-reset registers)."""
        self.writeb(DUART_OPR_RESET, 0xFF)
        self.writeb(DUART_OPR_SET, asserted_bits)


@pytest.fixture
def board():
    with robocube_emu.start() as machine:
        yield Board(machine)
