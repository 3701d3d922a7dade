"""A robocube machine for tests: qtest, QMP and the three serial ports.

Starts qemu-system-m68k -M robocube with
  * the qtest protocol on a Unix socket (``-accel qtest``: the CPU does not
    run, the test owns the virtual clock) or, with ``kernel=``, a running CPU
    (``-accel tcg``) executing that ELF from flash,
  * QMP on a Unix socket (``qom-get``/``qom-set`` on the board's devices),
  * the three serial ports on Unix sockets served by this module:
    index 0 = DUART channel B (console), 1 = DUART channel A (radio),
    2 = QSM SCI.

    with robocube_emu.start() as m:
        m.writeb(0xFFE40A, 0x05)
        m.clock_step(1_000_000)
        m.qom_get("/machine/duart", "opr")

The QEMU binary: launch.qemu_binary().
"""

import contextlib
import os
import selectors
import shutil
import socket
import subprocess
import tempfile
import threading
import time

from . import launch
from .qmp import QMPLink

SERIAL_NAMES = ("console", "radio", "sci")
SYPCR = 0xFFFA21
QMP_REPLY_TIMEOUT = 120.0     # seconds of wall time one QMP answer may take


class QTestError(RuntimeError):
    pass


class SerialPort:
    """Host end of one board serial port (a Unix stream socket).

    A thread of the machine (SerialPump) reads every port as soon as QEMU writes
    to it, whatever the test is doing meanwhile. QEMU's serial devices send each
    byte with a blocking write while the vCPU holds QEMU's big lock: a port nobody
    reads fills its socket after some 280 bytes (each one-byte send costs the
    socket ~770 bytes of buffer), the vCPU then waits for the reader while holding
    the lock, and QEMU's main loop, which needs the lock to answer QMP, waits for
    the vCPU. A test blocked on a QMP answer (cont, say) while its board printed
    was thus a deadlock, seen as QMP silent for 120 s whenever QEMU's main thread
    was descheduled long enough for the board to print that much first."""

    def __init__(self, name, conn):
        self.name = name
        self.conn = conn
        self.conn.setblocking(False)
        self.received = bytearray()
        self.closed = False             # QEMU closed its end
        self._arrived = threading.Condition()

    def write(self, data):
        self.conn.sendall(data)

    def _drain(self):
        """Reads what the socket holds (caller holds self._arrived)."""
        got = False
        while not self.closed:
            try:
                chunk = self.conn.recv(65536)
            except BlockingIOError:
                break
            except OSError:
                self.closed = True
                break
            if not chunk:
                self.closed = True
                break
            self.received += chunk
            got = True
        if got or self.closed:
            self._arrived.notify_all()

    def poll(self):
        """Moves whatever QEMU has sent so far into self.received (the pump
        may already have; this reads the socket too, so nothing sent before the
        call is missing after it)."""
        with self._arrived:
            self._drain()

    def read_until(self, marker, timeout=10.0, step=None):
        """Waits (wall time) until marker appears; returns everything up to and
        including it and keeps the rest. step: called between polls (e.g. to
        advance the qtest clock)."""
        def end():
            idx = self.received.find(marker)
            return idx + len(marker) if idx >= 0 else -1
        return self._take(end, f"{marker!r} not seen in {timeout} s", timeout, step)

    def read_exactly(self, count, timeout=10.0, step=None):
        """Waits until count bytes have come; returns them and keeps the rest."""
        return self._take(lambda: count if len(self.received) >= count else -1,
                          f"wanted {count} bytes", timeout, step)

    def _take(self, end, failure, timeout, step):
        """Until end() gives how many received bytes to return: with step, calls
        it between polls (the qtest clock only moves when told); without, waits
        for the pump to bring bytes. Raises TimeoutError after timeout s."""
        deadline = time.monotonic() + timeout
        while True:
            with self._arrived:
                self._drain()
                n = end()
                if n >= 0:
                    out = bytes(self.received[:n])
                    del self.received[:n]
                    return out
                left = deadline - time.monotonic()
                if left <= 0:
                    raise TimeoutError(f"serial {self.name}: {failure}; "
                                       f"got {bytes(self.received)!r}")
                if not step:
                    self._arrived.wait(min(left, 0.5))
            if step:
                step()

    def close(self):
        self.conn.close()


class SerialPump:
    """One thread that reads every serial port of a machine as soon as QEMU writes
    (see SerialPort); stop() ends it before the ports are closed."""

    def __init__(self, ports):
        self._ports = {p.conn.fileno(): p for p in ports}
        self._wake_r, self._wake_w = os.pipe()
        self._thread = threading.Thread(target=self._run, name="serial-pump", daemon=True)
        self._thread.start()

    def _run(self):
        sel = selectors.DefaultSelector()
        for fd in self._ports:
            sel.register(fd, selectors.EVENT_READ)
        sel.register(self._wake_r, selectors.EVENT_READ)
        try:
            while True:
                for key, _ in sel.select():
                    if key.fd == self._wake_r:
                        return
                    port = self._ports[key.fd]
                    with port._arrived:
                        port._drain()
                        if port.closed:
                            sel.unregister(key.fd)
        finally:
            sel.close()

    def stop(self):
        os.write(self._wake_w, b"x")
        self._thread.join()
        os.close(self._wake_r)
        os.close(self._wake_w)


class Machine:
    """One QEMU process (the robocube machine unless told otherwise) with qtest
    (optional), QMP and serial sockets."""

    def __init__(self, kernel=None, qtest=None, extra_args=(), timeout=20.0,
                 disable_watchdog=True, qemu=None, machine="robocube",
                 serial_names=SERIAL_NAMES, paused=False):
        """kernel: ELF to run (then the CPU runs, no qtest unless qtest=True).
        disable_watchdog (qtest only): write SYPCR = 0 first, because the SIM
        software watchdog is on at reset (15.6 ms) and would reset the board
        during clock_step; SYPCR is write-once, so tests of SYPCR pass False.
        qemu, machine, serial_names: another QEMU binary and machine (the
        stm32f405 board: qemu-system-arm, netduinoplus2, its one console
        USART), whose serial ports are served in the same way.
        A running CPU starts paused (-S) and is continued once QMP is up, so
        its first instruction comes after every socket is in place: an image
        that prints much or switches the board off at once cannot race the
        set-up. paused=True leaves it paused (the test sends cont)."""
        self.qtest_enabled = (kernel is None) if qtest is None else qtest
        self.dir = tempfile.mkdtemp(prefix="robocube-")
        self.irq_events = []            # (raise: bool, line) from irq_intercept_*
        self._buf = b""
        self.proc = None
        self._qtest = None
        self._pump = None
        self.qmp = None
        listeners = []
        try:
            args = ["-nodefaults"]
            serial_listeners = []
            for i, name in enumerate(serial_names):
                path = os.path.join(self.dir, f"serial{i}.sock")
                lst = self._listen(path)
                serial_listeners.append(lst)
                listeners.append(lst)
                args += ["-chardev", f"socket,id=ser{i},path={path}",
                         "-serial", f"chardev:ser{i}"]
            qmp_path = os.path.join(self.dir, "qmp.sock")
            qmp_listener = self._listen(qmp_path)
            listeners.append(qmp_listener)
            args += ["-qmp", f"unix:{qmp_path}"]
            if self.qtest_enabled:
                qtest_path = os.path.join(self.dir, "qtest.sock")
                qtest_listener = self._listen(qtest_path)
                listeners.append(qtest_listener)
                args += ["-accel", "qtest", "-qtest", f"unix:{qtest_path}"]
            else:
                args += ["-accel", "tcg", "-S"]
            args += list(extra_args)
            # icount=None: the run's -icount, if any, comes in extra_args.
            self.args = launch.command(args, kernel=kernel or None, icount=None, qemu=qemu,
                                       machine=machine)
            self.stderr_path = os.path.join(self.dir, "stderr.log")
            with open(self.stderr_path, "w") as stderr:
                self.proc = launch.popen(args, kernel=kernel or None, icount=None, qemu=qemu,
                                         machine=machine, stdout=subprocess.DEVNULL, stderr=stderr)
            # QEMU connects the chardevs, then qtest, then QMP, in this order.
            self.serial = [SerialPort(name, self._accept(lst, timeout))
                           for name, lst in zip(serial_names, serial_listeners)]
            self._pump = SerialPump(self.serial)
            if self.qtest_enabled:
                self._qtest = self._accept(qtest_listener, timeout)
            # A reply may be slow on a loaded host (once 30 s at a load average
            # of 20 on 2 cores); QMP_REPLY_TIMEOUT bounds the wait all the same.
            self.qmp = QMPLink(sock=self._accept(qmp_listener, timeout),
                               timeout=QMP_REPLY_TIMEOUT)
            if self.qtest_enabled and disable_watchdog and machine == "robocube":
                self.writeb(SYPCR, 0x00)
            if not self.qtest_enabled and not paused:
                self.qmp.command("cont")
        except BaseException:
            self.close()
            raise
        finally:
            for lst in listeners:
                lst.close()

    # -- process plumbing -------------------------------------------------
    @staticmethod
    def _listen(path):
        lst = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        lst.bind(path)
        lst.listen(1)
        return lst

    def _accept(self, listener, timeout):
        listener.settimeout(timeout)
        try:
            conn, _ = listener.accept()
        except socket.timeout:
            raise QTestError("QEMU did not connect: " + self.stderr()) from None
        conn.settimeout(None)
        return conn

    def stderr(self):
        try:
            with open(self.stderr_path) as f:
                return f.read()
        except OSError:
            return ""

    @property
    def console(self):
        return self.serial[0]

    @property
    def radio(self):
        return self.serial[1]

    @property
    def sci(self):
        return self.serial[2]

    def close(self):
        if self._pump:
            self._pump.stop()
            self._pump = None
        if self._qtest:
            self._qtest.close()
            self._qtest = None
        for port in getattr(self, "serial", []):
            port.close()
        if self.qmp:
            try:
                self.qmp.close()
            except Exception:
                pass
            self.qmp = None
        if self.proc:
            if self.proc.poll() is None:
                self.proc.kill()
            self.proc.wait()
            self.proc = None
        shutil.rmtree(self.dir, ignore_errors=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # -- qtest protocol ----------------------------------------------------
    def cmd(self, line):
        """Sends one qtest command; returns the words after OK."""
        if not self._qtest:
            raise QTestError("qtest is not enabled on this machine")
        self._qtest.sendall((line + "\n").encode())
        while True:
            while b"\n" not in self._buf:
                chunk = self._qtest.recv(65536)
                if not chunk:
                    raise QTestError(f"qtest connection closed during {line!r}: "
                                     + self.stderr())
                self._buf += chunk
            reply, self._buf = self._buf.split(b"\n", 1)
            words = reply.decode().split()
            if words[:1] == ["IRQ"]:
                self.irq_events.append((words[1] == "raise", int(words[2])))
                continue
            if words[:1] != ["OK"]:
                raise QTestError(f"qtest {line!r}: {reply.decode()}")
            return words[1:]

    def readb(self, addr):
        return int(self.cmd(f"readb {addr:#x}")[0], 16)

    def readw(self, addr):
        return int(self.cmd(f"readw {addr:#x}")[0], 16)

    def readl(self, addr):
        return int(self.cmd(f"readl {addr:#x}")[0], 16)

    def writeb(self, addr, value):
        self.cmd(f"writeb {addr:#x} {value & 0xFF:#x}")

    def writew(self, addr, value):
        self.cmd(f"writew {addr:#x} {value & 0xFFFF:#x}")

    def writel(self, addr, value):
        self.cmd(f"writel {addr:#x} {value & 0xFFFFFFFF:#x}")

    def memread(self, addr, size):
        return bytes.fromhex(self.cmd(f"read {addr:#x} {size:#x}")[0][2:])

    def memwrite(self, addr, data):
        self.cmd(f"write {addr:#x} {len(data):#x} 0x{bytes(data).hex()}")

    def clock_step(self, ns=None):
        """Advances virtual time by ns (or to the next timer); returns the clock."""
        return int(self.cmd("clock_step" if ns is None else f"clock_step {int(ns)}")[0])

    def clock_now(self):
        return int(self.cmd("clock_step 0")[0])

    def irq_intercept_out(self, qom_path):
        self.cmd(f"irq_intercept_out {qom_path}")

    def irq_intercept_in(self, qom_path):
        self.cmd(f"irq_intercept_in {qom_path}")

    def system_reset(self):
        self.qmp_cmd("system_reset")

    # -- QMP ---------------------------------------------------------------
    def qmp_cmd(self, name, **args):
        return self.qmp.command(name, **args)

    def qom_get(self, path, prop):
        return self.qmp.command("qom-get", path=path, property=prop)

    def qom_set(self, path, prop, value):
        self.qmp.command("qom-set", path=path, property=prop, value=value)

    def console_write_taken(self, data, timeout=10.0):
        """Writes data to the console and returns once the DUART has taken all
        of it into its host queue (its received-b count), not just the chardev.
        With the VM stopped meanwhile, the guest meets the whole of data at the
        same virtual times however slowly the I/O thread hands it over."""
        return self._write_taken(self.console, "received-b", data, timeout)

    def radio_write_taken(self, data, timeout=10.0):
        """The same for the radio port in radio-medium mode (received-a counts
        the medium's bytes there): returns once the model has them all."""
        return self._write_taken(self.radio, "received-a", data, timeout)

    def _write_taken(self, port, counter, data, timeout):
        before = self.qom_get("/machine/duart", counter)
        port.write(data)
        deadline = time.monotonic() + timeout
        while self.qom_get("/machine/duart", counter) - before < len(data):
            assert time.monotonic() < deadline, f"the DUART did not take all the data ({counter})"
            time.sleep(0.005)
        return before


@contextlib.contextmanager
def start(**kwargs):
    """Context manager around Machine(**kwargs) that always stops QEMU."""
    machine = Machine(**kwargs)
    try:
        yield machine
    finally:
        machine.close()
