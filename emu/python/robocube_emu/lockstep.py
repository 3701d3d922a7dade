"""The lockstep device (/machine/lockstep, emu/README.md "Lockstep"): QEMU
stops at every boundary of virtual time, sends one line on the lockstep
chardev ("S STEPS BOUNDARY_NS V...", the sampled properties) and resumes once
the host answers with one line of inputs ("I V..."). QMP only sets the lists
up: a QMP command costs about as much as a whole step."""

import os
import shutil
import socket
import subprocess
import tempfile

from . import launch
from .qmp import QMPLink

LOCKSTEP = "/machine/lockstep"
FRAME_TIMEOUT_S = 60.0


class Emulator:
    """qemu-system-m68k -M robocube running `elf`, paused at start (-S), the
    lockstep device on with boundaries every step_ns, the console on a pipe
    (read_console)."""

    def __init__(self, qemu, elf, step_ns, extra_args=()):
        self.dir = tempfile.mkdtemp(prefix="bsched-eco-")
        sock = os.path.join(self.dir, "qmp")
        frames = os.path.join(self.dir, "lockstep")
        self.stderr_path = os.path.join(self.dir, "stderr")
        self._stderr = open(self.stderr_path, "wb")
        self.proc = launch.popen(
            ["-serial", "stdio", "-qmp", f"unix:{sock},server=on,wait=off",
             "-chardev", f"socket,id=lockstep,path={frames},server=on,wait=off",
             "-global", "robocube-lockstep.chardev=lockstep",
             "-S", "-global", f"robocube-lockstep.step-ns={step_ns}", *extra_args],
            kernel=elf, qemu=qemu, stderr=self._stderr)
        os.set_blocking(self.proc.stdout.fileno(), False)
        self.console = b""
        try:
            self.qmp = QMPLink(sock, proc=self.proc)
            self.frames = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            self.frames.connect(frames)
            self.frames.settimeout(FRAME_TIMEOUT_S)
            self.frame_buf = b""
        except Exception:
            self.close()
            raise

    def read_frame(self):
        """The next "S STEPS BOUNDARY_NS V..." line, as a list of ints."""
        while b"\n" not in self.frame_buf:
            try:
                chunk = self.frames.recv(65536)
            except socket.timeout:
                raise RuntimeError(f"lockstep: no frame from QEMU in {FRAME_TIMEOUT_S} s "
                                   "(the machine hangs or died)") from None
            if not chunk:
                raise RuntimeError("lockstep: QEMU closed the frame channel")
            self.frame_buf += chunk
        line, self.frame_buf = self.frame_buf.split(b"\n", 1)
        words = line.decode().split()
        if words[0] != "S":
            raise RuntimeError(f"lockstep: QEMU refused a frame: {line.decode()}")
        return [int(w) for w in words[1:]]

    def send_inputs(self, values):
        self.frames.sendall(("I " + " ".join(str(int(v)) for v in values) + "\n").encode())

    def read_console(self):
        """New complete console lines since the last call."""
        try:
            chunk = self.proc.stdout.read()
        except BlockingIOError:
            chunk = None
        if chunk:
            self.console += chunk
        *lines, self.console = self.console.split(b"\n")
        return [ln.decode(errors="replace").rstrip("\r") for ln in lines]

    def close(self):
        """Stops QEMU; returns what it wrote on stderr."""
        if getattr(self, "frames", None):
            self.frames.close()
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait()
        self._stderr.close()
        with open(self.stderr_path, errors="replace") as f:
            err = f.read()
        shutil.rmtree(self.dir, ignore_errors=True)
        return err
