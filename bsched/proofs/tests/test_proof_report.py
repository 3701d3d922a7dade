"""make proof-report: the report against the raw results of the proof tools.

Makes its own small raw results (WP on period_of and reverse_bits, ~5 s; CBMC's
errors harness at capacity 2, ~5 s), builds the report from them, and compares every
row with what Frama-C and CBMC printed. A goal that timed out and a CBMC run without
a result must be rows (fixtures: the tools are not made to time out here).
"""
import json
import os
import re
import shutil
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
PROOFS = os.path.dirname(HERE)
ROOT = os.path.dirname(os.path.dirname(PROOFS))
REPORT = os.path.join(PROOFS, "proof_report.py")
WP_REPORT = os.path.join(PROOFS, "wp", "wp_report.py")
GOAL = re.compile(r"^\[wp\] \[(?P<prover>[^\]]+)\] Goal (?P<goal>\S+)(?: : (?P<status>\w+))?", re.M)


def report(build, out, *args):
    r = subprocess.run([sys.executable, REPORT, "--build", str(build), "--out", str(out), *args],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr
    assert (out / "index.html").exists()
    return json.load(open(out / "proof-report.json"))


@pytest.fixture(scope="module")
def raw(tmp_path_factory):
    build = tmp_path_factory.mktemp("build")
    wp = build / "wp"
    wp.mkdir()
    env = dict(os.environ, WP_STEPS_Z3="13000000")
    with open(wp / "wp.log", "w") as log:
        subprocess.run(["frama-c", "-cpp-extra-args=-I%s/bsched" % ROOT, "-wp", "-wp-rte",
                        "-wp-prover", "cvc4,z3-qi,cvc5", "-wp-steps", "2500000", "-wp-timeout", "600",
                        "-wp-verbose", "1", "-wp-cache", "none", "-wp-fct", "period_of,reverse_bits",
                        "-wp-report-json", str(wp / "wp.json"), os.path.join(ROOT, "bsched", "bsched.c")],
                       stdout=log, stderr=subprocess.STDOUT, env=env, timeout=300, check=True)
    subprocess.run([sys.executable, WP_REPORT, str(wp / "wp.log"), str(wp / "wp.json"), str(wp / "report.json"),
                    "--min-goals", "1"], capture_output=True, timeout=60, check=True)
    r = subprocess.run(["make", "--no-print-directory", "-C", ROOT, "cbmc-run-errors", "BUILD=%s" % build,
                        "CBMC_ARGS_errors=N=2"], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    return build


def test_every_wp_goal_is_a_row_as_frama_c_reported_it(raw, tmp_path):
    rep = report(raw, tmp_path / "out", "--cbmc-runs", "errors")
    log = open(raw / "wp" / "wp.log").read()
    frama = json.load(open(raw / "wp" / "wp.json"))["wp:global"]["wp:main"]
    lines = {m["goal"]: m["status"] or "Failed" for m in GOAL.finditer(log)}
    rows = {g["goal"]: g for g in rep["wp"]["goals"]}
    assert rep["wp"]["goals_total"] == len(rows) == len(lines) == frama["total"] > 20
    assert sum(g["status"] == "Valid" for g in rows.values()) == frama["valid"]
    for goal, status in lines.items():
        assert rows[goal]["status"] == status
    provers = [g for g in rows.values() if g["prover"] != "Qed"]
    assert provers and all(g["steps"] and g["steps"] > 0 for g in provers)
    assert all(g["function"] in ("period_of", "reverse_bits") for g in rows.values())


def test_every_cbmc_run_is_a_row_as_cbmc_reported_it(raw, tmp_path):
    rep = report(raw, tmp_path / "out", "--cbmc-runs", "errors", "never_run")
    runs = {r["run"]: r for r in rep["cbmc"]["runs"]}
    log = open(raw / "cbmc" / "errors" / "cbmc.log").read()
    failed, total = map(int, re.search(r"^\*\* (\d+) of (\d+) failed", log, re.M).groups())
    assert runs["errors"]["properties"] == total == len(re.findall(r": (?:SUCCESS|FAILURE)$", log, re.M))
    assert runs["errors"]["failed"] == failed == 0
    assert runs["errors"]["status"] == "PASS" and runs["errors"]["bounds"]["N"] == "2"
    assert runs["errors"]["solver"] and runs["errors"]["seconds"] is not None
    assert runs["never_run"]["status"] == "NOT RUN"
    page = open(tmp_path / "out" / "index.html").read()
    assert "never_run" in page and "NOT RUN" in page


def test_a_timeout_is_a_visible_row(raw, tmp_path):
    """A goal WP gave up on and a CBMC run that never finished are rows, not gaps."""
    build = tmp_path / "build"
    shutil.copytree(raw, build)
    rep_path = build / "wp" / "report.json"
    rep = json.load(open(rep_path))
    victim = next(g for g in rep["goals"] if g["prover"] != "Qed")
    victim.update(status="Timeout", prover="CVC4 1.8")
    json.dump(rep, open(rep_path, "w"))
    (build / "cbmc" / "errors" / "result.txt").unlink()
    out = report(build, tmp_path / "out", "--cbmc-runs", "errors")
    row = next(g for g in out["wp"]["goals"] if g["goal"] == victim["goal"])
    assert row["status"] == "Timeout" and out["wp"]["by_status"]["Timeout"] == 1
    assert out["wp"]["goals"][0]["goal"] == victim["goal"]  # not proven: listed first
    run = out["cbmc"]["runs"][0]
    assert run["status"] == "NO RESULT"
    page = open(tmp_path / "out" / "index.html").read()
    assert re.search(r'<tr class="bad">.*%s.*Timeout' % re.escape(victim["goal"]), page)
    assert re.search(r'<tr class="bad"><td>errors</td>.*NO RESULT', page)


def test_tool_versions_are_the_manifest_rows(raw, tmp_path):
    rep = report(raw, tmp_path / "out")
    names = [t["tool"] for t in rep["tools"]]
    assert names == ["frama-c", "why3", "z3", "cvc4", "cvc5", "cbmc", "kissat"]
    assert {t["tool"]: t["verdict"] for t in rep["tools"]}["frama-c"] == "ok"
