#!/usr/bin/env python3
"""The committed WP cache (bsched/proofs/wp/cache/): the proofs make wp-replay re-checks.

  wp_cache.py commit RUN_CACHE REPORT_JSON CACHE_DIR
      After a make prove that proved every goal (REPORT_JSON: its wp_report.py
      report): CACHE_DIR/entries/ becomes the valid entries of RUN_CACHE, the
      cache that run wrote (-wp-cache rebuild: one file per prover call,
      <digest of the prover task>.json), and nothing else, so an entry that the
      current goals do not use never stays; CACHE_DIR/goals.tsv lists every goal of
      that run with the prover that proved it (Qed for WP's own simplifier).
  wp_cache.py check REPORT_JSON LOG CACHE_DIR [--subset] [--seconds S]
      After make wp-replay (REPORT_JSON: wp_report.py's report of the replay, LOG
      its WP log): fails, naming the goals, when a goal has no proof in the cache
      (its task changed: the code, the spec or a tool changed), when the replay has a
      goal that goals.tsv lacks, or (unless --subset: a replay of some functions
      only) lacks a goal that goals.tsv has; otherwise prints the counts.

Frama-C 25's offline mode returns a cached result as it was recorded and never runs a
prover; a goal whose task digest has no entry gets no result ('[Failed] Goal X').
"""
import argparse
import json
import os
import re
import shutil
import sys

GOALS_TSV = "goals.tsv"
ENTRIES = "entries"
HOW_TO_REFRESH = ("run make prove: it proves every goal again with the provers and, "
                  "when all are proven, refreshes bsched/proofs/wp/cache/")
CACHED_LINE = re.compile(r"^\[wp\] \[(?P<prover>[^\]]+)\] Goal (?P<goal>\S+) : Valid.*\(cached\)$")


def commit(run_cache, report_path, cache_dir):
    with open(report_path, encoding="utf-8") as f:
        report = json.load(f)
    if report.get("verdict") != "PROVEN":
        sys.exit("wp_cache: %s is not a complete proof (%s): the committed cache is left as it was"
                 % (report_path, report.get("verdict")))
    entries = os.path.join(cache_dir, ENTRIES)
    shutil.rmtree(entries, ignore_errors=True)
    os.makedirs(entries)
    kept = skipped = 0
    for name in sorted(os.listdir(run_cache)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(run_cache, name), encoding="utf-8") as f:
            text = f.read()
        try:
            entry = json.loads(text)
        except ValueError:
            # Frama-C 25 writes a whole-second time as "600." (not JSON); it does
            # so only for timeouts, which are not proofs either.
            skipped += 1
            continue
        # A prover that lost the race with a Step limit is recorded too; the
        # replay needs only the proofs.
        if entry.get("verdict") != "valid":
            skipped += 1
            continue
        shutil.copyfile(os.path.join(run_cache, name), os.path.join(entries, name))
        kept += 1
    goals = report["goals"]
    with open(os.path.join(cache_dir, GOALS_TSV), "w", encoding="utf-8") as f:
        f.write("# Every WP goal of the make prove that wrote this cache (wp_cache.py commit),\n"
                "# with the prover that proved it; make wp-replay must find exactly these goals.\n"
                "# %d goals: %d by Qed, %d from the %d entries in entries/.\n"
                % (len(goals), sum(g["prover"] == "Qed" for g in goals),
                   sum(g["prover"] != "Qed" for g in goals), kept))
        for g in goals:
            f.write("%s\t%s\n" % (g["goal"], g["prover"]))
    print("wp_cache: %d goals; %d proofs -> %s (%d results that are not proofs left out)"
          % (len(goals), kept, entries, skipped))


def read_manifest(cache_dir):
    path = os.path.join(cache_dir, GOALS_TSV)
    if not os.path.exists(path):
        sys.exit("wp-replay: no %s: %s" % (path, HOW_TO_REFRESH))
    goals = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            goal, prover = line.rstrip("\n").split("\t")
            goals[goal] = prover
    return goals


def named(goals, limit=40):
    goals = sorted(goals)
    more = len(goals) - limit
    return "\n".join("  " + g for g in goals[:limit]) + ("\n  ... and %d more" % more if more > 0 else "")


def check(report_path, log_path, cache_dir, subset, secs):
    manifest = read_manifest(cache_dir)
    with open(report_path, encoding="utf-8") as f:
        report = json.load(f)
    replay = {g["goal"]: g for g in report["goals"]}
    cached = {}
    with open(log_path, encoding="utf-8", errors="replace") as f:
        for line in f:
            m = CACHED_LINE.match(line.rstrip("\n"))
            if m:
                cached[m["goal"]] = m["prover"]

    missing = [g for g, r in replay.items() if r["status"] != "Valid"]
    new = [g for g in replay if g not in manifest]
    gone = [] if subset else [g for g in manifest if g not in replay]
    # In offline mode a prover's Valid can only come from the cache; a Valid goal
    # that is neither Qed's nor marked (cached) would mean a prover ran.
    uncached = [g for g, r in replay.items()
                if r["status"] == "Valid" and r["prover"] != "Qed" and g not in cached]
    problems = 0
    if missing:
        problems += 1
        print("wp-replay: FAILED: %d goal(s) have no proof in the committed cache (the code, "
              "the spec or a tool changed since the cache was made):\n%s" % (len(missing), named(missing)))
    if new:
        problems += 1
        print("wp-replay: FAILED: %d goal(s) are not among the goals of the proof that made the "
              "cache:\n%s" % (len(new), named(new)))
    if gone:
        problems += 1
        print("wp-replay: FAILED: %d goal(s) of the proof that made the cache were not generated "
              "(the replay has %d goals, the proof had %d):\n%s"
              % (len(gone), len(replay), len(manifest), named(gone)))
    if uncached:
        problems += 1
        print("wp-replay: FAILED: %d goal(s) proven by a prover that is not Qed and not from the "
              "cache:\n%s" % (len(uncached), named(uncached)))
    if problems:
        print("wp-replay: the committed cache is stale: " + HOW_TO_REFRESH)
        return 1
    qed = sum(r["prover"] == "Qed" for r in replay.values())
    print("wp-replay: %d goals (the proof that made the cache had %d), all proven: %d by Qed, "
          "%d from the cache%s" % (len(replay), len(manifest), qed, len(cached),
                                   (", %.0f s" % secs) if secs is not None else ""))
    return 0


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("commit")
    c.add_argument("run_cache")
    c.add_argument("report")
    c.add_argument("cache_dir")
    k = sub.add_parser("check")
    k.add_argument("report")
    k.add_argument("log")
    k.add_argument("cache_dir")
    k.add_argument("--subset", action="store_true")
    k.add_argument("--seconds", type=float)
    args = ap.parse_args()
    if args.cmd == "commit":
        return commit(args.run_cache, args.report, args.cache_dir)
    return check(args.report, args.log, args.cache_dir, args.subset, args.seconds)


if __name__ == "__main__":
    sys.exit(main())
