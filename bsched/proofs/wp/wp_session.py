#!/usr/bin/env python3
"""The WP proof session: the prover that proves each goal, so that make prove runs
that prover alone instead of racing every prover of WP_PROVERS on the goal.

  wp_session.py write REPORT_JSON SESSION_TSV
      From the report of a racing run (make wp-session: make prove WP_SESSION=0),
      one line per goal a prover proved (Qed's goals need none): goal, the
      winner's Why3 id, its time in that run (for the reader only).
  wp_session.py install SESSION_TSV DIR --steps N --steps-z3 N --timeout S
      Writes DIR/script/<goal>.json, the proof scripts of Frama-C WP's session
      (-wp-session DIR -wp-prover script,PROVERS). Each script names its prover;
      replaying it is the prover call the race would make, under make prove's own
      limits (-wp-steps, WP_STEPS_Z3, -wp-timeout; the scripts carry the same
      values, and WP ignores a script's step limit). It is not a cache: the prover
      runs again. A script whose prover no longer proves its goal is followed by
      the race of PROVERS, so a stale session costs time, never the verdict.
"""
import argparse
import json
import os
import re
import shutil
import sys

# Report names ("CVC4 1.8", "Z3 4.8.12 (qi)") -> Why3 ids ("CVC4:1.8", "Z3:4.8.12:qi").
PROVER_NAME = re.compile(r"^(?P<name>\S+) (?P<version>\S+)(?: \((?P<alt>[^)]+)\))?$")


def why3_id(prover):
    m = PROVER_NAME.match(prover)
    if not m:
        sys.exit("wp_session: cannot read the prover name %r" % prover)
    return ":".join(x for x in (m["name"], m["version"], m["alt"]) if x)


def write(report_path, session_path):
    with open(report_path, encoding="utf-8") as f:
        report = json.load(f)
    if report.get("verdict") != "PROVEN":
        sys.exit("wp_session: %s is not a complete proof (%s); a session is taken only "
                 "from a run that proved every goal" % (report_path, report.get("verdict")))
    lines = []
    for g in report["goals"]:
        if g["status"] == "Valid" and g["prover"] not in ("Qed", "Script"):
            lines.append("%s\t%s\t%.2f" % (g["goal"], why3_id(g["prover"]), g["seconds"]))
    with open(session_path, "w", encoding="utf-8") as f:
        f.write("# The prover that proved each WP goal, replayed alone by make prove\n"
                "# (make wp-session writes this file from the report of a racing run).\n"
                "# goal, Why3 prover id, seconds in that run.\n"
                "# %d goals proven by a prover; %d by Qed.\n"
                % (len(lines), sum(g["prover"] == "Qed" for g in report["goals"])))
        f.write("".join(line + "\n" for line in sorted(lines)))
    print("wp_session: %d goals with their prover -> %s" % (len(lines), session_path))


def install(session_path, out_dir, steps, steps_z3, timeout):
    scripts = os.path.join(out_dir, "script")
    shutil.rmtree(out_dir, ignore_errors=True)
    os.makedirs(scripts)
    count = 0
    for line in open(session_path, encoding="utf-8"):
        if line.startswith("#") or not line.strip():
            continue
        goal, prover = line.split("\t")[:2]
        name = goal[len("typed_"):] if goal.startswith("typed_") else goal
        limit = steps_z3 if prover.startswith("Z3:") else steps
        script = [dict({"prover": prover, "verdict": "valid", "time": timeout},
                       **({"steps": limit} if limit else {}))]  # 0: no step limit
        with open(os.path.join(scripts, name + ".json"), "w", encoding="utf-8") as f:
            json.dump(script, f)
        count += 1
    return count


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest="command", required=True)
    w = sub.add_parser("write")
    w.add_argument("report")
    w.add_argument("session")
    i = sub.add_parser("install")
    i.add_argument("session")
    i.add_argument("dir")
    i.add_argument("--steps", type=int, required=True)
    i.add_argument("--steps-z3", type=int, required=True)
    i.add_argument("--timeout", type=int, required=True)
    args = ap.parse_args()
    if args.command == "write":
        write(args.report, args.session)
    else:
        install(args.session, args.dir, args.steps, args.steps_z3, args.timeout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
