"""QSM SCI and MC68681 DUART of the robocube machine through qtest: register
reset values, transmit and receive through the chardev sockets, interrupts
with level and vector, FIFO/overrun, input and output port from the host,
counter/timer in virtual time."""
import time

import pytest

INTC = "/machine/intc"
DUART_QOM = "/machine/duart"

# QSM
QSMCR, QILR, QIVR = 0xFFFC00, 0xFFFC04, 0xFFFC05
SCCR0, SCCR1, SCSR, SCDR = 0xFFFC08, 0xFFFC0A, 0xFFFC0C, 0xFFFC0E
TDRE, TC, RDRF, OR = 0x100, 0x80, 0x40, 0x08
TE, RE, RIE, TIE, LOOPS = 0x08, 0x04, 0x20, 0x80, 0x4000

# DUART (base 0xFFE400)
D = 0xFFE400
MRA, SRA, CSRA, CRA, RBA, TBA = D + 0, D + 1, D + 1, D + 2, D + 3, D + 3
IPCR, ACR, ISR, IMR, CUR, CTUR, CLR, CTLR = D + 4, D + 4, D + 5, D + 5, D + 6, D + 6, D + 7, D + 7
MRB, SRB, CSRB, CRB, RBB, TBB = D + 8, D + 9, D + 9, D + 10, D + 11, D + 11
IVR, IP, OPCR, START_CT, OPR_SET, STOP_CT, OPR_RESET = D + 12, D + 13, D + 13, D + 14, D + 14, D + 15, D + 15
RXRDY, FFULL, TXRDY, TXEMT, OE = 0x01, 0x02, 0x04, 0x08, 0x10


def wait_bits(m, addr, mask, read=None, timeout=5.0):
    """Polls a status register until all mask bits are set (host characters
    arrive through QEMU's main loop, asynchronously to qtest commands)."""
    read = read or m.readb
    deadline = time.monotonic() + timeout
    while True:
        value = read(addr)
        if value & mask == mask:
            return value
        assert time.monotonic() < deadline, f"{addr:#x}: bits {mask:#x} never set ({value:#x})"
        time.sleep(0.005)


def intc(m):
    return m.qom_get(INTC, "level"), m.qom_get(INTC, "vector")


# ---- QSM SCI ----------------------------------------------------------------

def test_qsm_reset_values(machine):
    m = machine
    assert m.readw(QSMCR) == 0x0080
    assert m.readb(QILR) == 0x00
    assert m.readb(QIVR) == 0x0F
    assert m.readw(SCCR0) == 0x0004
    assert m.readw(SCCR1) == 0x0000
    assert m.readw(SCSR) == TDRE | TC


def test_sci_transmit_to_chardev(machine):
    m = machine
    m.writew(SCCR0, 9)                       # 58254 baud at 16.78 MHz (stored only)
    m.writew(SCCR1, TE | RE)
    for byte in b"SCI ok\r\n":
        wait_bits(m, SCSR, TDRE, read=m.readw)
        m.writew(SCDR, byte)
    assert m.sci.read_exactly(8) == b"SCI ok\r\n"
    assert m.readw(SCSR) & (TDRE | TC) == TDRE | TC
    m.console.poll()
    assert m.console.received == b""         # nothing leaked to the DUART


def test_sci_receive_and_rdrf_clearing(machine):
    m = machine
    m.writew(SCCR1, TE | RE)
    got = []
    for byte in b"Qz":
        m.sci.write(bytes([byte]))
        wait_bits(m, SCSR, RDRF, read=m.readw)   # reading SCSR arms the clear
        got.append(m.readw(SCDR) & 0xFF)
        assert not m.readw(SCSR) & RDRF
    assert bytes(got) == b"Qz"
    m.sci.write(b"k")                            # SCDR read without SCSR first:
    deadline = time.monotonic() + 10             # RDRF stays set (the scsr property
    while not m.qom_get("/machine/qsm", "scsr") & RDRF:   # reads it without arming)
        assert time.monotonic() < deadline, "the SCI did not take the character"
        time.sleep(0.005)
    m.readw(SCDR)
    assert m.readw(SCSR) & RDRF


def test_sci_receiver_off_holds_host_data(machine):
    m = machine
    m.writew(SCCR1, TE)
    m.sci.write(b"h")
    time.sleep(0.1)
    assert not m.readw(SCSR) & RDRF
    m.writew(SCCR1, TE | RE)
    wait_bits(m, SCSR, RDRF, read=m.readw)
    assert m.readw(SCDR) & 0xFF == ord("h")


def test_sci_interrupt_vector_bit0_forced_to_zero(machine):
    """QIVR=65 as CubeOS writes it: the SCI requests vector 64 (QSM quirk)."""
    m = machine
    m.writeb(QILR, 0x05)
    m.writeb(QIVR, 65)
    m.writew(SCCR1, TE | RE | RIE)
    assert intc(m) == (0, 0)
    m.sci.write(b"i")
    deadline = time.monotonic() + 5
    while intc(m) != (5, 64):
        assert time.monotonic() < deadline, f"no SCI interrupt: {intc(m)}"
        time.sleep(0.005)
    m.readw(SCSR)
    m.readw(SCDR)
    assert intc(m) == (0, 0)
    m.writew(SCCR1, TE | RE | TIE)           # TDRE is set: transmit interrupt at once
    assert intc(m) == (5, 64)


def test_sci_loop_mode_overrun(machine):
    m = machine
    m.writew(SCCR1, LOOPS | TE | RE)
    m.writew(SCDR, 0x31)
    m.writew(SCDR, 0x32)                     # RDR still full: overrun, 0x32 lost
    status = m.readw(SCSR)
    assert status & (RDRF | OR) == RDRF | OR
    assert m.readw(SCDR) & 0xFF == 0x31
    assert not m.readw(SCSR) & (RDRF | OR)
    m.sci.poll()
    assert m.sci.received == b""             # loop mode: nothing on the line


# ---- MC68681 DUART ------------------------------------------------------------

def test_duart_reset_values(machine):
    m = machine
    assert m.readb(IVR) == 0x0F
    assert m.readb(IP) == 0xFF               # IP0..IP5 pulled up, bits 6-7 read 1
    assert m.readb(SRA) == 0x00              # receiver and transmitter off
    assert m.readb(SRB) == 0x00
    assert m.readb(ISR) == 0x00
    assert m.qom_get(DUART_QOM, "opr") == 0
    assert m.qom_get(DUART_QOM, "output-pins") == 0xFF


def test_duart_mode_register_pointer(machine):
    m = machine
    m.writeb(MRB, 0x13)                      # MR1B: 8 bits, no parity
    m.writeb(MRB, 0x07)                      # MR2B: 1 stop bit
    m.writeb(CRB, 0x10)                      # reset MR pointer
    assert m.readb(MRB) == 0x13
    assert m.readb(MRB) == 0x07
    assert m.readb(MRB) == 0x07              # pointer stays at MR2


@pytest.mark.parametrize("channel", ["A", "B"])
def test_duart_transmit_and_receive(machine, channel):
    m = machine
    cr, sr, tb, rb = (CRA, SRA, TBA, RBA) if channel == "A" else (CRB, SRB, TBB, RBB)
    port, other = (m.radio, m.console) if channel == "A" else (m.console, m.radio)
    m.writeb(cr, 0x2A)                       # CubeOS init: reset RX, reset TX
    m.writeb(cr, 0x3A)
    m.writeb(cr, 0x05)                       # enable RX and TX
    assert m.readb(sr) & (TXRDY | TXEMT) == TXRDY | TXEMT
    for byte in b"chan " + channel.encode():
        m.writeb(tb, byte)
    assert port.read_exactly(6) == b"chan " + channel.encode()
    port.write(b"xyz")
    got = []
    for _ in range(3):
        wait_bits(m, sr, RXRDY)
        got.append(m.readb(rb))
    assert bytes(got) == b"xyz"
    assert not m.readb(sr) & RXRDY
    other.poll()
    assert other.received == b""


def test_duart_takes_a_host_burst_whole_and_loses_nothing(machine):
    """The host's characters wait in the model's queue, not in the chardev:
    received-b counts all of them at once, the FIFO holds 3 with FFULL and no
    overrun, and each read of RBB brings the next in order."""
    m = machine
    m.writeb(CRB, 0x2A)
    m.writeb(CRB, 0x05)
    burst = bytes(range(32, 127)) * 4                  # 380 characters, FIFO is 3
    before = m.console_write_taken(burst)
    assert m.qom_get(DUART_QOM, "received-b") - before == len(burst)
    assert m.readb(SRB) & (RXRDY | FFULL | OE) == RXRDY | FFULL
    got = bytes(m.readb(RBB) for _ in range(len(burst)))
    assert got == burst
    assert m.readb(SRB) & (RXRDY | OE) == 0
    assert m.qom_get(DUART_QOM, "received-a") == 0


def test_duart_fifo_overrun_in_local_loopback(machine):
    m = machine
    m.writeb(CRB, 0x10)
    m.writeb(MRB, 0x13)
    m.writeb(MRB, 0x87)                      # MR2B channel mode 10: local loopback
    m.writeb(CRB, 0x05)
    for byte in b"1234":
        m.writeb(TBB, byte)
    status = m.readb(SRB)
    assert status & (RXRDY | FFULL | OE) == RXRDY | FFULL | OE
    assert bytes(m.readb(RBB) for _ in range(3)) == b"124"   # '3' overwritten
    m.writeb(CRB, 0x40)                      # reset error status
    assert m.readb(SRB) & (RXRDY | OE) == 0
    m.console.poll()
    assert m.console.received == b""


def test_duart_receive_interrupt_level5_with_ivr(machine):
    m = machine
    m.writeb(IVR, 0x45)
    m.writeb(CRB, 0x05)
    m.writeb(IMR, 0x20)                      # RxRDYB
    assert intc(m) == (0, 0)
    m.console.write(b"!")
    deadline = time.monotonic() + 5
    while intc(m) != (5, 0x45):
        assert time.monotonic() < deadline, f"no DUART interrupt: {intc(m)}"
        time.sleep(0.005)
    assert m.readb(ISR) & 0x20
    assert m.readb(RBB) == ord("!")
    assert intc(m) == (0, 0)
    m.writeb(IMR, 0x10)                      # TxRDYB: transmitter ready at once
    assert intc(m) == (5, 0x45)
    m.writeb(IMR, 0x00)
    assert intc(m) == (0, 0)


def test_duart_input_port_from_host(machine):
    m = machine
    m.readb(IPCR)                            # clear change bits
    m.writeb(ACR, 0x01)                      # IP0 (carrier detect) change interrupt
    m.writeb(IMR, 0x80)
    m.qom_set(DUART_QOM, "input-port", 0x3E)  # carrier detect low
    assert m.readb(IP) == 0xFE
    assert m.readb(ISR) & 0x80
    assert intc(m) == (5, 0x0F)
    ipcr = m.readb(IPCR)
    assert ipcr == 0x1E                      # delta IP0, IP3..IP0 = 1110
    assert not m.readb(ISR) & 0x80
    assert intc(m) == (0, 0)
    m.qom_set(DUART_QOM, "input-port", 0x1E)  # IP5 low: no change interrupt for IP4/5
    assert m.readb(IP) == 0xDE
    assert not m.readb(ISR) & 0x80
    assert m.qom_get(DUART_QOM, "input-port") == 0x1E
    with pytest.raises(Exception):
        m.qom_set(DUART_QOM, "input-port", 0x40)   # only 6 input pins


def test_duart_output_port_to_host(machine):
    m = machine
    m.writeb(OPCR, 0x00)
    m.writeb(OPR_RESET, 0xFF)                # CubeOS init: all pins high
    assert m.qom_get(DUART_QOM, "opr") == 0x00
    m.writeb(OPR_SET, 0x06)                  # OP1 (radio TX select) and OP2 asserted
    assert m.qom_get(DUART_QOM, "opr") == 0x06
    assert m.qom_get(DUART_QOM, "output-pins") == 0xF9   # asserted = driven low
    m.writeb(OPR_SET, 0x80)
    m.writeb(OPR_RESET, 0x02)
    assert m.qom_get(DUART_QOM, "opr") == 0x84


def test_duart_timer_mode_period(machine):
    """ACR=0x60: timer from X1 (3.6864 MHz); preload 0x1200 = 4608:
    square wave period 2*4608/3686400 s = 2.5 ms, counter-ready once a period."""
    m = machine
    m.writeb(CTUR, 0x12)
    m.writeb(CTLR, 0x00)
    m.writeb(ACR, 0x60)
    m.writeb(IMR, 0x08)
    m.clock_step(2_499_000)
    assert not m.readb(ISR) & 0x08
    m.clock_step(2_000)
    assert m.readb(ISR) & 0x08
    assert intc(m) == (5, 0x0F)
    m.readb(STOP_CT)                         # clears counter-ready
    assert not m.readb(ISR) & 0x08
    assert intc(m) == (0, 0)
    m.clock_step(2_500_000)                  # timer keeps running
    assert m.readb(ISR) & 0x08


def test_duart_counter_mode(machine):
    """ACR=0x30: counter from X1/16 = 230400 Hz; preload 2304 -> 10 ms."""
    m = machine
    m.writeb(ACR, 0x30)
    m.writeb(CTUR, 2304 >> 8)
    m.writeb(CTLR, 2304 & 0xFF)
    m.readb(START_CT)
    m.clock_step(5_000_000)
    value = (m.readb(CUR) << 8) | m.readb(CLR)
    assert value == 2304 - 1152
    assert not m.readb(ISR) & 0x08
    m.clock_step(5_000_000)
    assert m.readb(ISR) & 0x08
    m.readb(STOP_CT)                         # stops the counter and clears ISR[3]
    held = (m.readb(CUR) << 8) | m.readb(CLR)
    m.clock_step(20_000_000)
    assert (m.readb(CUR) << 8) | m.readb(CLR) == held
    assert not m.readb(ISR) & 0x08


def test_duart_console_baud_timer_is_lazy(machine):
    """CubeOS's 57600 baud setting (ACR=0xE0: timer from X1, preload 2) gives a
    counter-ready event every 1.085 us.  With IMR bit 3 clear the model must
    still report ISR[3] when read, without a callback per event (one virtual
    second of it has to be cheap), and arm a timer once IMR enables it."""
    m = machine
    m.writeb(CTUR, 0x00)
    m.writeb(CTLR, 0x02)
    m.writeb(ACR, 0xE0)
    m.readb(STOP_CT)                         # clear ISR[3]
    assert not m.readb(ISR) & 0x08
    start = time.monotonic()
    m.clock_step(1_000_000_000)
    assert time.monotonic() - start < 0.5
    assert m.readb(ISR) & 0x08
    assert intc(m) == (0, 0)
    m.readb(STOP_CT)
    m.writeb(IMR, 0x08)
    m.clock_step(2_000)                      # next event within 1.085 us
    assert intc(m) == (5, 0x0F)


def test_duart_timer_preload_change_restarts_period(machine):
    m = machine
    m.writeb(CTUR, 0x12)                     # 2.5 ms period
    m.writeb(CTLR, 0x00)
    m.writeb(ACR, 0x60)
    m.clock_step(1_000_000)
    m.writeb(CTUR, 0x24)                     # 0x2400: 5 ms period from now
    m.writeb(CTLR, 0x00)
    m.clock_step(4_900_000)
    assert not m.readb(ISR) & 0x08
    m.clock_step(200_000)
    assert m.readb(ISR) & 0x08
