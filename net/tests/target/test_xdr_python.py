"""net/xdr.c against Python's xdrlib3 (the host peer's XDR), both directions."""
import os
import subprocess

import pytest
import xdrlib3

TOOL = os.environ.get("NET_XDR_SAMPLE") or os.path.join(
    os.path.dirname(__file__), "..", "..", "..", "build", "net", "tests", "xdr_sample")

VALUES = dict(i=-123456, u=4000000000, h=-9000000000000000000, uh=18000000000000000000, b=True,
              e=7, f=-2.5, d=3.141592653589793, fixed=b"RoboC", var=bytes((1, 2, 3)),
              s=b"radio", arr=[1, -1, 65536, -65536])


def pack(v):
    p = xdrlib3.Packer()
    p.pack_int(v["i"]); p.pack_uint(v["u"]); p.pack_hyper(v["h"]); p.pack_uhyper(v["uh"])
    p.pack_bool(v["b"]); p.pack_enum(v["e"]); p.pack_float(v["f"]); p.pack_double(v["d"])
    p.pack_fopaque(5, v["fixed"]); p.pack_bytes(v["var"]); p.pack_string(v["s"])
    p.pack_array(v["arr"], p.pack_int)
    return p.get_buffer()


def test_c_encoding_equals_xdrlib3():
    out = subprocess.run([TOOL, "encode"], capture_output=True, text=True, check=True)
    assert bytes.fromhex(out.stdout.strip()) == pack(VALUES)


def test_c_decodes_xdrlib3_bytes():
    v = dict(VALUES, i=2**31 - 1, e=-3, f=0.15625, s=b"", arr=[])
    out = subprocess.run([TOOL, "decode", pack(v).hex()], capture_output=True, text=True,
                         check=True).stdout.split("\n")
    assert out[:8] == [str(v["i"]), str(v["u"]), str(v["h"]), str(v["uh"]), "1", "-3",
                       "0.15625", "3.1415926535897931"]
    assert out[8] == "RoboC" and out[9] == "1 2 3 " and out[10] == "" and out[11] == ""


def test_c_refuses_truncated_xdrlib3_bytes():
    data = pack(VALUES)
    r = subprocess.run([TOOL, "decode", data[:-2].hex()], capture_output=True)
    assert r.returncode == 3
