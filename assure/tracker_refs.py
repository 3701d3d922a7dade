#!/usr/bin/env python3
"""No tracker numbers and no paths outside the repository in the tree.

  tracker_refs.py

The repository has no issue tracker, so "issue 15", "(#38)" or "PR 7" in a
comment or a document points nowhere; nor do paths to files outside it (the
machine's /work or /home folders, a ../shared or briefs/ folder beside the
checkout). Every file git tracks is read as text (binary files are skipped)
and each such reference is printed with its place. A built-in sample with one
reference of each kind must be found in full first, so the scan is shown able
to fail. The last line is 'P passed, F failed'; exit status 1 on a failure.
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HASH = "#"   # kept apart so that this file does not match its own patterns
KINDS = {
    "tracker number": re.compile(r"\b[Ii]ssues? " + HASH + r"?\d+\b|\(" + HASH + r"\d+\)|"
                                 r"\b(?:PR|[Tt]icket|[Pp]ull request) " + HASH + r"?\d+\b"),
    "outside path": re.compile(r"/work/|\.\./shared\b|(?<![\w.$}-])shared/(?:notes|paper|hardware)/|"
                               r"\bbriefs/|(?<![\w$}])/home/\w"),
}
SAMPLE = {
    "tracker number": ["see issue 15", "fixed (" + HASH + "38)", "PR 7 added it"],
    "outside path": ["/work/main/x.c", "../shared/notes/a.md", "briefs/driver-api.md",
                     "shared/paper/p.pdf", "/home/me/x"],
}


def scan(text):
    """[(kind, line number, line)] for every reference in text."""
    found = []
    for number, line in enumerate(text.splitlines(), 1):
        for kind, pattern in KINDS.items():
            if pattern.search(line):
                found.append((kind, number, line.strip()))
    return found


def main():
    if sys.argv[1:]:
        print("usage: tracker_refs.py (no arguments)", file=sys.stderr)
        return 2
    passed = failed = 0
    for kind, lines in SAMPLE.items():
        missed = [ln for ln in lines if [k for k, _, _ in scan(ln)] != [kind]]
        if missed:
            print(f"FAILED the scan does not find every {kind} of the sample: {missed}")
            failed += 1
        else:
            print(f"ok the scan finds each {kind} of the sample ({len(lines)})")
            passed += 1
    files = subprocess.run(["git", "-C", ROOT, "ls-files", "-z"], check=True,
                           capture_output=True).stdout.decode().split("\0")
    me = os.path.relpath(os.path.abspath(__file__), ROOT)
    hits = []
    for name in files:
        path = os.path.join(ROOT, name)
        if not name or name == me or not os.path.isfile(path):
            continue
        data = open(path, "rb").read()
        if b"\0" in data:
            continue
        hits += [(name, kind, n, line) for kind, n, line in scan(data.decode("utf-8", "replace"))]
    for name, kind, n, line in hits:
        print(f"FAILED {name}:{n}: {kind}: {line[:120]}")
    if hits:
        failed += 1
    else:
        print(f"ok no tracker number and no outside path in {len(files) - 1} tracked files")
        passed += 1
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
