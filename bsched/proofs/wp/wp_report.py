#!/usr/bin/env python3
"""Gate and summarise a Frama-C WP run on bsched.c.

Reads the WP log (one line per goal: '[wp] [Prover] Goal NAME : STATUS (...)')
and WP's own JSON report (-wp-report-json), prints a table of goals per
function and property kind and per prover, writes a machine-readable report,
lists the logic definitions and axioms the proof relies on, and exits 1 when
any goal is not proven, when the goal count is below the minimum (so '0 of 0'
never passes), or when a goal expected to fail (negative check) was proven.
--known-gap GOAL... names goals that are known not to be proven yet (a gap
stated in bsched/proofs/README.md): they may stay unproven without failing the
gate, and every one is printed as a KNOWN GAP; a proven one is simply proven.

usage: wp_report.py LOG WP_JSON OUT_JSON --min-goals N --spec FILE... [--expect-fail GOAL...]
       [--known-gap GOAL...]
"""
import argparse
import json
import re
import sys
from collections import defaultdict

GOAL_LINE = re.compile(
    r"^\[wp\] \[(?P<prover>[^\]]+)\] Goal (?P<goal>\S+)(?: : (?P<status>\w+)(?P<rest>.*))?$")
# After '[wp] [Failed] Goal NAME', one indented line per prover tried.
ATTEMPT_LINE = re.compile(r"^  (?P<prover>[A-Za-z][^:]*): (?P<status>\w+)(?P<rest>.*)$")
# Frama-C prints a time as 380ms, 1.9s, 1'14s (a minute and 14 s) or 1h2' (an hour
# and 2 minutes), after "Qed:" for the time of its own simplifier.
TIME = re.compile(r"\((?:Qed:)?(?:(\d+)h)?(?:(\d+)')?(?:([0-9.]+)(ms|s))?\)")
# Goal names are typed_<function>_<kind...>; lemma goals are typed_lemma_<name>.
KINDS = [
    ("assert_rte", "rte"), ("loop_invariant", "loop invariant"), ("loop_variant", "termination"),
    ("loop_assigns", "assigns"), ("assigns", "assigns"), ("ensures", "ensures"),
    ("requires", "call precondition"), ("assert", "assert"), ("complete", "behaviors"),
    ("disjoint", "behaviors"), ("terminates", "termination"), ("exits", "ensures"),
]


def short(prover):
    """Column names: qed, z3-qi, z3, cvc4, cvc5 (the -wp-prover names)."""
    p = prover.lower()
    if p == "qed":
        return "qed"
    name = p.split()[0]
    return name + ("-qi" if "(qi)" in p else "")


def seconds(rest):
    """The longest time in a goal line's tail (the prover's, or Qed's if longer)."""
    longest = 0.0
    for hours, minutes, value, unit in TIME.findall(rest):
        if not (hours or minutes or value):
            continue  # "()" or a step count: no time
        t = int(hours or 0) * 3600.0 + int(minutes or 0) * 60.0
        if value:
            t += float(value) / (1000.0 if unit == "ms" else 1.0)
        longest = max(longest, t)
    return longest


def script_prover(wp, goal):
    """The prover that proved a goal replayed from the session: the log says only
    '[Script]'; the JSON report lists it under the goal (its Why3 id, e.g.
    Z3:4.8.12:qi), returned as the log names it (Z3 4.8.12 (qi)). None when the
    JSON files the goal under another name (call preconditions, assigns parts)."""
    name = goal[len("typed_"):] if goal.startswith("typed_") else goal
    for props in wp.get("wp:functions", {}).values():
        for prover, counts in props.get(name, {}).items():
            if prover != "wp:main" and counts.get("valid"):
                parts = prover.split(":")
                return " ".join(parts[:2]) + ("".join(" (%s)" % a for a in parts[2:]))
    return None


def classify(goal, functions):
    name = goal[len("typed_"):] if goal.startswith("typed_") else goal
    func = None
    for f in sorted(functions, key=len, reverse=True):
        if name.startswith(f + "_"):
            func = f
            break
    if func is None:
        return ("(global lemma)", "lemma")
    tail = name[len(func) + 1:]
    # Behavior-qualified names: <behavior>_ensures_..., <behavior>_assigns...
    for key, kind in KINDS:
        if re.search(r"(^|_)" + key + r"(_|$)", tail):
            if kind == "call precondition":
                return (func, "call precondition")
            return (func, kind)
    return (func, "other")


def logic_inventory(spec_files):
    """Names of logic definitions, predicates, lemmas and any axiom in the spec."""
    defs, preds, lemmas, axioms, axiomatics = [], [], [], [], []
    for path in spec_files:
        text = open(path, encoding="utf-8").read()
        defs += re.findall(r"\blogic\s+\w+\s+(\w+)\s*(?:\{[^}]*\})?\s*\(", text)
        preds += re.findall(r"\bpredicate\s+(\w+)\s*(?:\{[^}]*\})?\s*\(", text)
        lemmas += re.findall(r"\blemma\s+(\w+)\s*:", text)
        axioms += re.findall(r"\baxiom\s+(\w+)\s*:", text)
        axiomatics += re.findall(r"\baxiomatic\s+(\w+)", text)
        lemmas += ["lemma function " + n for n in re.findall(r"\bvoid\s+(\w+)\s*\(", text)]
    return {"logic_definitions": sorted(set(defs)), "predicates": sorted(set(preds)),
            "lemmas": lemmas, "axioms": sorted(set(axioms)), "axiomatic_blocks": sorted(set(axiomatics))}


def merge(out, inputs):
    """Merges the -wp-report-json files of split WP runs into one: counts add up."""
    def add_counts(acc, by_prover):
        for prover, counts in by_prover.items():
            into = acc.setdefault(prover, {})
            for key, value in counts.items():
                into[key] = max(into.get(key, 0), value) if key == "rank" else into.get(key, 0) + value

    merged = {"wp:global": {}, "wp:functions": {}}
    for path in inputs:
        with open(path, encoding="utf-8") as f:
            part = json.load(f)
        add_counts(merged["wp:global"], part.get("wp:global", {}))
        # A function's properties may be split over runs, but no property may be
        # analysed twice; its totals (wp:section) add up.
        for func, goals in part.get("wp:functions", {}).items():
            acc = merged["wp:functions"].setdefault(func, {})
            for prop, counts in goals.items():
                if prop == "wp:section":
                    add_counts(acc.setdefault(prop, {}), counts)
                elif prop in acc:
                    sys.exit("wp_report: %s of %s analysed by two WP runs" % (prop, func))
                else:
                    acc[prop] = counts
    with open(out, "w", encoding="utf-8") as f:
        json.dump(merged, f, indent=1)


def main():
    if len(sys.argv) > 2 and sys.argv[1] == "--merge":
        return merge(sys.argv[2], sys.argv[3:])
    ap = argparse.ArgumentParser()
    ap.add_argument("log")
    ap.add_argument("wp_json")
    ap.add_argument("out_json")
    ap.add_argument("--min-goals", type=int, required=True)
    ap.add_argument("--spec", nargs="+", default=[])
    ap.add_argument("--expect-fail", nargs="*", default=[])
    ap.add_argument("--known-gap", nargs="*", default=[])
    ap.add_argument("--seconds", type=float, default=None)
    args = ap.parse_args()

    with open(args.wp_json, encoding="utf-8") as f:
        wp = json.load(f)
    functions = list(wp.get("wp:functions", {}).keys())

    goals = {}
    failed_goal = None
    for line in open(args.log, encoding="utf-8", errors="replace"):
        line = line.rstrip("\n")
        a = ATTEMPT_LINE.match(line)
        if failed_goal is not None and a:
            goals[failed_goal]["attempts"].append(
                {"prover": a["prover"], "status": a["status"], "seconds": seconds(a["rest"])})
            continue
        failed_goal = None
        m = GOAL_LINE.match(line)
        if not m:
            continue
        goal, prover, status = m["goal"], m["prover"], m["status"]
        if status is None:  # '[wp] [Failed] Goal X': not proven, attempts follow
            goals[goal] = {"goal": goal, "status": prover, "prover": "NOT PROVEN",
                           "seconds": 0.0, "attempts": []}
            failed_goal = goal
            continue
        if prover == "Script":  # replayed from the session (wp_session.py): the JSON names the prover
            prover = script_prover(wp, goal) or prover
        g = goals.setdefault(goal, {"goal": goal, "status": status, "prover": prover,
                                    "seconds": 0.0, "attempts": []})
        t = seconds(m["rest"] or "")
        g["attempts"].append({"prover": prover, "status": status, "seconds": t})
        if status == "Valid":
            g["status"], g["prover"], g["seconds"] = "Valid", prover, t
        elif g["status"] != "Valid":
            g["status"], g["prover"], g["seconds"] = status, prover, t

    # WP prints a line per goal; the JSON total is the cross-check.
    wp_total = wp.get("wp:global", {}).get("wp:main", {}).get("total", 0)
    wp_valid = wp.get("wp:global", {}).get("wp:main", {}).get("valid", 0)

    table = defaultdict(lambda: defaultdict(int))
    provers = set()
    for g in goals.values():
        func, kind = classify(g["goal"], functions)
        g["function"], g["kind"] = func, kind
        key = short(g["prover"]) if g["status"] == "Valid" else "NOT PROVEN"
        provers.add(key)
        table[(func, kind)][key] += 1
    cols = sorted(p for p in provers if p != "NOT PROVEN") + (["NOT PROVEN"] if "NOT PROVEN" in provers else [])

    print("\nWP goals per function, property kind and prover")
    header = "%-22s %-18s" % ("function", "property") + "".join("%11s" % c for c in cols) + "%8s" % "total"
    print(header)
    print("-" * len(header))
    totals = defaultdict(int)
    for (func, kind) in sorted(table):
        row = table[(func, kind)]
        print("%-22s %-18s" % (func, kind) + "".join("%11d" % row.get(c, 0) for c in cols)
              + "%8d" % sum(row.values()))
        for c in cols:
            totals[c] += row.get(c, 0)
    print("-" * len(header))
    print("%-41s" % "all" + "".join("%11d" % totals[c] for c in cols) + "%8d" % sum(totals.values()))
    if "script" in cols:
        print("script: proven by replaying the proof session (wp_session.py); WP's JSON report files "
              "these goals (call preconditions, parts of assigns) under other names, so their prover "
              "is not shown")

    unproven = sorted(g["goal"] for g in goals.values() if g["status"] != "Valid")
    expected = set(args.expect_fail)
    gaps = set(args.known_gap)
    unexpected_fail = [g for g in unproven if g not in expected and g not in gaps]
    open_gaps = [g for g in unproven if g in gaps]
    unexpected_pass = [g for g in expected if g in goals and goals[g]["status"] == "Valid"]
    missing_expected = [g for g in expected if g not in goals]
    inventory = logic_inventory(args.spec)

    problems = []
    if len(goals) < args.min_goals:
        problems.append("only %d goals, the minimum is %d" % (len(goals), args.min_goals))
    if wp_total != len(goals):
        problems.append("WP's JSON counts %d goals but the log shows %d" % (wp_total, len(goals)))
    if unexpected_fail:
        problems.append("%d goal(s) not proven: %s" % (len(unexpected_fail), ", ".join(unexpected_fail)))
    if unexpected_pass or missing_expected:
        problems.append("negative check: expected failure(s) did not fail: %s"
                        % ", ".join(unexpected_pass + missing_expected))
    if inventory["axioms"] or inventory["axiomatic_blocks"]:
        problems.append("the specification contains axioms: %s" % ", ".join(inventory["axioms"]))

    report = {
        "verdict": "FAILED" if problems else
            ("PROVEN EXCEPT %d KNOWN GAP(S)" % len(open_gaps) if open_gaps else "PROVEN"),
        "problems": problems,
        "goals_total": len(goals), "goals_valid": len(goals) - len(unproven),
        "wp_json_total": wp_total, "wp_json_valid": wp_valid,
        "min_goals": args.min_goals,
        "wall_seconds": args.seconds,
        "per_prover": dict(totals),
        "per_function_kind": {"%s/%s" % k: dict(v) for k, v in sorted(table.items())},
        "expected_failures": sorted(expected),
        "known_gaps_unproven": open_gaps,
        "relies_on": dict(inventory, **{
            "note": "No user axiom and no axiomatic block. Each recursive logic definition is "
                    "given to the provers as its defining equations; WP adds its own library "
                    "theories (Frama-C 25 share/wp/why3: Cint, Cbits for <<, Cmath, Memory)."}),
        "goals": sorted(goals.values(), key=lambda g: g["goal"]),
    }
    with open(args.out_json, "w", encoding="utf-8") as f:
        json.dump(report, f, indent=1)

    print("\nRelies on: no axiom, no axiomatic block; logic definitions: "
          + ", ".join(inventory["logic_definitions"]))
    print("Predicates: " + ", ".join(inventory["predicates"]))
    print("Lemmas proven as goals: " + ", ".join(inventory["lemmas"]))
    print("WP library theories: Cint, Cbits (<< via lsl axioms), Cmath, Memory (Frama-C 25)")
    if unproven:
        print("\nNot proven:")
        for g in unproven:
            a = goals[g]["attempts"]
            print("  %s%s: %s" % (g, " (expected)" if g in expected else (" (KNOWN GAP)" if g in gaps else ""),
                                  ", ".join("%s %s" % (x["prover"], x["status"]) for x in a)))
    print("\n%d goals, %d proven%s -> %s" % (len(goals), len(goals) - len(unproven),
          (", %.0f s" % args.seconds) if args.seconds is not None else "", report["verdict"]))
    if open_gaps:
        print("KNOWN GAP: %d goal(s) not proven yet (bsched/proofs/README.md): %s"
              % (len(open_gaps), ", ".join(open_gaps)))
    for p in problems:
        print("FAILED: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
