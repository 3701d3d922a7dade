#!/usr/bin/env python3
"""One report of the proofs of bsched.c: build/proof-report/index.html and proof-report.json.

  proof_report.py --build BUILD --out DIR [--wp DIR] [--cbmc-runs RUN...]
                  [--cbmc-mutants RUN...] [--manifest TOOLS_TXT]

Reads what the proof jobs left (nothing is re-run):
  - WP: DIR/report.json (wp_report.py: every goal with its status and prover), DIR/wp.log
    (Frama-C's line per goal: the steps and time of the proof) and DIR/wp.json (Frama-C's
    own totals). DIR is --wp, else BUILD/wp (make prove; its log has no steps for the
    goals its session's scripts prove).
  - CBMC: BUILD/cbmc/<run>/ for every run named (result.txt, time.txt, command.txt, cbmc.log).
  - The negative checks: BUILD/wp/mutant/report.json (check-wp-negative) and
    BUILD/cbmc/<run>-mutant/ for each --cbmc-mutants run.
  - The mutants summary: BUILD/mutants/report-full.json, else report-sample.json.
  - The tool versions: tools_check.py's comparison with bsched/proofs/tools.txt.
Every goal and every run named is a row: a goal that timed out, hit its step limit or got
no result is a row with that status, and a run with no result is a row saying so.
"""
import argparse
import datetime
import html
import json
import os
import re
import subprocess
import sys

# The one reader of tools.txt, beside this script (the script's folder is the
# first entry of the import path when it is run, as make proof-report does).
import tools_check

HERE = os.path.dirname(os.path.abspath(__file__))
GOAL_LINE = re.compile(r"^\[wp\] \[(?P<prover>[^\]]+)\] Goal (?P<goal>\S+)(?: : (?P<status>\w+(?: \w+)?)(?P<rest>.*))?$")
STEPS = re.compile(r"\((\d+)\)")
CBMC_SUMMARY = re.compile(r"^\*\* (\d+) of (\d+) failed", re.M)
CBMC_RESULT = re.compile(r"^\[[^\]]+\] .*: (SUCCESS|FAILURE)$", re.M)


def load_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def read(path):
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return f.read()
    except OSError:
        return None


def wp_steps(log_text):
    """goal -> steps of the line that gave its final status (the last number in parentheses)."""
    steps = {}
    for line in (log_text or "").splitlines():
        m = GOAL_LINE.match(line)
        if not m or m["status"] is None:
            continue
        found = STEPS.findall(m["rest"] or "")
        if found and (m["status"] == "Valid" or m["goal"] not in steps):
            steps[m["goal"]] = int(found[-1])
    return steps


def wp_section(build, wp_dir):
    if wp_dir is None:
        wp_dir = os.path.join(build, "wp")
    report = load_json(os.path.join(wp_dir, "report.json"))
    if report is None:
        return {"dir": wp_dir, "source": "not run", "verdict": "NOT RUN", "goals": [], "goals_total": 0,
                "by_status": {}}
    source = "make prove (provers run)"
    steps = wp_steps(read(os.path.join(wp_dir, "wp.log")))
    frama = load_json(os.path.join(wp_dir, "wp.json")) or {}
    main = frama.get("wp:global", {}).get("wp:main", {})
    goals, by_status = [], {}
    for g in report["goals"]:
        status = g["status"]
        by_status[status] = by_status.get(status, 0) + 1
        goals.append({"function": g.get("function", "?"), "property": g.get("kind", "?"), "goal": g["goal"],
                      "status": status, "prover": g["prover"], "steps": steps.get(g["goal"]),
                      "seconds": g.get("seconds", 0.0)})
    goals.sort(key=lambda g: (g["status"] == "Valid", g["function"], g["property"], g["goal"]))
    return {"dir": wp_dir, "source": source, "verdict": report.get("verdict"),
            "problems": report.get("problems", []), "goals_total": len(goals),
            "frama_c_total": main.get("total"), "frama_c_valid": main.get("valid"),
            "wall_seconds": report.get("wall_seconds"), "by_status": by_status, "goals": goals}


def cbmc_run(build, run, folder="cbmc"):
    d = os.path.join(build, folder, run)
    row = {"run": run, "dir": d}
    result = read(os.path.join(d, "result.txt"))
    log = read(os.path.join(d, "cbmc.log"))
    times = read(os.path.join(d, "time.txt")) or ""
    command = read(os.path.join(d, "command.txt")) or ""
    fields = dict(re.findall(r"(\w+)=(\S+)", times))
    row["bounds"] = {k: fields[k] for k in ("N", "P", "n") if k in fields}
    row["seconds"] = float(fields["seconds"]) if "seconds" in fields else None
    row["cpu_seconds"] = float(fields["cpu"]) if "cpu" in fields else None
    m = re.search(r"--external-sat-solver (\S+)", command)
    row["solver"] = os.path.basename(m.group(1)) if m else ("MiniSat (built in)" if command else None)
    if log is not None:
        s = CBMC_SUMMARY.search(log)
        results = CBMC_RESULT.findall(log)
        row["properties"] = int(s.group(2)) if s else len(results)
        row["failed"] = int(s.group(1)) if s else results.count("FAILURE")
    else:
        row["properties"] = row["failed"] = None
    if result is not None:
        row["status"] = "PASS" if result.startswith("PASS") else "FAIL"
        row["result"] = result.strip()
    elif log is not None or os.path.isdir(d):
        row["status"] = "NO RESULT"
        row["result"] = "no result.txt: CBMC did not finish (stopped or timed out)"
    else:
        row["status"] = "NOT RUN"
        row["result"] = "no output in %s" % d
    return row


def negative_section(build, mutants):
    wp_mut = load_json(os.path.join(build, "wp", "mutant", "report.json"))
    wp = {"check": "check-wp-negative: bsched.c built with -DBSCHED_MUTANT_NO_REVERSE must fail WP"}
    if wp_mut is None:
        wp.update(status="NOT RUN")
    else:
        unproven = [g["goal"] for g in wp_mut["goals"] if g["status"] != "Valid"]
        wp.update(status="PASS" if unproven else "FAIL", goals=len(wp_mut["goals"]), not_proven=unproven)
    return {"wp": wp, "cbmc": [cbmc_run(build, r + "-mutant") for r in mutants]}


def mutants_section(build):
    for name in ("full", "sample", "partial"):
        r = load_json(os.path.join(build, "mutants", "report-%s.json" % name))
        if r is not None:
            return {"status": "run", "kind": name, "generated": r.get("generated"), "compiled": r.get("compiled"),
                    "killed": r.get("killed"), "killed_by": r.get("killed_by"),
                    "survivors_equivalent": r.get("survivors_equivalent"),
                    "survivors_unexplained": r.get("survivors_unexplained"), "per_stage": r.get("per_stage")}
    return {"status": "NOT RUN", "note": "make mutants (or make check-mutants-sample) writes build/mutants/"}


def tools_section(manifest):
    rows = []
    for name, want, command in tools_check.manifest(manifest):
        have = tools_check.installed(command)
        verdict = "MISSING" if have is None else ("ok" if have == want or have.startswith(want + "-") else "DIFFERENT")
        rows.append({"tool": name, "listed": want, "installed": have, "verdict": verdict})
    return rows


def esc(x):
    return html.escape("" if x is None else str(x))


def table(headers, rows, classes=None):
    out = ["<table><tr>" + "".join("<th>%s</th>" % esc(h) for h in headers) + "</tr>"]
    for i, r in enumerate(rows):
        cls = (' class="%s"' % classes[i]) if classes and classes[i] else ""
        out.append("<tr%s>" % cls + "".join("<td>%s</td>" % esc(c) for c in r) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def status_class(status):
    return "ok" if status in ("Valid", "PASS", "ok") else "bad"


def write_html(path, rep):
    wp, parts = rep["wp"], []
    parts.append("<h1>Proofs of bsched.c</h1><p>Generated %s from the results in <code>%s</code>; nothing "
                 "was re-run.</p>" % (esc(rep["generated"]), esc(rep["build"])))
    parts.append("<h2>Tool versions</h2>")
    parts.append(table(["tool", "listed (bsched/proofs/tools.txt)", "installed", ""],
                       [[t["tool"], t["listed"], t["installed"] or "-", t["verdict"]] for t in rep["tools"]],
                       [status_class(t["verdict"]) for t in rep["tools"]]))
    parts.append("<h2>Frama-C WP: %s goals, %s</h2>" % (wp["goals_total"], esc(wp["verdict"])))
    parts.append("<p>From %s (<code>%s</code>). Frama-C's own count: %s goals, %s valid. By status: %s.</p>"
                 % (esc(wp["source"]), esc(wp["dir"]), esc(wp.get("frama_c_total")), esc(wp.get("frama_c_valid")),
                    esc(", ".join("%s %d" % kv for kv in sorted(wp["by_status"].items())))))
    parts.append(table(["function", "property", "goal", "status", "prover", "steps", "seconds"],
                       [[g["function"], g["property"], g["goal"], g["status"], g["prover"],
                         "" if g["steps"] is None else g["steps"], "%.2f" % g["seconds"]] for g in wp["goals"]],
                       [status_class(g["status"]) for g in wp["goals"]]))
    runs = rep["cbmc"]["runs"]
    parts.append("<h2>CBMC: %d runs</h2>" % len(runs))
    parts.append(table(["run", "bounds", "properties", "failed", "solver", "seconds", "CPU s", "status", "result"],
                       [[r["run"], " ".join("%s=%s" % kv for kv in sorted(r["bounds"].items())), r["properties"],
                         r["failed"], r["solver"], r["seconds"], r["cpu_seconds"], r["status"], r["result"]]
                        for r in runs], [status_class(r["status"]) for r in runs]))
    neg = rep["negative"]
    parts.append("<h2>Negative checks (a deliberately wrong bsched.c must fail)</h2>")
    parts.append(table(["check", "status", "detail"],
                       [[neg["wp"]["check"], neg["wp"]["status"],
                         ", ".join(neg["wp"].get("not_proven", [])) or "-"]] +
                       [["cbmc " + r["run"], r["status"], r["result"]] for r in neg["cbmc"]],
                       [status_class(neg["wp"]["status"])] + [status_class(r["status"]) for r in neg["cbmc"]]))
    mut = rep["mutants"]
    parts.append("<h2>Mutants</h2>")
    if mut["status"] == "NOT RUN":
        parts.append('<p class="bad">Not run: %s</p>' % esc(mut["note"]))
    else:
        parts.append(table(["report", "generated", "compiled", "killed", "killed by", "equivalent", "unexplained"],
                           [[mut["kind"], mut["generated"], mut["compiled"], mut["killed"],
                             json.dumps(mut["killed_by"]), mut["survivors_equivalent"],
                             mut["survivors_unexplained"]]]))
    style = ("body{font-family:sans-serif;margin:1.5em}table{border-collapse:collapse;margin-bottom:1.5em}"
             "td,th{border:1px solid #ccc;padding:2px 6px;font-size:12px;text-align:left}"
             "tr.bad td{background:#fdd}tr.ok td:nth-child(4){color:#060}p.bad{color:#b00}")
    with open(path, "w", encoding="utf-8") as f:
        f.write("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>bsched proofs</title><style>%s</style>"
                "</head><body>\n%s\n</body></html>\n" % (style, "\n".join(parts)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--wp")
    ap.add_argument("--cbmc-runs", nargs="*", default=[])
    ap.add_argument("--cbmc-mutants", nargs="*", default=[])
    ap.add_argument("--manifest", default=os.path.join(HERE, "tools.txt"))
    a = ap.parse_args()
    rep = {"generated": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
           "build": os.path.abspath(a.build),
           "tools": tools_section(a.manifest),
           "wp": wp_section(a.build, a.wp),
           "cbmc": {"runs": [cbmc_run(a.build, r) for r in a.cbmc_runs]},
           "negative": negative_section(a.build, a.cbmc_mutants),
           "mutants": mutants_section(a.build)}
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "proof-report.json"), "w", encoding="utf-8") as f:
        json.dump(rep, f, indent=1)
    write_html(os.path.join(a.out, "index.html"), rep)
    bad_runs = sum(r["status"] != "PASS" for r in rep["cbmc"]["runs"])
    print("proof-report: WP %d goals (%s, %s), CBMC %d runs (%d without PASS), -> %s"
          % (rep["wp"]["goals_total"], rep["wp"]["verdict"], rep["wp"]["source"], len(rep["cbmc"]["runs"]),
             bad_runs, os.path.join(a.out, "index.html")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
