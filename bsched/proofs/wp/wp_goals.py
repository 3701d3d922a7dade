#!/usr/bin/env python3
"""The record of what the WP proof proves: its goals and the text of its contracts.

make check proves every goal with the provers (make prove, nothing cached). That a
prover proved a goal says nothing of a goal that is no longer generated or of a
contract that now claims less, so the proof's verdict is also held against a record
that only a complete proof writes and that every change to the contracts shows in
its diff:

  goals.tsv      every goal of the last complete make prove, with the prover that
                 proved it (Qed: WP's own simplifier);
  contracts.tsv  each proof source, the number of its ACSL annotations and the
                 SHA-256 of their text (whitespace folded): the contracts, the spec's
                 logic and lemmas, the loop annotations and the ghost code.

  wp_goals.py record REPORT_JSON DIR --root ROOT --spec FILE...
      After a make prove that proved every goal: writes DIR/goals.tsv and
      DIR/contracts.tsv anew.
  wp_goals.py check REPORT_JSON DIR --root ROOT --spec FILE... [--functions F,...]
      Fails, naming them, when a goal of the record was not generated (a deleted
      goal), when a goal was generated that the record lacks, or when a source's
      annotations differ from the record (a changed, weakened or deleted contract).
      --functions: a run of those functions only (WP_FCT); only their goals are held
      against the record.

A change to the contracts is legitimate only with its record: make prove, when it
proves every goal, writes both, and the commit shows them beside the change.
"""
import argparse
import hashlib
import json
import os
import re
import sys

GOALS_TSV = "goals.tsv"
CONTRACTS_TSV = "contracts.tsv"
# An ACSL annotation: /*@ ... */ or //@ to the end of the line.
ANNOTATION = re.compile(r"/\*@(.*?)\*/|//@([^\n]*)", re.S)
HOW_TO_RECORD = ("if the change is meant, run make prove: when it proves every goal it "
                 "records the goals and contracts anew (bsched/proofs/wp/goals.tsv, "
                 "contracts.tsv), and the commit shows them beside the change")


def annotations(path):
    """(count, sha256) of the ACSL annotations of one file, whitespace folded."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    found = [" ".join((a or b).split()) for a, b in ANNOTATION.findall(text)]
    digest = hashlib.sha256("\n".join(found).encode("utf-8")).hexdigest()
    return len(found), digest


def load_report(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def read_tsv(path):
    if not os.path.exists(path):
        sys.exit("wp_goals: no %s: %s" % (path, HOW_TO_RECORD))
    rows = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append(line.rstrip("\n").split("\t"))
    return rows


def named(items, limit=40):
    items = sorted(items)
    more = len(items) - limit
    return "\n".join("  " + g for g in items[:limit]) + ("\n  ... and %d more" % more if more > 0 else "")


def record(report_path, out_dir, root, spec):
    report = load_report(report_path)
    if report.get("verdict") != "PROVEN":
        sys.exit("wp_goals: %s is not a complete proof (%s): the record is left as it was"
                 % (report_path, report.get("verdict")))
    goals = report["goals"]
    with open(os.path.join(out_dir, GOALS_TSV), "w", encoding="utf-8") as f:
        f.write("# Every WP goal of the last make prove that proved them all, with its prover;\n"
                "# make check fails when one is no longer generated or a new one is not here\n"
                "# (wp_goals.py). %d goals: %d by Qed, %d by a prover.\n"
                % (len(goals), sum(g["prover"] == "Qed" for g in goals),
                   sum(g["prover"] != "Qed" for g in goals)))
        for g in sorted(goals, key=lambda g: g["goal"]):
            f.write("%s\t%s\n" % (g["goal"], g["prover"]))
    with open(os.path.join(out_dir, CONTRACTS_TSV), "w", encoding="utf-8") as f:
        f.write("# The ACSL annotations of each proof source when make prove last proved every\n"
                "# goal: file, annotation count, SHA-256 of their text (whitespace folded);\n"
                "# make check fails when they differ (wp_goals.py).\n")
        for path in sorted(spec):
            count, digest = annotations(os.path.join(root, path))
            f.write("%s\t%d\t%s\n" % (path, count, digest))
    print("wp_goals: recorded %d goals and the annotations of %d sources in %s"
          % (len(goals), len(spec), out_dir))


def check(report_path, rec_dir, root, spec, functions):
    report = load_report(report_path)
    recorded = {row[0]: row[1] for row in read_tsv(os.path.join(rec_dir, GOALS_TSV))}
    contracts = {row[0]: (int(row[1]), row[2]) for row in read_tsv(os.path.join(rec_dir, CONTRACTS_TSV))}
    run = {g["goal"] for g in report["goals"]}
    if functions:
        # Goal names are typed_<function>_<kind>... (typed_lemma_<name> for lemmas).
        prefixes = tuple("typed_%s_" % f for f in functions)
        recorded = {g: p for g, p in recorded.items() if g.startswith(prefixes)}
    problems = 0
    gone = sorted(set(recorded) - run)
    new = sorted(run - set(recorded))
    if gone:
        problems += 1
        print("wp_goals: FAILED: %d goal(s) of the record were not generated (a contract or "
              "annotation was deleted?):\n%s" % (len(gone), named(gone)))
    if new:
        problems += 1
        print("wp_goals: FAILED: %d goal(s) are not in the record:\n%s" % (len(new), named(new)))
    changed = []
    for path in sorted(set(spec) | set(contracts)):
        full = os.path.join(root, path)
        now = annotations(full) if os.path.exists(full) else None
        if now != contracts.get(path):
            was = contracts.get(path)
            changed.append("%s: %s annotations now, %s in the record" % (
                path, now[0] if now else "no file", was[0] if was else "none"))
    if changed:
        problems += 1
        print("wp_goals: FAILED: the annotations of %d source(s) differ from the record (a "
              "contract changed, was weakened or deleted):\n%s" % (len(changed), named(changed)))
    if problems:
        print("wp_goals: " + HOW_TO_RECORD)
        return 1
    print("wp_goals: the %d goals are the record's%s; the annotations of %d sources are the record's"
          % (len(run), " (of %s)" % ",".join(functions) if functions else "", len(contracts)))
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("action", choices=("record", "check"))
    ap.add_argument("report")
    ap.add_argument("dir")
    ap.add_argument("--root", default=".")
    ap.add_argument("--spec", nargs="+", required=True)
    ap.add_argument("--functions", default="")
    a = ap.parse_args()
    if a.action == "record":
        record(a.report, a.dir, a.root, a.spec)
        return 0
    return check(a.report, a.dir, a.root, a.spec, [f for f in a.functions.split(",") if f])


if __name__ == "__main__":
    sys.exit(main())
