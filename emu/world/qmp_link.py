"""A small synchronous QMP client that pipelines commands.

Why not qemu.qmp (used by the device tests): the lockstep loop exchanges two
batches of commands with QEMU every 10 ms of virtual time, tens of thousands
of times per run, and its cost is the real-time factor. QMP answers commands
in the order they were sent, so a batch can go out in one write and its
answers come back in one read; qemu.qmp's asyncio client (or its synchronous
legacy wrapper) costs a round trip and an event-loop turn per command.
Measured in emu/world/README.md.
"""

import json
import socket
import time


class QMPError(RuntimeError):
    pass


class QMPLink:
    def __init__(self, path, timeout=30.0):
        self.timeout = timeout
        deadline = time.monotonic() + timeout
        while True:
            try:
                self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
                self.sock.connect(path)
                break
            except (FileNotFoundError, ConnectionRefusedError):
                self.sock.close()
                if time.monotonic() > deadline:
                    raise QMPError(f"QMP socket {path}: QEMU did not open it in {timeout} s")
                time.sleep(0.01)
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
        order. Events that arrive meanwhile are kept in self.events."""
        out = []
        for name, args in commands:
            msg = {"execute": name}
            if args is not None:
                msg["arguments"] = args
            out.append(json.dumps(msg, separators=(",", ":")))
        self.sock.sendall(("\n".join(out) + "\n").encode())
        results = []
        while len(results) < len(commands):
            msg = self._read_message()
            if "event" in msg:
                self.events.append(msg)
            elif "error" in msg:
                name = commands[len(results)]
                raise QMPError(f"{name[0]} {name[1]}: {msg['error'].get('desc')}")
            else:
                results.append(msg.get("return"))
        return results

    def execute(self, name, args=None):
        return self.batch([(name, args)])[0]

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


def qom_get(path, prop):
    return ("qom-get", {"path": path, "property": prop})


def qom_set(path, prop, value):
    return ("qom-set", {"path": path, "property": prop, "value": value})
