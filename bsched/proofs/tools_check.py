#!/usr/bin/env python3
"""Compares the installed proof tools with bsched/proofs/tools.txt.

  tools_check.py [--only NAME,...] [--strict] [--suite NAME]

Prints one line per tool: its listed version, the installed one, and 'ok',
'DIFFERENT' or 'MISSING'. $CBMC and $KISSAT name the CBMC and kissat binaries
(default: cbmc and kissat on PATH). Exit 1 with --strict when any differs or is
missing; otherwise 0 (make prove and make cbmc report and go on: the verdict of
a proof run with other tools is still a verdict, but not the verified one).
With --suite, writes build/results/NAME.txt ('P passed, F failed').
"""
import argparse
import os
import re
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
VERSION = re.compile(r"\d+\.\d+(?:\.\d+)?(?:-beta)?(?: \([A-Za-z]+\))?")


def manifest(path):
    tools = []
    for line in open(path):
        line = line.split("#", 1)[0].rstrip()
        if line:
            name, rest = line.split(None, 1)
            version, command = re.match(r"(.+?)\s{2,}(\S.*)$", rest).groups()
            tools.append((name, version.strip(), command))
    return tools


def installed(command):
    env = {"$CBMC": os.environ.get("CBMC", "cbmc"), "$KISSAT": os.environ.get("KISSAT", "kissat")}
    words = [env.get(w, w) for w in shlex.split(command)]
    try:
        out = subprocess.run(words, capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return None
    m = VERSION.search(out.stdout + out.stderr)
    return m.group(0) if m else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", help="comma-separated tool names")
    ap.add_argument("--strict", action="store_true")
    ap.add_argument("--suite")
    ap.add_argument("--manifest", default=os.path.join(HERE, "tools.txt"))
    a = ap.parse_args()
    only = set(a.only.split(",")) if a.only else None
    passed = failed = 0
    for name, want, command in manifest(a.manifest):
        if only and name not in only:
            continue
        have = installed(command)
        if have is None:
            verdict = "MISSING"
        elif have == want or have.startswith(want + "-"):
            verdict = "ok"
        else:
            verdict = "DIFFERENT"
        passed, failed = (passed + 1, failed) if verdict == "ok" else (passed, failed + 1)
        print(f"tools: {name:8} listed {want:24} installed {have or '-':24} {verdict}")
    if failed:
        print(f"tools: {failed} tool(s) differ from bsched/proofs/tools.txt: the proofs ran with "
              "another configuration than the verified one")
    if a.suite:
        os.makedirs(os.path.join(ROOT, "build", "results"), exist_ok=True)
        with open(os.path.join(ROOT, "build", "results", a.suite + ".txt"), "w") as f:
            f.write(f"{passed} passed, {failed} failed\n")
    return 1 if failed and a.strict else 0


if __name__ == "__main__":
    sys.exit(main())
