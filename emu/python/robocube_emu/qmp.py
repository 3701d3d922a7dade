"""The QMP client of every test and tool: small, synchronous, and it pipelines.

Why not qemu.qmp: the lockstep loop exchanges batches of commands with QEMU
tens of thousands of times per run, and its cost is the real-time factor. QMP
answers commands in the order they were sent, so a batch can go out in one
write and its answers come back in one read; qemu.qmp's asyncio client (or its
synchronous legacy wrapper) costs a round trip and an event-loop turn per
command. Measured in emu/world/README.md.
"""

import json
import socket
import time


class QMPError(RuntimeError):
    pass


class QMPLink:
    """One QMP connection, capabilities negotiated. Either `path`, the Unix
    socket of a QEMU started with -qmp unix:PATH,server=on,wait=off (the socket
    can appear before QEMU listens on it, so connecting is retried until
    `timeout` seconds pass or `proc`, the QEMU, exits), or `sock`, a connected
    socket (QEMU started with -qmp unix:PATH connects to a listener of ours)."""

    def __init__(self, path=None, timeout=30.0, proc=None, sock=None):
        self.timeout = timeout
        if sock is None:
            deadline = time.monotonic() + timeout
            while True:
                sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
                try:
                    sock.connect(str(path))
                    break
                except (FileNotFoundError, ConnectionRefusedError):
                    sock.close()
                    if proc is not None and proc.poll() is not None:
                        raise QMPError(f"QMP socket {path}: QEMU exited "
                                       f"(status {proc.returncode})") from None
                    if time.monotonic() > deadline:
                        raise QMPError(f"QMP socket {path}: QEMU did not open it in "
                                       f"{timeout} s") from None
                    time.sleep(0.01)
        self.sock = sock
        self.sock.settimeout(timeout)
        self.buf = b""
        self.events = []
        greeting = self._read_message()
        if "QMP" not in greeting:
            raise QMPError(f"unexpected QMP greeting {greeting!r}")
        self.batch([("qmp_capabilities", None)])

    def close(self):
        self.sock.close()

    def _read_message(self):
        while b"\n" not in self.buf:
            try:
                chunk = self.sock.recv(65536)
            except socket.timeout:
                raise QMPError(f"QEMU sent nothing for {self.timeout} s") from None
            if not chunk:
                raise QMPError("QEMU closed the QMP connection")
            self.buf += chunk
        line, self.buf = self.buf.split(b"\n", 1)
        return json.loads(line)

    def batch(self, commands):
        """Sends every (command, arguments) at once; returns their results in
        order. Every answer is read before the first error, if any, is raised,
        so the connection stays in step. Events that arrive meanwhile are kept
        in self.events."""
        out = []
        for name, args in commands:
            msg = {"execute": name}
            if args is not None:
                msg["arguments"] = args
            out.append(json.dumps(msg, separators=(",", ":")))
        self.sock.sendall(("\n".join(out) + "\n").encode())
        results, error = [], None
        while len(results) < len(commands):
            msg = self._read_message()
            if "event" in msg:
                self.events.append(msg)
                continue
            if "error" in msg and error is None:
                name, args = commands[len(results)]
                error = QMPError(f"{name} {args}: {msg['error'].get('desc')}")
            results.append(msg.get("return"))
        if error:
            raise error
        return results

    def execute(self, name, args=None):
        return self.batch([(name, args)])[0]

    def command(self, name, **args):
        """execute() with keyword arguments (qemu.qmp's spelling)."""
        return self.execute(name, args or None)

    def wait_event(self, name):
        """Returns the next event called name (earlier other events are dropped)."""
        while True:
            while self.events:
                ev = self.events.pop(0)
                if ev["event"] == name:
                    return ev
            msg = self._read_message()
            if "event" in msg:
                self.events.append(msg)
            else:
                raise QMPError(f"unexpected QMP answer while waiting for {name}: {msg!r}")


def connect(path, proc=None, timeout=10.0):
    """A QMPLink to QEMU's QMP server socket `path` (see QMPLink)."""
    return QMPLink(path, timeout=timeout, proc=proc)


def qom_get(path, prop):
    return ("qom-get", {"path": path, "property": prop})


def qom_set(path, prop, value):
    return ("qom-set", {"path": path, "property": prop, "value": value})
