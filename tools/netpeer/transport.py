"""How a host peer reaches the air: the emulator's radio medium or a real module."""
import socket
import threading
import time

MSG_DATA, MSG_CONTROL, MSG_HELLO = 0, 1, 2
SEL_RX, SEL_TX = 1, 2


class MediumTransport:
    """A station on emu/radio_medium.py (its 2-byte message protocol).
    Transmissions are paced at the baud rate in wall time, so the air is
    busy as long as on the boards."""

    def __init__(self, path, baud=19200, connect_timeout=10.0):
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
        self.lock = threading.Lock()
        self.closed = False
        self._pending = b""

    def hello(self, station):
        self._send(bytes((MSG_HELLO, station, MSG_CONTROL, SEL_RX)))

    def _send(self, data):
        with self.lock:
            if self.closed:
                return
            try:
                self.sock.sendall(data)
            except OSError:
                self.closed = True    # the medium is gone: the air is silent

    def transmit(self, data):
        msgs = bytearray((MSG_CONTROL, SEL_TX))
        for b in data:
            msgs += bytes((MSG_DATA, b))
        self._send(bytes(msgs))
        time.sleep(len(data) * 10 / self.baud)
        self._send(bytes((MSG_CONTROL, SEL_RX)))

    def read(self, timeout):
        """Bytes heard within timeout (b'' when none); None when the medium is gone."""
        self.sock.settimeout(timeout)
        try:
            chunk = self.sock.recv(4096)
        except socket.timeout:
            return b""
        except OSError:
            return None
        if not chunk:
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
        return bytes(out)

    def close(self):
        self.closed = True
        self.sock.close()


class SerialTransport:
    """A real BiM-433 module on a serial port (pyserial). The module's select
    lines are wired to RTS (TX select) and DTR (RX select) on a host adapter,
    carrier detect to CD; without them the adapter must be hard-wired."""

    def __init__(self, device, baud=19200):
        import serial                 # pyserial: only needed for real hardware
        self.port = serial.Serial(device, baud, timeout=0.1)
        self.baud = baud

    @property
    def carrier(self):
        try:
            return bool(self.port.cd)
        except OSError:
            return False

    def hello(self, station):
        self.port.dtr = True
        self.port.rts = False

    def transmit(self, data):
        self.port.dtr, self.port.rts = False, True
        self.port.write(data)
        self.port.flush()
        self.port.dtr, self.port.rts = True, False

    def read(self, timeout):
        self.port.timeout = timeout
        return self.port.read(4096)

    def close(self):
        self.port.close()
