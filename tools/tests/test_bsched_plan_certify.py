"""bsched-plan --certify / --recheck: CBMC's certificate for one priority set
(--method cbmc; the run+check method: test_bsched_plan_check.py).

Each CBMC run of the paper's Table 1 set (9 processes, maxpv 4) takes 5-10 s of CPU.
"""
import hashlib
import os
import re
import shutil
import subprocess

import pytest

PLAN = os.environ.get("BSCHED_PLAN", os.path.join(os.path.dirname(__file__), "../../build/bin/bsched-plan"))
SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../bsched")
TABLE1_PV = ["1", "1", "1", "2", "2", "3", "4", "4", "4"]


def run(*args, timeout=600):
    return subprocess.run([PLAN, *args], capture_output=True, text=True, timeout=timeout)


def fields(path):
    text = open(path, encoding="utf-8").read()
    return dict(re.findall(r"^([\w.-]+): (.*)$", text, re.M)), text


def with_digest(body_lines, seconds="1.0"):
    """A certificate whose own digest is right for its lines (as a forger would write it)."""
    body = "".join(line + "\n" for line in body_lines)
    return body + "seconds: %s\ncertificate-sha256: %s\n" % (seconds, hashlib.sha256(body.encode()).hexdigest())


@pytest.fixture(scope="module")
def table1_certificate(tmp_path_factory):
    path = tmp_path_factory.mktemp("cert") / "table1.cert"
    r = run("--certify", str(path), *TABLE1_PV)
    return path, r


def test_table1_set_is_certified(table1_certificate):
    path, r = table1_certificate
    assert r.returncode == 0, r.stdout + r.stderr
    f, text = fields(path)
    # 9 x 2^4 = 144 process-cycles: --method auto takes CBMC
    assert text.startswith("bsched-plan certificate 2\nmethod: cbmc\n")
    assert f["verdict"] == "CERTIFIED"
    assert f["set"] == " ".join(TABLE1_PV)
    assert f["processes"] == "9" and f["maxpv"] == "4"
    assert f["bsched.c-sha256"] == hashlib.sha256(open(os.path.join(SOURCE, "bsched.c"), "rb").read()).hexdigest()
    assert f["cbmc"].startswith("6.")
    assert int(f["properties"]) > 100 and f["failed"] == "0"
    log = open(str(path) + ".log", encoding="utf-8").read()
    # CBMC's own count, and every property of the harness is among them.
    assert "** 0 of %s failed" % f["properties"] in log
    for what in ("period: runs exactly 2^pv cycles apart", "load: at most perfect processes in every cycle",
                 "idle: no idle cycle while U >= 1", "fig7: the same processes in the same order as Fig. 7"):
        assert re.search(re.escape(what) + r".*: SUCCESS$", log, re.M), what


def test_recheck_reproduces_a_good_certificate(table1_certificate):
    path, _ = table1_certificate
    r = run("--recheck", str(path))
    assert r.returncode == 0, r.stdout + r.stderr
    assert "recheck: OK" in r.stdout


def test_recheck_refuses_a_corrupted_certificate(table1_certificate, tmp_path):
    path, _ = table1_certificate
    bad = tmp_path / "bad.cert"
    bad.write_text(open(path, encoding="utf-8").read().replace("verdict: CERTIFIED", "verdict: CERTIFIED!"))
    r = run("--recheck", str(bad))
    assert r.returncode == 1
    assert "corrupted" in r.stdout


def test_recheck_finds_a_forged_line_by_running_the_check_again(table1_certificate, tmp_path):
    """The digest is only a checksum: a certificate re-digested after a change is
    caught by re-running CBMC and comparing."""
    path, _ = table1_certificate
    f, text = fields(path)
    lines = text.splitlines()
    body = [l for l in lines if not l.startswith(("seconds:", "certificate-sha256:"))]
    body = [("properties: %d" % (int(f["properties"]) - 1)) if l.startswith("properties:") else l for l in body]
    forged = tmp_path / "forged.cert"
    forged.write_text(with_digest(body))
    r = run("--recheck", str(forged))
    assert r.returncode == 1
    assert "differs: properties" in r.stdout and "FAILED" in r.stdout


def test_a_broken_bsched_c_is_not_certified(tmp_path):
    """bsched.c built as the unbalanced mutant (identity instead of bit reversal):
    CBMC reports failed properties, and the certificate says so."""
    src = tmp_path / "bsched"
    shutil.copytree(SOURCE, src, ignore=shutil.ignore_patterns("tests", "wp", "cbmc", "dist"))
    lib = src / "bsched.c"
    lib.write_text("#define BSCHED_MUTANT_NO_REVERSE 1\n" + lib.read_text())
    cert = tmp_path / "broken.cert"
    r = run("--certify", str(cert), "--method", "cbmc", "--source", str(src), "1", "1", "2", "2")
    assert r.returncode == 1, r.stdout + r.stderr
    f, _ = fields(cert)
    assert f["verdict"].startswith("NOT CERTIFIED") and int(f["failed"]) >= 1
    assert ": FAILURE" in open(str(cert) + ".log", encoding="utf-8").read()


def test_time_limit_stops_cbmc_and_is_not_certified(tmp_path):
    cert = tmp_path / "slow.cert"
    r = run("--certify", str(cert), "--method", "cbmc", "--time-limit", "1", *(["8"] * 64))
    assert r.returncode == 1
    assert fields(cert)[0]["verdict"] == "NOT CERTIFIED: time limit of 1 s"


@pytest.mark.parametrize("args, names", [
    (["--certify", "x.cert"], "no priority values"),
    (["--certify", "x.cert", "1", "x"], "'x'"),
    (["--certify", "x.cert", "-1"], "'-1'"),
    (["--certify", "x.cert", "32"], "'32'"),
    (["--certify", "x.cert", "21"], "'21'"),
    (["--certify", "x.cert", "17"], "'17'"),
    (["--certify"], "'--certify'"),
    (["--recheck"], "'--recheck'"),
    (["--certify", "x.cert", "--time-limit", "0", "1"], "'0'"),
    (["--certify", "x.cert", "--json", "1"], "'x.cert'"),
    (["--recheck", "x.cert", "1"], "'x.cert'"),
])
def test_bad_input_is_refused_as_bsched_plan_refuses_it(args, names, tmp_path):
    r = subprocess.run([PLAN, *args], capture_output=True, text=True, timeout=60, cwd=tmp_path)
    assert r.returncode == 2
    assert r.stdout == ""
    assert len(r.stderr.splitlines()) == 1 and names in r.stderr
    assert not (tmp_path / "x.cert").exists()
