"""How a host peer reaches the air: the emulator's radio medium or a real module."""
import socket
import threading
import time

# The medium's message codes and select bits, defined once, by the medium.
from robocube_emu.radio_medium import (CLOCK_UNIT_NS, MSG_CLOCK, MSG_CONTROL, MSG_DATA,
                                       MSG_HELLO, MSG_PACE, SEL_RX, SEL_TX)

CLOCK_UNIT = CLOCK_UNIT_NS / 1e9   # seconds per unit of the medium's 05 k


class PeerClock:
    """The time a host peer's timers run on: the boards' virtual time while
    the medium reports it (robocube_emu.radio_medium, "Clock"), wall time
    otherwise. In wall time the peer's retransmission timer expired while
    boards slowed by a loaded host were still answering in their own time.

    The reading is monotonic and continuous when the source changes. If the
    virtual clock stops for longer than STALL seconds of wall time (boards
    stopped, the medium hung), wall time counts from then on, so no wait on
    this clock lasts for ever."""

    STALL = 10.0

    def __init__(self):
        self._cond = threading.Condition()
        self._base = 0.0              # the reading when the current source took over
        self._virtual = None          # virtual seconds since then; None: wall time
        self._since = time.monotonic()    # wall: when it took over / the last tick

    def _now(self):
        idle = time.monotonic() - self._since
        if self._virtual is None:
            return self._base + idle
        return self._base + self._virtual + max(0.0, idle - self.STALL)

    def now(self):
        with self._cond:
            return self._now()

    def advance(self, seconds):
        """The boards' clock moved on by seconds (05 k)."""
        with self._cond:
            if self._virtual is None:
                self._base, self._virtual = self._now(), 0.0
            else:                     # a stall counted in wall time stays counted
                self._base += max(0.0, time.monotonic() - self._since - self.STALL)
            self._virtual += seconds
            self._since = time.monotonic()
            self._cond.notify_all()

    def to_wall(self):
        """Nobody keeps virtual time now (05 0, or the medium is gone)."""
        with self._cond:
            if self._virtual is not None:
                self._base, self._virtual = self._now(), None
                self._since = time.monotonic()
            self._cond.notify_all()

    def notify(self):
        """Something a waiter's predicate looks at has changed."""
        with self._cond:
            self._cond.notify_all()

    def wait_until(self, deadline, predicate=None, poll=0.05):
        """True as soon as predicate() holds, False when the clock reaches
        deadline first. Whoever changes what predicate reads calls notify()."""
        with self._cond:
            while True:
                if predicate is not None and predicate():
                    return True
                left = deadline - self._now()
                if left <= 0:
                    return False
                self._cond.wait(min(left, poll))

    def sleep(self, seconds):
        self.wait_until(self.now() + seconds)


class MediumTransport:
    """A station on robocube_emu.radio_medium (its 2-byte message protocol).
    The medium plays our transmissions in the boards' virtual time when they
    run in lock step (its docstring, "Pacing"), and tells us when one is over;
    without boards in lock step we pace in wall time. Either way a transmission
    occupies the air as long as on the boards, and transmit() returns when it
    is over."""

    def __init__(self, path, baud=19200, connect_timeout=10.0):
        if not 300 <= baud <= 255 * 300 or baud % 300:
            raise ValueError(f"baud {baud}: a multiple of 300 up to {255 * 300}")
        deadline = time.monotonic() + connect_timeout
        while True:
            try:
                self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
                self.sock.connect(path)
                break
            except OSError:
                self.sock.close()
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.05)
        self.baud = baud
        self.carrier = False
        self.clock = PeerClock()
        self.lock = threading.Lock()
        self.closed = False
        self._pending = b""
        self._tx_over_count = 0       # the medium's "your transmission is over" (04 p)
        self._tx_paced = False

    def hello(self, station):
        self._send(bytes((MSG_HELLO, station, MSG_PACE, self.baud // 300,
                          MSG_CONTROL, SEL_RX)))

    def _send(self, data):
        with self.lock:
            if self.closed:
                return
            try:
                self.sock.sendall(data)
            except OSError:
                self.closed = True    # the medium is gone: the air is silent

    def transmit(self, data):
        air_time = len(data) * 10 / self.baud
        msgs = bytearray((MSG_CONTROL, SEL_TX))
        for b in data:
            msgs += bytes((MSG_DATA, b))
        msgs += bytes((MSG_CONTROL, SEL_RX))
        start = self.clock.now()
        seen = self._tx_over_count
        self._send(bytes(msgs))
        # The medium's word that it is over; bounded, in case it is gone
        # or the boards stall (then the air is silent anyway).
        over = self.clock.wait_until(start + max(10.0, 50 * air_time),
                                     lambda: self._tx_over_count != seen or self.closed)
        if not (over and self._tx_paced and not self.closed):
            self.clock.wait_until(start + air_time)

    def read(self, timeout):
        """Bytes heard within timeout (b'' when none); None when the medium is gone."""
        self.sock.settimeout(timeout)
        try:
            chunk = self.sock.recv(4096)
        except socket.timeout:
            return b""
        except OSError:
            self.clock.to_wall()
            return None
        if not chunk:
            self.clock.to_wall()
            return None
        data = self._pending + chunk
        usable = len(data) & ~1
        self._pending = data[usable:]
        out = bytearray()
        for i in range(0, usable, 2):
            if data[i] == MSG_DATA:
                out.append(data[i + 1])
            elif data[i] == MSG_CONTROL:
                self.carrier = bool(data[i + 1])
            elif data[i] == MSG_PACE:
                self._tx_paced = bool(data[i + 1])
                self._tx_over_count += 1
                self.clock.notify()
            elif data[i] == MSG_CLOCK:
                if data[i + 1]:
                    self.clock.advance(data[i + 1] * CLOCK_UNIT)
                else:
                    self.clock.to_wall()
        return bytes(out)

    def close(self):
        self.closed = True
        self.clock.to_wall()          # no 05 k will come: waits end in wall time
        self.sock.close()


class SerialTransport:
    """A real BiM-433 module on a serial port (pyserial). The module's select
    lines are wired to RTS (TX select) and DTR (RX select) on a host adapter,
    carrier detect to CD. A port without modem lines (a pseudo-terminal, a
    3-wire adapter with the module hard-wired) works too: then the selects are
    not driven and the carrier reads as absent (modem_lines is False)."""

    def __init__(self, device, baud=19200):
        import serial                 # pyserial: only needed for real hardware
        self.port = serial.Serial(device, baud, timeout=0.1)
        self.baud = baud
        self.clock = PeerClock()      # real radios: always wall time
        self.modem_lines = True

    @property
    def carrier(self):
        if not self.modem_lines:
            return False
        try:
            return bool(self.port.cd)
        except OSError:
            return False

    def _selects(self, rx, tx):
        if not self.modem_lines:
            return
        try:
            self.port.dtr, self.port.rts = rx, tx
        except OSError:               # no modem control on this port (e.g. a pty)
            self.modem_lines = False

    def hello(self, station):
        self._selects(True, False)

    def transmit(self, data):
        self._selects(False, True)
        self.port.write(data)
        self.port.flush()
        # flush() returns when the driver took the bytes; the last ones are
        # still in the UART: wait their air time before un-keying.
        time.sleep(len(data) * 10 / self.baud)
        self._selects(True, False)

    def read(self, timeout):
        """Bytes heard within timeout (b'' when none); None when the port is gone."""
        import serial
        try:
            self.port.timeout = timeout
            return self.port.read(4096)
        except (serial.SerialException, OSError):
            return None

    def close(self):
        self.port.close()
