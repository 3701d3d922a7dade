"""The board model's radio mode (emu/hw/mc68681_duart.c, radio-medium=on) under
qtest: the test is the medium on channel A's socket and owns the virtual clock."""
import os
import time

import pytest

import robocube_emu

D = 0xFFE400
MRA, SRA, CSRA, CRA, RBA, TBA = D + 0, D + 1, D + 1, D + 2, D + 3, D + 3
ACR, IP, OPR_SET, OPR_RESET = D + 4, D + 13, D + 14, D + 15
RXRDY, TXRDY, TXEMT = 0x01, 0x04, 0x08
OP_RX, OP_TX = 0x01, 0x02
CHAR_NS = 10 * 1_000_000_000 // 19200          # 520833 ns per character at 19200


@pytest.fixture
def radio():
    with robocube_emu.start(extra_args=["-global", "mc68681-duart.radio-medium=on",
                                    "-global", "mc68681-duart.radio-station=5"]) as m:
        m.writeb(ACR, 0x80)                     # baud-rate set 2
        m.writeb(CSRA, 0xCC)                    # 19200
        m.writeb(MRA, 0x13)
        m.writeb(MRA, 0x07)
        m.writeb(CRA, 0x05)                     # receiver and transmitter on
        yield m


def messages(m, count, timeout=5.0):
    data = m.radio.read_exactly(2 * count, timeout=timeout)
    return [(data[i], data[i + 1]) for i in range(0, len(data), 2)]


def test_hello_and_selects_reported(radio):
    first = messages(radio, 2)
    assert first[0] == (2, 5)                   # hello: station 5
    assert first[1][0] == 1                     # the selects as they are
    radio.writeb(OPR_SET, OP_TX)
    assert messages(radio, 1) == [(1, OP_TX)]
    radio.writeb(OPR_SET, 0x04)                 # a motor bit: no message
    radio.writeb(OPR_RESET, OP_TX)
    assert messages(radio, 1) == [(1, 0)]


def test_character_takes_its_time_and_needs_tx_select(radio):
    messages(radio, 2)
    radio.writeb(TBA, 0x41)                     # not keyed: lost
    assert radio.readb(SRA) & TXEMT == 0        # but the shifter is busy for its time
    radio.clock_step(CHAR_NS + 1000)
    assert radio.readb(SRA) & TXEMT
    radio.writeb(OPR_SET, OP_TX)
    assert messages(radio, 1) == [(1, OP_TX)]
    radio.writeb(TBA, 0x42)
    radio.writeb(TBA, 0x43)                     # into the holding register
    assert radio.readb(SRA) & TXRDY == 0
    radio.clock_step(CHAR_NS // 2)
    radio.radio.poll()
    assert radio.radio.received == b""          # not on air before its last bit
    radio.clock_step(CHAR_NS // 2 + 1000)
    assert messages(radio, 1) == [(0, 0x42)]
    assert radio.readb(SRA) & TXRDY
    radio.clock_step(CHAR_NS)
    assert messages(radio, 1) == [(0, 0x43)]


def wait_set(m, addr, mask, step_ns=CHAR_NS):
    deadline = time.monotonic() + 5
    while not m.readb(addr) & mask:
        assert time.monotonic() < deadline
        m.clock_step(step_ns)
        time.sleep(0.002)


def test_reception_paced_and_gated_by_rx_select(radio):
    messages(radio, 2)
    radio.radio_write_taken(bytes((0, 0x61)))   # RX select off: dropped
    radio.clock_step(3 * CHAR_NS)
    assert radio.readb(SRA) & RXRDY == 0
    radio.writeb(OPR_SET, OP_RX)
    messages(radio, 1)
    radio.radio_write_taken(bytes((0, 0x62, 0, 0x63)))   # both queued in the model now
    radio.clock_step(CHAR_NS - 1000)
    assert radio.readb(SRA) & RXRDY == 0        # the first is still arriving
    assert radio.readb(IP) & 1 == 0             # carrier detect while characters arrive
    radio.clock_step(2000)
    assert radio.readb(SRA) & RXRDY
    assert radio.readb(RBA) == 0x62
    wait_set(radio, SRA, RXRDY)
    assert radio.readb(RBA) == 0x63
    radio.clock_step(CHAR_NS)
    assert radio.readb(IP) & 1 == 1


def test_carrier_from_medium_drives_ip0(radio):
    messages(radio, 2)
    radio.radio.write(bytes((1, 1)))
    deadline = time.monotonic() + 5
    while radio.readb(IP) & 1:
        assert time.monotonic() < deadline
        time.sleep(0.01)
    radio.radio.write(bytes((1, 0)))
    while not radio.readb(IP) & 1:
        assert time.monotonic() < deadline
        time.sleep(0.01)


def test_loopback_mode_with_both_selects(radio):
    messages(radio, 2)
    radio.writeb(OPR_SET, OP_RX | OP_TX)
    messages(radio, 1)
    radio.writeb(TBA, 0x5A)
    radio.clock_step(3 * CHAR_NS)
    assert radio.readb(SRA) & RXRDY
    assert radio.readb(RBA) == 0x5A
    radio.radio.poll()
    assert radio.radio.received == b""          # nothing on air
