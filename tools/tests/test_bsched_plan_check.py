"""bsched-plan --certify --method check (run+check): bsched.c runs the whole major
cycle, the independent checker (tools/bsched-check.c) judges its trace.

Each run compiles bsched.c once (about a second of CPU); the largest set here
(65535 processes, pv 0..16, 5 x 10^8 runs) takes about 10 s.
"""
import hashlib
import json
import os
import random
import re
import shutil
import struct
import subprocess

import pytest

PLAN = os.environ.get("BSCHED_PLAN", os.path.join(os.path.dirname(__file__), "../../build/bin/bsched-plan"))
HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.join(HERE, "../../bsched")
CHECKER = os.path.join(HERE, "../bsched-check.c")
TABLE1_PV = ["1", "1", "1", "2", "2", "3", "4", "4", "4"]
PROPERTIES = ("plan", "period", "balance", "fig7", "repeat")


def run(*args, timeout=600, cwd=None):
    return subprocess.run([PLAN, *args], capture_output=True, text=True, timeout=timeout, cwd=cwd)


def fields(path):
    text = open(path, encoding="utf-8").read()
    return dict(re.findall(r"^([\w.-]+): (.*)$", text, re.M)), text


def sha256_file(path):
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


def spec_digest(source):
    """spec-sha256 as the certificate defines it: the sha256 of the 'digest  name'
    lines of spec/*.h in name order."""
    spec = os.path.join(source, "spec")
    lines = "".join("%s  %s\n" % (sha256_file(os.path.join(spec, n)), n)
                    for n in sorted(os.listdir(spec)) if n.endswith(".h"))
    return hashlib.sha256(lines.encode()).hexdigest()


def failed_checks(f):
    return {k: int(v) for k, v in re.findall(r"(\w+) (\d+)", f["failed-checks"])}


def balance_of(pvs):
    """What the balance theorem says for the set: A = U 2^maxpv runs in all,
    loads floor(U)..ceil(U), and how many cycles run ceil(U)."""
    maxpv = max(pvs)
    cycles = 2 ** maxpv
    area = sum(2 ** (maxpv - p) for p in pvs)
    lo, hi = area // cycles, -(-area // cycles)
    at_hi = area % cycles or cycles
    return cycles, area, "%d..%d, %d of %d cycles at %d" % (lo, hi, at_hi, cycles, hi)


def with_digest(body_lines, seconds="1.0"):
    """A certificate whose own digest is right for its lines (as a forger would write it)."""
    body = "".join(line + "\n" for line in body_lines)
    return body + "seconds: %s\ncertificate-sha256: %s\n" % (seconds, hashlib.sha256(body.encode()).hexdigest())


def body_lines(text):
    return [l for l in text.splitlines() if not l.startswith(("seconds:", "certificate-sha256:"))]


@pytest.fixture(scope="module")
def table1(tmp_path_factory):
    path = tmp_path_factory.mktemp("check") / "table1.cert"
    r = run("--certify", str(path), "--method", "check", *TABLE1_PV)
    return path, r


def test_table2_run_check_certificate(table1):
    path, r = table1
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.startswith("certified: 9 processes, maxpv 4, run+check: 16 cycles, 37 runs, CERTIFIED")
    f, text = fields(path)
    assert text.startswith("bsched-plan certificate 2\nmethod: run+check\n")
    assert f["verdict"] == "CERTIFIED" and f["failed"] == "0"
    assert failed_checks(f) == {p: 0 for p in PROPERTIES}
    assert f["set"] == " ".join(TABLE1_PV) and f["processes"] == "9" and f["maxpv"] == "4"
    # Table 2: 16 cycles, 37 runs, loads 2 or 3 with 5 cycles at 3 (U = 2.3125)
    assert f["cycles"] == "16" and f["executions"] == "37"
    assert f["loads"] == "2..3, 5 of 16 cycles at 3"
    # the digests of the sources it was made from
    assert f["bsched.c-sha256"] == sha256_file(os.path.join(SOURCE, "bsched.c"))
    assert f["bsched.h-sha256"] == sha256_file(os.path.join(SOURCE, "bsched.h"))
    assert f["spec-sha256"] == spec_digest(SOURCE)
    assert f["checker-sha256"] == sha256_file(CHECKER)
    assert re.fullmatch(r"[0-9a-f]{64}", f["trace-driver-sha256"])
    assert f["compile"].endswith("-std=c99 -O2 -DBSCHED_MAX_PROCS=9")
    log = open(str(path) + ".log", encoding="utf-8").read()
    for p in PROPERTIES:
        assert re.search(r"^\[%s\] .*: SUCCESS$" % p, log, re.M), p


def test_recheck_reproduces_an_intact_certificate(table1):
    path, _ = table1
    r = run("--recheck", str(path))
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.startswith("recheck: OK: %s reproduced by run+check" % path)


@pytest.mark.parametrize("edit", ["set", "digest line"])
def test_recheck_refuses_a_tampered_certificate(table1, tmp_path, edit):
    path, _ = table1
    text = open(path, encoding="utf-8").read()
    if edit == "set":
        bad_text = text.replace("set: 1 1 1 2 2 3 4 4 4", "set: 1 1 1 2 2 3 4 4 3")
    else:
        bad_text = re.sub(r"^bsched.c-sha256: [0-9a-f]{64}$", "bsched.c-sha256: " + "0" * 64, text, flags=re.M)
    assert bad_text != text
    bad = tmp_path / "bad.cert"
    bad.write_text(bad_text)
    r = run("--recheck", str(bad))
    assert r.returncode == 1
    assert "recheck: FAILED" in r.stdout and "corrupted" in r.stdout


def test_recheck_catches_re_digested_forgeries_by_running_again(table1, tmp_path):
    """The digest only catches accidents: a forger re-digests. The re-run catches
    a changed count, a changed set (its runs differ) and a changed source digest."""
    path, _ = table1
    f, text = fields(path)
    forgeries = {
        "executions": [("executions: 38" if l.startswith("executions:") else l) for l in body_lines(text)],
        "set": [("set: 1 1 1 2 2 3 4 4 3" if l.startswith("set:") else l) for l in body_lines(text)],
        "bsched.c-sha256": [("bsched.c-sha256: " + "1" * 64 if l.startswith("bsched.c-sha256:") else l)
                            for l in body_lines(text)],
    }
    for what, lines in forgeries.items():
        forged = tmp_path / ("forged-%s.cert" % what.replace(".", "-"))
        forged.write_text(with_digest(lines))
        r = run("--recheck", str(forged))
        assert r.returncode == 1, what
        assert "FAILED: the check of" in r.stdout, what
        # a forged set is run as written: its counts come out other than the certificate's
        differs = "executions" if what == "set" else what
        assert "differs: %s:" % differs in r.stdout, (what, r.stdout)


def test_recheck_refuses_a_swapped_method(table1, tmp_path):
    path, _ = table1
    _, text = fields(path)
    lines = [("method: cbmc" if l.startswith("method:") else l) for l in body_lines(text)]
    forged = tmp_path / "method.cert"
    forged.write_text(with_digest(lines))
    r = run("--recheck", str(forged), timeout=900)
    assert r.returncode == 1
    # re-run by CBMC: the certificate has none of CBMC's lines
    assert "differs: harness-sha256: certificate ''" in r.stdout, r.stdout


@pytest.mark.parametrize("seed", [1, 2, 3, 4, 5, 6])
def test_random_sets_are_certified_with_the_theorem_counts(tmp_path, seed):
    rng = random.Random(seed)
    n = rng.choice([1, 2, 17, 300, 1000, 3000])
    top = rng.randint(0, 16)
    pvs = [rng.randint(0, top) for _ in range(n)]
    cert = tmp_path / "random.cert"
    r = run("--certify", str(cert), "--method", "check", *map(str, pvs))
    assert r.returncode == 0, r.stdout + r.stderr
    f, _ = fields(cert)
    cycles, area, loads = balance_of(pvs)
    assert f["verdict"] == "CERTIFIED"
    assert f["processes"] == str(n) and f["maxpv"] == str(max(pvs))
    assert f["cycles"] == str(cycles) and f["executions"] == str(area)
    assert f["loads"] == loads


def test_checker_agrees_with_the_json_schedule_on_random_sets(tmp_path):
    """The library's own --json schedule, written as a trace, is what the checker
    accepts; the same schedule with one cycle's order reversed it refuses."""
    rng = random.Random(7)
    for _ in range(5):
        pvs = [rng.randint(0, 7) for _ in range(rng.randint(2, 60))]
        doc = json.loads(run("--json", *map(str, pvs)).stdout)
        good = tmp_path / "good.trace"
        good.write_bytes(trace_bytes(pvs, doc["perfect"], doc["wait"], doc["major_cycle"]))
        r = run("--check-trace", str(good), *map(str, pvs))
        assert r.returncode == 0, r.stdout
        cyc = [list(c) for c in doc["major_cycle"]]
        t = next((t for t, c in enumerate(cyc) if len(c) >= 2), None)
        if t is None:
            continue
        cyc[t].reverse()
        bad = tmp_path / "bad.trace"
        bad.write_bytes(trace_bytes(pvs, doc["perfect"], doc["wait"], cyc))
        r = run("--check-trace", str(bad), *map(str, pvs))
        assert r.returncode == 1 and "fig7 1," in r.stdout, r.stdout


# ---------- wrong schedules are refused ----------

def mutant_source(tmp_path, edit):
    src = tmp_path / "bsched"
    shutil.copytree(SOURCE, src, ignore=shutil.ignore_patterns("tests", "proofs", "dist"))
    lib = src / "bsched.c"
    text = lib.read_text()
    new = edit(text)
    assert new != text
    lib.write_text(new)
    return src


def test_the_no_reverse_mutant_is_refused(tmp_path):
    """bsched.c built with BSCHED_MUTANT_NO_REVERSE (the proofs' unbalanced mutant):
    its initial waits are the identity, not Fig. 6's bit reversal. Its step derives
    the due set from the class starts, so what it runs stays Fig. 7's, balanced;
    the checker refuses its plan, and its runs for not being at its own initial waits."""
    src = mutant_source(tmp_path, lambda t: "#define BSCHED_MUTANT_NO_REVERSE 1\n" + t)
    cert = tmp_path / "mutant.cert"
    r = run("--certify", str(cert), "--method", "check", "--source", str(src), *TABLE1_PV)
    assert r.returncode == 1, r.stdout + r.stderr
    f, _ = fields(cert)
    assert f["verdict"] == "NOT CERTIFIED: the checker refuses the schedule"
    failed = failed_checks(f)
    assert failed["plan"] == 4 and failed["period"] == 4  # p2.1, p4.1, p4.2 and p4.3
    assert failed["balance"] == 0 and failed["fig7"] == 0
    assert f["first-failure"].startswith("plan: process 3 (pv 2): the library's initial wait is 2, Fig. 6's 1")
    assert f["bsched.c-sha256"] != sha256_file(os.path.join(SOURCE, "bsched.c"))


def test_a_step_without_class_starts_is_refused_as_unbalanced(tmp_path):
    """The step keys every class from slot 0 (Fig. 6's start ignored), the plan is
    still Fig. 6's: the classes pile up in the same cycles, and the processes run
    once every 2^pv cycles but not at their initial waits: balance, Fig. 7 and the
    phase fail, the plan holds."""
    src = mutant_source(tmp_path, lambda t: t.replace("class_key(classes.cursor[pvk], pvk)", "class_key(0u, pvk)"))
    cert = tmp_path / "unbalanced.cert"
    r = run("--certify", str(cert), "--method", "check", "--source", str(src), *TABLE1_PV)
    assert r.returncode == 1, r.stdout + r.stderr
    f, _ = fields(cert)
    failed = failed_checks(f)
    assert failed["balance"] >= 1 and failed["fig7"] >= 1 and failed["period"] >= 1
    assert failed["plan"] == 0 and failed["repeat"] == 0
    assert f["first-failure"] == "balance: cycle 0 runs 5 processes, the balance theorem's count is 3"


def trace_bytes(pvs, perfect, waits, cycles, status=0, end=(0, 0)):
    """A trace in the format of tools/bsched-check.h, native byte order."""
    n = len(pvs)
    out = [b"BSTRACE1", struct.pack("=iIII", status, n, max(pvs), perfect), bytes(pvs),
           struct.pack("=%dI" % n, *waits)]
    for c in cycles:
        out.append(struct.pack("=iI", len(c), len(c)) + struct.pack("=%dH" % len(c), *c))
    out.append(struct.pack("=II", *end) + b"BSTREND1")
    return b"".join(out)


TABLE1_WAITS = [0, 1, 0, 1, 3, 0, 4, 12, 2]
TABLE2 = [
    [0, 2, 5], [1, 3], [0, 2, 8], [1, 4], [0, 2, 6], [1, 3], [0, 2], [1, 4],
    [0, 2, 5], [1, 3], [0, 2], [1, 4], [0, 2, 7], [1, 3], [0, 2], [1, 4],
]


def check_trace(tmp_path, data, pvs=tuple(int(p) for p in TABLE1_PV)):
    path = tmp_path / "x.trace"
    path.write_bytes(data)
    r = run("--check-trace", str(path), *map(str, pvs))
    m = re.search(r"failed: (.*); first failure: (.*)$", r.stdout.strip())
    assert m, r.stdout + r.stderr
    return r.returncode, {k: int(v) for k, v in re.findall(r"(\w+) (\d+)", m.group(1))}, m.group(2)


def test_check_trace_accepts_the_papers_table2(tmp_path):
    rc, failed, first = check_trace(tmp_path, trace_bytes(list(map(int, TABLE1_PV)), 3, TABLE1_WAITS, TABLE2))
    assert rc == 0 and failed == {p: 0 for p in PROPERTIES} and first == "none"


@pytest.mark.parametrize("name, change, expect, first", [
    # p1.1 and p1.3 swapped in cycle 0: the right processes in another order
    ("order", lambda c, w: c[0].__setitem__(slice(0, 2), [2, 0]), {"fig7": 1}, "fig7: cycle 0"),
    # p4.3 moved from cycle 2 to cycle 6: still once in 16 cycles, but not at its initial
    # wait 2, and cycles 2 and 6 off the theorem's count
    ("late", lambda c, w: (c[2].remove(8), c[6].append(8)), {"period": 1, "balance": 2, "fig7": 2},
     "balance: cycle 2 runs 2 processes, the balance theorem's count is 3"),
    # p1.1 run twice in cycle 0
    # (balance twice: cycle 0's count, and a load of 4 above ceil(U) = 3)
    ("twice", lambda c, w: c[0].insert(1, 0), {"period": 2, "balance": 2, "fig7": 1}, "balance: cycle 0"),
    # p3.1 left out of cycle 8: runs once in 16 cycles, not twice
    # (balance twice: cycle 8's count, and 4 cycles at ceil(U), not A mod 2^maxpv = 5)
    ("missing", lambda c, w: c[8].remove(5), {"period": 1, "balance": 2, "fig7": 1}, "balance: cycle 8"),
    # an initial wait that is not Fig. 6's (p2.2 claims 1) and not where it runs
    ("plan", lambda c, w: w.__setitem__(4, 1), {"plan": 1, "period": 1}, "plan: process 4 (pv 2)"),
])
def test_check_trace_refuses_wrong_schedules(tmp_path, name, change, expect, first):
    cycles = [list(c) for c in TABLE2]
    waits = list(TABLE1_WAITS)
    change(cycles, waits)
    rc, failed, got_first = check_trace(tmp_path, trace_bytes(list(map(int, TABLE1_PV)), 3, waits, cycles))
    assert rc == 1, name
    assert failed == {p: expect.get(p, 0) for p in PROPERTIES}, (name, failed)
    assert got_first.startswith(first), (name, got_first)


def test_check_trace_refuses_a_library_that_does_not_end_where_it_began(tmp_path):
    rc, failed, _ = check_trace(tmp_path, trace_bytes(list(map(int, TABLE1_PV)), 3, TABLE1_WAITS, TABLE2, end=(1, 8)))
    assert rc == 1 and failed["repeat"] == 1


@pytest.mark.parametrize("cut", [0, 7, 60, -9, -1])
def test_check_trace_refuses_a_cut_trace(tmp_path, cut):
    data = trace_bytes(list(map(int, TABLE1_PV)), 3, TABLE1_WAITS, TABLE2)
    rc, _, first = check_trace(tmp_path, data[:cut])
    assert rc == 1 and first.startswith("trace: "), first


def test_check_trace_refuses_more_after_the_end(tmp_path):
    data = trace_bytes(list(map(int, TABLE1_PV)), 3, TABLE1_WAITS, TABLE2) + b"x"
    rc, _, first = check_trace(tmp_path, data)
    assert rc == 1 and first == "trace: more after its end"


def test_check_trace_refuses_a_wrong_perfect_and_another_set(tmp_path):
    rc, failed, first = check_trace(tmp_path, trace_bytes(list(map(int, TABLE1_PV)), 4, TABLE1_WAITS, TABLE2))
    assert rc == 1 and failed["plan"] == 1 and first == "plan: the library's perfect is 4, not ceil(U) = 3"
    other = [1, 1, 1, 2, 2, 3, 4, 4, 3]
    rc, failed, first = check_trace(tmp_path, trace_bytes(other, 3, TABLE1_WAITS, TABLE2))
    assert rc == 1 and first == "plan: the library holds pv 3 for process 8, the set 4"


# ---------- the checker is written apart from the library ----------

def test_the_checker_uses_nothing_of_the_library(tmp_path):
    """bsched-check.c includes neither bsched.h nor the reference engine, and its
    object file calls no function of theirs (only the C library's)."""
    text = open(CHECKER, encoding="utf-8").read()
    includes = re.findall(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', text, re.M)
    assert "bsched.h" not in includes and not any("fig7" in i for i in includes), includes
    obj = tmp_path / "check.o"
    subprocess.run(["cc", "-std=c99", "-O2", "-c", "-o", str(obj), CHECKER], check=True)
    undefined = subprocess.run(["nm", "-u", str(obj)], capture_output=True, text=True, check=True).stdout.split()
    assert "fread" in undefined  # the list is real
    assert not [s for s in undefined if "bsched" in s], undefined


# ---------- the method, the largest sets, the time limit ----------

def test_auto_takes_run_check_above_the_cbmc_line(tmp_path):
    cert = tmp_path / "auto.cert"
    r = run("--certify", str(cert), *(["4"] * 65))  # 65 x 2^4 = 1040 process-cycles > 1024
    assert r.returncode == 0, r.stdout + r.stderr
    assert fields(cert)[0]["method"] == "run+check"
    help_text = run("--help").stdout
    assert "--method M" in help_text and "N x 2^maxpv <= 1024" in help_text


def test_65535_processes_up_to_pv_16_complete(tmp_path):
    rng = random.Random(65535)
    pvs = [rng.randint(0, 16) for _ in range(65535 - 17)] + list(range(17))
    cert = tmp_path / "big.cert"
    r = run("--certify", str(cert), *map(str, pvs), timeout=900)  # auto: run+check
    assert r.returncode == 0, r.stdout + r.stderr
    f, _ = fields(cert)
    cycles, area, loads = balance_of(pvs)
    assert f["method"] == "run+check" and f["verdict"] == "CERTIFIED"
    assert f["processes"] == "65535" and f["cycles"] == "65536" == str(cycles)
    assert f["executions"] == str(area) and area > 10 ** 8
    assert f["loads"] == loads
    # O(N) memory: the checker's peak is megabytes (a stored trace would be gigabytes)
    m = re.search(r"max RSS: checker (\d+) KiB, library run (\d+) KiB", r.stdout)
    assert m and int(m.group(1)) < 64 * 1024 and int(m.group(2)) < 64 * 1024, r.stdout
    assert r.stdout.startswith("certified: 65535 processes, maxpv 16, run+check")


def test_time_limit_stops_run_check_and_is_not_certified(tmp_path):
    """65534 processes at pv 0 and one at 16: 4.3 x 10^9 runs, far more than 1 s."""
    cert = tmp_path / "slow.cert"
    r = run("--certify", str(cert), "--time-limit", "1", *(["0"] * 65534 + ["16"]), timeout=120)
    assert r.returncode == 1, r.stdout + r.stderr
    assert fields(cert)[0]["verdict"] == "NOT CERTIFIED: time limit of 1 s"


# ---------- bad input ----------

@pytest.mark.parametrize("args, names", [
    (["--certify", "x.cert", "1", "17"], "'17'"),
    (["--certify", "x.cert", "--method", "check", "17"], "'17'"),
    (["--certify", "x.cert", "--method", "cbmc", "1", "20"], "'20'"),
    (["--certify", "x.cert", "1", "x"], "'x'"),
    (["--certify", "x.cert", "1", "1.5"], "'1.5'"),
    (["--certify", "x.cert", "1", ""], "''"),
    (["--certify", "x.cert", "--method", "fast", "1"], "'fast'"),
    (["--certify", "x.cert", "--method"], "'--method'"),
    (["--method", "check", "1"], "'check'"),
    (["--recheck", "x.cert", "--method", "check"], "'x.cert'"),
    (["--check-trace", "x.trace", "17"], "'17'"),
    (["--check-trace"], "'--check-trace'"),
])
def test_bad_input_is_one_line_and_status_2(args, names, tmp_path):
    r = run(*args, timeout=60, cwd=tmp_path)
    assert r.returncode == 2, r.stdout + r.stderr
    assert r.stdout == ""
    lines = r.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("bsched-plan: ") and names in lines[0], r.stderr
    assert not (tmp_path / "x.cert").exists()


def test_65536_processes_are_refused(tmp_path):
    r = run("--certify", "x.cert", "--method", "check", *(["3"] * 65536), timeout=60, cwd=tmp_path)
    assert r.returncode == 2 and r.stdout == ""
    assert len(r.stderr.splitlines()) == 1 and "too many processes" in r.stderr
    assert not (tmp_path / "x.cert").exists()


def test_recheck_against_other_sources_names_what_differs(table1, tmp_path):
    """An intact certificate re-checked on a changed bsched.c (the NO_REVERSE mutant)
    is not reproduced: the digest and the verdict differ, and the run is refused."""
    path, _ = table1
    src = mutant_source(tmp_path, lambda t: "#define BSCHED_MUTANT_NO_REVERSE 1\n" + t)
    r = run("--recheck", str(path), "--source", str(src))
    assert r.returncode == 1
    assert "differs: bsched.c-sha256:" in r.stdout and "differs: verdict:" in r.stdout, r.stdout
    assert "differs: failed-checks: certificate 'plan 0, period 0," in r.stdout


def test_recheck_refuses_a_format_1_certificate(tmp_path):
    old = tmp_path / "old.cert"
    old.write_text(with_digest(["bsched-plan certificate 1", "set: 1", "processes: 1", "maxpv: 1",
                                "verdict: CERTIFIED"]))
    r = run("--recheck", str(old))
    assert r.returncode == 1
    assert "format 1" in r.stdout and "certify the set again" in r.stdout
