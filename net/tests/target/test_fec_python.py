"""net/fec.c and net/rs.c against the host peer's FEC (tools/netpeer, on
reedsolo), both directions, with errors the code must correct."""
import os
import random
import subprocess

from netpeer.protocol import FEC_COPIES, FEC_N, PREAMBLE, FecDecoder, Frame, encode_frame_fec

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))

TOOL = os.environ.get("NET_FEC_SAMPLE") or os.path.join(ROOT, "build", "net", "tests",
                                                         "fec_sample")
HEAD = len(PREAMBLE) + 1 + FEC_COPIES


def c_encode(f):
    out = subprocess.run([TOOL, "encode", str(f.src), str(f.dst), str(f.type), str(f.seq),
                          f.payload.hex()], capture_output=True, text=True, check=True)
    return bytes.fromhex(out.stdout.strip())


def c_decode(data):
    out = subprocess.run([TOOL, "decode", data.hex()], capture_output=True, text=True,
                         check=True)
    frames = []
    for line in out.stdout.split("\n"):
        if line:
            src, dst, typ, seq, payload, corrected = line.split(" ")
            frames.append((Frame(int(src), int(dst), int(typ), int(seq),
                                 bytes.fromhex(payload)), int(corrected)))
    return frames


def corrupt(data, rng, per_codeword):
    """per_codeword wrong bytes in every codeword, and two of the five counts."""
    out = bytearray(data)
    out[len(PREAMBLE) + 1] ^= 0xFF
    out[len(PREAMBLE) + 4] ^= 0x0F
    for start in range(HEAD, len(out), FEC_N):
        for p in rng.sample(range(FEC_N), per_codeword):
            out[start + p] ^= rng.randrange(1, 256)
    return bytes(out)


FRAMES = [Frame(1, 9, 2, 0), Frame(9, 1, 1, 255, bytes(range(128))),
          Frame(3, 255, 3, 7, b"\x7e\x7d\x55" * 10), Frame(0, 1, 1, 42, b"x" * 17)]


def test_c_encoding_equals_reedsolo():
    for f in FRAMES:
        assert c_encode(f) == encode_frame_fec(f), f


def test_c_corrects_what_python_sent():
    rng = random.Random(1)
    for f in FRAMES:
        got = c_decode(b"\x00\x55" + corrupt(encode_frame_fec(f), rng, 6) + b"\x55")
        ncw = (len(encode_frame_fec(f)) - HEAD) // FEC_N
        assert got == [(f, 6 * ncw)]


def test_python_corrects_what_c_sent():
    rng = random.Random(2)
    for f in FRAMES:
        d = FecDecoder()
        assert d.feed(b"\x13" + corrupt(c_encode(f), rng, 6)) == [f]
        assert d.corrected == 6 * ((len(c_encode(f)) - HEAD) // FEC_N)


def test_both_refuse_seven_errors_in_a_codeword():
    rng = random.Random(3)
    f = FRAMES[1]
    bad = corrupt(encode_frame_fec(f), rng, 7)
    assert c_decode(bad) == []
    d = FecDecoder()
    assert d.feed(bad) == [] and d.uncorrectable + d.bad_frames == 1
