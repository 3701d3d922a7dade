#!/usr/bin/env python3
"""Steps each prover used in a WP run, and the -wp-steps limit they call for.

make prove limits every prover call by steps (-wp-steps, WP_STEPS in wp.mk), so
that the verdict does not depend on the machine's speed or load; the wall-clock
timeout is only a backstop. This script reads the WP log(s) of a run made with a
generous limit (make wp-calibrate) and prints, per prover, the goals it proved,
the most steps and the longest time one of them took, and the limits to set:
MARGIN times the largest count, rounded up to two significant digits, once for
cvc4 and cvc5 (WP_STEPS, -wp-steps) and once for Z3 (WP_STEPS_Z3: its units are
much cheaper, prover-steps.sh). It exits 1 when a goal was not proven (a
calibration must start from a proven run) or when --limit / --limit-z3 is given
and the run used more than limit / MARGIN steps (the limit no longer keeps its
margin: re-calibrate).

Log lines read (Frama-C 25, -wp-verbose 1):
  [wp] [CVC4 1.8] Goal typed_f_ensures : Valid (Qed:6ms) (60ms) (20000)
  [wp] [Failed] Goal typed_f_ensures            (then one indented line per prover)
    CVC5 1.0.3: Step limit (1000)

A goal that failed in one log and was proven in another counts as proven (a goal
that hit the wall-clock backstop can be re-run alone with a longer one).

usage: wp_steps.py LOG... [--margin M] [--limit N] [--limit-z3 N] [--timeout S]
"""
import argparse
import math
import re
import sys
from collections import defaultdict

GOAL = re.compile(r"^\[wp\] \[(?P<prover>[^\]]+)\] Goal (?P<goal>\S+) : (?P<status>[A-Za-z ]+?)(?: \(|$)(?P<rest>.*)$")
FAILED = re.compile(r"^\[wp\] \[Failed\] Goal (?P<goal>\S+)")
ATTEMPT = re.compile(r"^  (?P<prover>[A-Za-z][^:]*): (?P<status>[A-Za-z ]+?)(?: \(|$)")
# "(60ms)", "(1.2s)", "(1'02s)"; steps are the parenthesised bare integer at the end.
TIME = re.compile(r"\((?:(\d+)')?([0-9.]+)(ms|s)\)")
STEPS = re.compile(r"\((\d+)\)\s*$")


def seconds(rest):
    """Prover time of a goal line (the Qed simplification time is not counted)."""
    best = 0.0
    for minutes, value, unit in TIME.findall(rest.replace("(Qed:", "(qed:")):
        t = float(value) / (1000.0 if unit == "ms" else 1.0) + 60.0 * float(minutes or 0)
        best = max(best, t)
    return best


def round_up(x, digits=2):
    """x rounded up to `digits` significant digits (2 -> 1234 becomes 1300)."""
    if x <= 0:
        return 0
    scale = 10 ** max(0, int(math.floor(math.log10(x))) - digits + 1)
    return int(math.ceil(x / scale) * scale)


def parse(paths):
    per_prover = defaultdict(lambda: {"goals": 0, "steps": 0, "steps_goal": "", "time": 0.0,
                                      "time_goal": "", "no_steps": 0})
    not_proven = []
    cut_by_steps = []
    failed_goal = None
    proven = set()
    for path in paths:
        for line in open(path, encoding="utf-8", errors="replace"):
            line = line.rstrip("\n")
            m = FAILED.match(line)
            if m:
                failed_goal = m.group("goal")
                not_proven.append((failed_goal, "no prover"))
                continue
            m = ATTEMPT.match(line)
            if m and failed_goal:
                if m.group("status") == "Step limit":
                    cut_by_steps.append((failed_goal, m.group("prover")))
                continue
            failed_goal = None
            m = GOAL.match(line)
            if not m or m.group("prover") in ("Qed", "Failed"):
                continue
            prover, goal, status, rest = m.group("prover", "goal", "status", "rest")
            if status != "Valid":
                not_proven.append((goal, prover + ": " + status))
                if status == "Step limit":
                    cut_by_steps.append((goal, prover))
                continue
            proven.add(goal)
            p = per_prover[prover]
            p["goals"] += 1
            s = STEPS.search(line)
            if s is None:
                p["no_steps"] += 1
            elif int(s.group(1)) > p["steps"]:
                p["steps"], p["steps_goal"] = int(s.group(1)), goal
            t = seconds(rest)
            if t > p["time"]:
                p["time"], p["time_goal"] = t, goal
    # A goal proven in one of the logs (say a re-run of the goals that hit the
    # wall-clock backstop on a loaded machine, with a longer one) counts as proven.
    not_proven = [g for g in not_proven if g[0] not in proven]
    cut_by_steps = [g for g in cut_by_steps if g[0] not in proven]
    return per_prover, not_proven, cut_by_steps


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("logs", nargs="+")
    ap.add_argument("--margin", type=float, default=2.0)
    ap.add_argument("--limit", type=int, default=0, help="the WP_STEPS in force (checks its margin)")
    ap.add_argument("--limit-z3", type=int, default=0, help="the WP_STEPS_Z3 in force")
    ap.add_argument("--timeout", type=float, default=0.0, help="the wall-clock backstop in force (s)")
    args = ap.parse_args()
    per_prover, not_proven, cut_by_steps = parse(args.logs)
    rc = 0
    print("%-22s %6s %12s  %-40s %8s" % ("prover", "goals", "max steps", "(goal)", "max time"))
    # Two limits: WP_STEPS (-wp-steps) for cvc4 and cvc5, WP_STEPS_Z3 for Z3, whose
    # units are much cheaper (prover-steps.sh).
    overall = {"WP_STEPS": 0, "WP_STEPS_Z3": 0}
    for prover in sorted(per_prover):
        p = per_prover[prover]
        print("%-22s %6d %12d  %-40s %7.2fs" % (prover, p["goals"], p["steps"], p["steps_goal"][:40], p["time"]))
        if p["no_steps"]:
            print("  %d goals proven by %s without a step count: the run was not made with "
                  "-wp-steps, or the driver does not read this prover's steps" % (p["no_steps"], prover))
            rc = 1
        var = "WP_STEPS_Z3" if prover.startswith("Z3") else "WP_STEPS"
        overall[var] = max(overall[var], p["steps"])
    slowest = max([p["time"] for p in per_prover.values()] or [0.0])
    suggested = {var: round_up(n * args.margin) for var, n in overall.items()}
    print("with margin %gx: WP_STEPS = %d (cvc4, cvc5: largest count %d), WP_STEPS_Z3 = %d (largest %d)"
          % (args.margin, suggested["WP_STEPS"], overall["WP_STEPS"], suggested["WP_STEPS_Z3"],
             overall["WP_STEPS_Z3"]))
    if args.timeout:
        print("slowest proof: %.2f s; the wall-clock backstop %g s is %.0fx that"
              % (slowest, args.timeout, args.timeout / slowest if slowest else float("inf")))
    for goal, why in not_proven[:20]:
        print("NOT PROVEN: %s (%s)" % (goal, why))
    if not_proven:
        print("%d goals not proven (%d cut by the step limit): calibrate on a proven run"
              % (len(not_proven), len(cut_by_steps)))
        rc = 1
    for var, limit in (("WP_STEPS", args.limit), ("WP_STEPS_Z3", args.limit_z3)):
        if not limit:
            continue
        if overall[var] * args.margin > limit:
            print("%s = %d keeps less than the %gx margin over %d steps: set %s = %d"
                  % (var, limit, args.margin, overall[var], var, suggested[var]))
            rc = 1
        else:
            print("%s = %d: %.1fx the largest step count (margin %gx kept)"
                  % (var, limit, limit / overall[var] if overall[var] else float("inf"), args.margin))
    return rc


if __name__ == "__main__":
    sys.exit(main())
