"""Boards running apps/netnode on the radio medium: configuration patching and launch."""
import os
import struct
import subprocess
import sys
import threading
import time

import robocube_emu

MAGIC = b"NETNODE\0"
MODES = {"soak": 1, "echo": 2, "bench": 3}
# struct netnode_config after the magic (apps/netnode/netnode.c), big-endian, m68k layout.
CONFIG = struct.Struct(">BBHHHIIBxH")
FLAG_FEC = 0x1
# struct netnode_auth after its magic: key[16], epoch (u32), flags, 3 reserved.
AUTH_MAGIC = b"NETAUTH\0"
AUTH_CONFIG = struct.Struct(">16sIB3x")
AUTH_OFF = 0x1
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
# The firmware's usual deterministic setting (2^8 ns per instruction, idle
# time skipped), with the boards in lock step through the medium every
# SYNC_NS of virtual time (emu/README.md, "Radio medium").
ICOUNT = "shift=8,sleep=off"
SYNC_NS = 500_000


def stop_process(proc):
    """Asks proc to end (SIGTERM), kills it after 5 s, and reaps it."""
    if proc.poll() is None:
        proc.terminate()
        try:
            proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def _block(data, magic, elf):
    at = data.find(magic)
    if at < 0 or data.find(magic, at + 1) >= 0:
        raise ValueError(f"{elf}: no unique {magic[:-1].decode()} configuration block")
    return at + len(magic)


def patch_config(elf_in, elf_out, station, mode="echo", peers=(), messages=10, size=32,
                 seed=1, linger_ms=3000, fec=False, boot=0, key=None, auth=True, epoch=None):
    """boot: this launch's number for the station (0 first). The board's
    authentication epoch is boot unless given (it must grow from boot to boot,
    and the link's session is epoch % 64); key: the network key (16 bytes,
    default the public development key, netpeer.auth.DEV_KEY); auth=False: no
    authentication (every station must agree: only to measure its cost)."""
    from .auth import DEV_KEY, EPOCH_MAX, KEY_LEN
    key = DEV_KEY if key is None else bytes(key)
    epoch = boot if epoch is None else epoch
    if len(key) != KEY_LEN:
        raise ValueError(f"a key is {KEY_LEN} bytes, not {len(key)}")
    if not 0 <= epoch <= EPOCH_MAX:
        raise ValueError(f"epoch {epoch} not in 0..{EPOCH_MAX}")
    data = bytearray(open(elf_in, "rb").read())
    at = _block(data, MAGIC, elf_in) - len(MAGIC)
    auth_at = _block(data, AUTH_MAGIC, elf_in)
    data[auth_at:auth_at + AUTH_CONFIG.size] = AUTH_CONFIG.pack(key, epoch,
                                                                0 if auth else AUTH_OFF)
    mask = 0
    for p in peers:
        mask |= 1 << p
    cfg = CONFIG.pack(station, MODES[mode], mask, messages, size, seed, linger_ms,
                      FLAG_FEC if fec else 0, boot)
    data[at + len(MAGIC):at + len(MAGIC) + CONFIG.size] = cfg
    with open(elf_out, "wb") as f:
        f.write(data)


class Board:
    """One emulated RoboCube whose radio joins the medium at `medium_sock`; or,
    with medium_sock None, whose DUART channel A is a plain wire to a host
    pseudo-terminal (pty_path(): what a serial adapter would be), with the
    virtual clock near the wall clock (sleep=on) since no lock step paces it."""

    def __init__(self, elf, station, medium_sock, workdir, icount=ICOUNT, sync_ns=SYNC_NS,
                 **config):
        self.station = station
        self.elf = os.path.join(workdir, f"netnode-{station}-{config.get('boot', 0)}.elf")
        patch_config(elf, self.elf, station, **config)
        self.console = bytearray()
        self.lock = threading.Lock()
        if medium_sock is None:
            radio = ["-serial", "pty"]
            icount = icount.replace("sleep=off", "sleep=on")
        else:
            radio = ["-chardev", f"socket,id=air,path={medium_sock},reconnect=1",
                     "-serial", "chardev:air",
                     "-global", "mc68681-duart.radio-medium=on",
                     "-global", f"mc68681-duart.radio-station={station}",
                     "-global", f"mc68681-duart.radio-sync-ns={sync_ns}"]
        self.proc = robocube_emu.popen(["-serial", "stdio"] + radio, kernel=self.elf,
                                       icount=icount, stderr=subprocess.STDOUT)
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        for chunk in iter(lambda: self.proc.stdout.read1(4096), b""):
            with self.lock:
                self.console += chunk

    def text(self):
        with self.lock:
            return self.console.decode(errors="replace").replace("\r", "")

    def wait_for(self, marker, timeout):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if marker in self.text():
                return True
            if self.proc.poll() is not None:
                return marker in self.text()
            time.sleep(0.05)
        return False

    def pty_path(self, timeout=10):
        """The pseudo-terminal QEMU made for channel A (medium_sock None)."""
        import re
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            m = re.search(r"char device redirected to (/dev/pts/\d+)", self.text())
            if m:
                return m[1]
            time.sleep(0.05)
        raise RuntimeError("no pty for channel A:\n" + self.text())

    def stop(self):
        stop_process(self.proc)


class MediumProcess:
    def __init__(self, sock, seed=1, loss=0.0, corrupt=0.0, noise=0.0, out_of_range=(),
                 byte_errors=0.0):
        cmd = [sys.executable, "-m", "robocube_emu.radio_medium", "--socket", sock,
               "--seed", str(seed), "--loss", str(loss), "--corrupt", str(corrupt),
               "--noise", str(noise), "--byte-errors", str(byte_errors), "--sync-ns", str(SYNC_NS)]
        if os.environ.get("NET_MEDIUM_TRACE"):
            cmd.append("--trace")
        for a, b in out_of_range:
            cmd += ["--out-of-range", f"{a}:{b}"]
        self.sock = sock
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                     text=True)
        line = self.proc.stdout.readline()
        if "listening" not in line:
            raise RuntimeError(f"radio medium did not start: {line!r}")
        self.output = []
        threading.Thread(target=lambda: self.output.extend(self.proc.stdout), daemon=True).start()

    def control(self, command):
        import socket
        s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        s.settimeout(5)
        s.connect(self.sock + ".ctl")
        s.sendall((command + "\n").encode())
        reply = s.makefile().readline().strip()
        s.close()
        return reply

    def stats(self):
        return dict(kv.split("=") for kv in self.control("stats").split())

    def stop(self):
        stop_process(self.proc)
