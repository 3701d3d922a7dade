"""net/auth.c and the CPU32 build of Mbed TLS (ci/setup.d/mbedtls.sh) on the
emulated board (auth_board.c): big-endian CPU32 code that computes the same
CMAC as RFC 4493 and the same sealed bytes as the host peer, and its cost."""
import os
import re
import subprocess
import sys

import pytest
from netpeer import auth

import auth_measure
from test_auth_python import KEY, RFC_MACS

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))

ELF = os.environ.get("NET_AUTH_BOARD_ELF") or os.path.join(ROOT, "build", "net", "auth",
                                                            "board", "auth_board.elf")
QEMU = os.environ.get("BSCHED_QEMU") or os.path.join(ROOT, "build", "emu", "qemu-system-m68k")


@pytest.fixture(scope="module")
def board():
    return auth_measure.console(QEMU, ELF)


def test_board_cmac_is_rfc4493(board):
    got = dict(re.findall(r"^AUTH-BOARD CMAC (\d+) ([0-9a-f]+)$", board, re.M))
    assert {int(k): v for k, v in got.items()} == RFC_MACS


def test_board_seals_what_the_host_peer_seals(board):
    seals = re.findall(r"^AUTH-BOARD SEAL (\d+) (\d+) (\d+) (\d+) ([0-9a-f]+)$", board, re.M)
    payload = bytes((0x7B + i) & 0xFF for i in range(40))
    tx = auth.Auth(KEY, 10)
    header = bytes((3, 0xFF, 0x07, 0x7E))
    expected = [tx.seal(header, payload), tx.seal(header, b""), tx.seal(header, payload)]
    assert len(seals) == 3
    for (s, d, t, q, hexed), e in zip(seals, expected):
        assert bytes(map(int, (s, d, t, q))) == header
        assert bytes.fromhex(hexed) == e
    # The host peer opens the board's frames; the board refused a replay and a forgery.
    rx = auth.Auth(KEY, 0)
    assert rx.open(header, bytes.fromhex(seals[0][4])) == payload
    assert re.search(r"^AUTH-BOARD OPEN good 40$", board, re.M)
    assert re.search(rf"^AUTH-BOARD OPEN replayed {auth.EREPLAY}$", board, re.M)
    assert re.search(rf"^AUTH-BOARD OPEN forged {auth.EFORGED}$", board, re.M)
    rounds = re.findall(r"^AUTH-BOARD ROUND \d+ (.*)$", board, re.M)
    assert rounds == [f"seal 136 open 128 seal-ack 8 open-ack 0 forged {auth.EFORGED}"] * 4
    assert "AUTH-BOARD DONE\n" in board


def test_board_cost_per_call():
    """Every measured call seen once per round; the MIC's cost does not depend
    on the data (AES and CMAC have no data-dependent branches): a seal costs
    the same in every round, and refusing a forged frame costs what taking a
    good one does, to within the few instructions of the counter update."""
    found, _ = auth_measure.costs(QEMU, ELF)
    print()
    print(auth_measure.report(found, auth_measure.footprint(ELF.replace(".elf", ".map"))))
    for name, counts in found.items():
        assert len(counts) == 4, (name, counts)
    for name in ("seal 128", "seal ACK", "open 128 forged"):
        assert len(set(found[name])) == 1, (name, found[name])
    assert abs(found["open 128 forged"][0] - found["open 128"][-1]) < 40
    # A full payload is 8 more AES blocks than an ACK's one: the difference
    # must be about 8 block costs, not something that grew elsewhere.
    per_block = (found["seal 128"][0] - found["seal ACK"][0]) / 8
    assert 500 < per_block < 4000, per_block


def test_board_image_is_cpu32_code_only():
    """Mbed TLS as built by ci/setup.d/mbedtls.sh, auth.c and the runtime hold
    no instruction the CPU32 lacks (assure/cpu32_isa.py, the scan every
    firmware image gets): the board model would trap on one only when reached."""
    out = subprocess.run([sys.executable, os.path.join(ROOT, "assure", "cpu32_isa.py"), ELF],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    count = int(re.search(r"^ok \S+: (\d+) instructions, all CPU32$", out.stdout, re.M)[1])
    assert count > 3000, count
