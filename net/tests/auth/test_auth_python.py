"""net/auth.c (host build, through net/tests/auth_sample.c) against the host
peer's tools/netpeer/auth.py on the cryptography package: the same CMAC, the
same MIC and sealed bytes for random frames, and each side opens what the
other sealed with the same verdicts."""
import os
import random
import re
import subprocess

import pytest
from netpeer import auth

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))

TOOL = os.environ.get("NET_AUTH_SAMPLE") or os.path.join(ROOT, "build", "net", "tests",
                                                          "auth_sample")
KEY = b"BSCHED-RADIO-KEY"      # the test key of test_auth.c and auth_board.c
RFC_KEY = bytes.fromhex("2b7e151628aed2a6abf7158809cf4f3c")
RFC_MSG = bytes.fromhex("6bc1bee22e409f96e93d7e117393172aae2d8a571e03ac9c9eb76fac45af8e51"
                        "30c81c46a35ce411e5fbc1191a0a52eff69f2445df4f9b17ad2b417be66c3710")
RFC_MACS = {0: "bb1d6929e95937287fa37d129b756746", 16: "070a16b46b4d4144f79bdd9dd04a287c",
            40: "dfa66747de9ae63030ca32611497c827", 64: "51f0bebf7e3b9d92fc49741779363cfe"}


def run_c(commands):
    """Runs auth_sample on the command lines; returns its answer lines."""
    out = subprocess.run([TOOL], input="\n".join(commands) + "\n", capture_output=True,
                         text=True, check=True).stdout.split("\n")
    assert out[-1] == ""
    assert len(out) - 1 == len(commands), out[-5:]
    return out[:-1]


def hx(b):
    return b.hex() if b else "-"


def random_frames(rng, n):
    for _ in range(n):
        header = bytes((rng.randrange(16), rng.randrange(256), rng.randrange(256),
                        rng.randrange(256)))
        length = rng.choice((0, 1, 15, 16, 17, 126, 127, 128, rng.randrange(129)))
        yield header, bytes(rng.randrange(256) for _ in range(length))


def test_python_cmac_is_rfc4493():
    for n, mac in RFC_MACS.items():
        assert auth.cmac(RFC_KEY, RFC_MSG[:n]).hex() == mac


def test_c_and_python_cmac_equal_on_rfc_and_random_messages():
    rng = random.Random(4493)
    msgs = [RFC_MSG[:n] for n in RFC_MACS] + [
        bytes(rng.randrange(256) for _ in range(rng.randrange(200))) for _ in range(200)]
    got = run_c([f"key {RFC_KEY.hex()}"] + [f"cmac {hx(m)}" for m in msgs])
    assert got[0] == "0"
    assert got[1:] == [auth.cmac(RFC_KEY, m).hex() for m in msgs]
    assert got[1:5] == list(RFC_MACS.values())


def test_mic_equal_for_random_frames():
    rng = random.Random(1)
    frames = [(h, rng.randrange(1 << 32), p) for h, p in random_frames(rng, 1000)]
    got = run_c([f"key {KEY.hex()}"] +
                [f"mic {h[0]} {h[1]} {h[2]} {h[3]} {fcnt} {hx(p)}" for h, fcnt, p in frames])
    assert got[0] == "0"
    assert got[1:] == [auth.mic(KEY, h, fcnt, p).hex() for h, fcnt, p in frames]


def test_sealed_bytes_equal_and_each_opens_the_others():
    """C seals a stream (epoch 9): the bytes equal Python's; Python opens them.
    Python seals a stream (epoch 3); C opens it; then both refuse the same
    replayed, forged and malformed frames with the same codes."""
    rng = random.Random(2)
    frames = list(random_frames(rng, 300))
    c_sealed = run_c([f"key {KEY.hex()}", "init 9"] +
                     [f"seal {h[0]} {h[1]} {h[2]} {h[3]} {hx(p)}" for h, p in frames])[2:]
    py_tx, py_rx = auth.Auth(KEY, 9), auth.Auth(KEY, 0)
    for (h, p), c in zip(frames, c_sealed):
        sealed = py_tx.seal(h, p)
        assert c == sealed.hex()
        assert py_rx.open(h, sealed) == p

    py_tx = auth.Auth(KEY, 3)
    stream = [(h, py_tx.seal(h, p)) for h, p in frames]
    replayed = stream[::7]
    forged = []
    for h, s in stream[::11]:
        b = bytearray(s)
        b[rng.randrange(len(b))] ^= 1 << rng.randrange(8)
        forged.append((h, bytes(b)))
    malformed = [(bytes((16, 1, 1, 0)), stream[0][1]), (stream[0][0], b"\x00" * 7)]
    tests = stream + replayed + forged + malformed
    got = run_c([f"key {KEY.hex()}", "init 0"] +
                [f"open {h[0]} {h[1]} {h[2]} {h[3]} {hx(s)}" for h, s in tests])[2:]
    py_rx = auth.Auth(KEY, 0)
    expected = []
    for h, s in tests:
        try:
            expected.append(str(len(py_rx.open(h, s))))
        except auth.AuthError as e:
            expected.append(str(e.code))
    assert got == expected
    n = len(stream)
    assert got[:n] == [str(len(p)) for _, p in frames]
    assert set(got[n:n + len(replayed)]) == {str(auth.EREPLAY)}
    assert set(got[n + len(replayed):n + len(replayed) + len(forged)]) == {str(auth.EFORGED)}
    assert got[-2:] == [str(auth.EMALFORMED)] * 2
    assert py_rx.stats == {"sealed": 0, "opened": n, "forged": len(forged),
                           "replayed": len(replayed), "malformed": 2}


def test_restart_with_next_epoch_in_python_as_in_c():
    h = bytes((5, 1, 1, 0))
    rx = auth.Auth(KEY, 0)
    boot1 = auth.Auth(KEY, 41)
    old = [boot1.seal(h, b"x") for _ in range(3)]
    for s in old:
        rx.open(h, s)
    boot2 = auth.Auth(KEY, 42)
    assert rx.open(h, boot2.seal(h, b"y")) == b"y"
    with pytest.raises(auth.Replayed):
        rx.open(h, old[-1])
    with pytest.raises(auth.Replayed):
        rx.open(h, auth.Auth(KEY, 42).seal(h, b"y"))     # a boot that did not advance
    with pytest.raises(ValueError):
        auth.Auth(KEY, auth.EPOCH_MAX + 1)


def test_constants_equal_auth_h():
    text = open(os.path.join(ROOT, "net", "auth.h")).read()
    defs = dict(re.findall(r"^#define (AUTH_\w+)\s+\(?(-?\w+)u?\)?", text, re.M))
    number = {k: int(v.rstrip("u"), 0) for k, v in defs.items()
              if re.fullmatch(r"-?(0x[0-9a-fA-F]+|\d+)u?", v)}
    python = {"AUTH_KEY_LEN": auth.KEY_LEN, "AUTH_HEADER_LEN": auth.HEADER_LEN,
              "AUTH_FCNT_LEN": auth.FCNT_LEN, "AUTH_MIC_LEN": auth.MIC_LEN,
              "AUTH_PAYLOAD_MAX": auth.PAYLOAD_MAX, "AUTH_STATIONS": auth.STATIONS,
              "AUTH_CMAC_LEN": auth.CMAC_LEN, "AUTH_COUNT_BITS": auth.COUNT_BITS,
              "AUTH_OK": auth.OK, "AUTH_EFORGED": auth.EFORGED, "AUTH_EREPLAY": auth.EREPLAY,
              "AUTH_EMALFORMED": auth.EMALFORMED, "AUTH_EINVAL": auth.EINVAL,
              "AUTH_EEXHAUSTED": auth.EEXHAUSTED, "AUTH_ECRYPTO": auth.ECRYPTO}
    assert {k: number[k] for k in python} == python
