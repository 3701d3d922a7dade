#!/usr/bin/env python3
"""Replays the red-team attacks of assure/redteam.txt and says how many were
handled cleanly.

  redteam.py [--quick] [--suite NAME]

Each attack is a regression test of some suite. The suites are run through
their own make targets (so each has the images and the environment it always
has), pytest ones with only the attacks' tests selected (-k), cmocka ones whole,
their test names read from the log; their results go to build/redteam, never
over make check's. An attack counts as handled when its test ran and passed
(every parameter of it). --quick: only the attacks that need no emulated board.
"""
import argparse
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "build", "redteam")


def catalog(quick):
    attacks = []
    for line in open(os.path.join(ROOT, "assure", "redteam.txt")):
        line = line.split("#", 1)[0].strip()
        if line:
            what, suite, test, kind = (part.strip() for part in line.split("|"))
            if kind not in ("quick", "board"):
                raise SystemExit(f"redteam.txt: '{kind}' is neither quick nor board: {line}")
            if not quick or kind == "quick":
                attacks.append((what, suite, test))
    return attacks


def run_suite(suite, tests):
    """{test name: passed?} for the given tests of one suite."""
    env = dict(os.environ, BSCHED_RESULTS=OUT)
    env["PYTEST_ADDOPTS"] = "-k '" + " or ".join(tests) + "'"
    log = os.path.join(OUT, suite + ".log")
    with open(log, "w") as f:
        subprocess.run(["make", "--no-print-directory", "-C", ROOT, "check-" + suite,
                        "RESULTS=" + os.path.join(OUT, "results")],
                       stdout=f, stderr=subprocess.STDOUT, env=env, timeout=1800)
    seen = {}
    xml = os.path.join(OUT, "pytest", suite + ".xml")
    if os.path.exists(xml) and os.path.getmtime(xml) >= os.path.getmtime(log) - 1:
        for case in ET.parse(xml).getroot().iter("testcase"):
            name = re.sub(r"\[.*\]$", "", case.get("name", ""))
            ok = case.find("failure") is None and case.find("error") is None \
                and case.find("skipped") is None
            seen[name] = seen.get(name, True) and ok
    text = open(log, errors="replace").read()
    for test in tests:
        if test in seen:
            continue
        # cmocka: "[       OK ] name" / "[  FAILED  ] name"; a program: its suite passed
        if re.search(r"^\[\s+OK\s+\] " + re.escape(test) + r"$", text, re.M):
            seen[test] = not re.search(r"^\[\s+FAILED\s+\] " + re.escape(test) + r"$", text, re.M)
        elif re.search(r"^\[\s+FAILED\s+\] " + re.escape(test) + r"$", text, re.M):
            seen[test] = False
        elif test in text:
            result = os.path.join(OUT, "results", suite + ".txt")
            seen[test] = os.path.exists(result) and \
                re.match(r"\d+ passed, 0 failed", open(result).read()) is not None
    return seen


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--suite")
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    attacks = catalog(a.quick)
    by_suite = {}
    for what, suite, test in attacks:
        by_suite.setdefault(suite, []).append(test)
    results = {suite: run_suite(suite, tests) for suite, tests in by_suite.items()}
    handled = 0
    for what, suite, test in attacks:
        ok = results[suite].get(test)
        handled += bool(ok)
        verdict = "handled" if ok else ("NOT RUN" if ok is None else "NOT HANDLED")
        print(f"{verdict:12} {what} ({suite}: {test})")
    print(f"redteam: {handled} of {len(attacks)} attacks handled cleanly"
          f"{' (quick: no emulated board)' if a.quick else ''}")
    print(f"{handled} passed, {len(attacks) - handled} failed")
    if a.suite:
        os.makedirs(os.path.join(ROOT, "build", "results"), exist_ok=True)
        with open(os.path.join(ROOT, "build", "results", a.suite + ".txt"), "w") as f:
            f.write(f"{handled} passed, {len(attacks) - handled} failed\n")
    return 0 if handled == len(attacks) else 1


if __name__ == "__main__":
    sys.exit(main())
