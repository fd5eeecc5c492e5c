#!/usr/bin/env python3
"""The many-robot tables from `mms bench` results (scripts/bench-many-robots.sh).

Usage: many-robots-summary.py RESULTS_CSV TIME_LIMIT [SWEEP_RESULTS_CSV]

Scenes are grouped into families by their name without the trailing "-SEED". Per family and
planner: the median time to the first certified path over the seeds (a failure counts as the
limit), the seeds solved and the median peak memory; then, over the solved runs, the median
makespan and sum of distances against their lower bounds and the robots moving at once. The
sweep's table: per family and number of robots, MMS's median time and memory.
"""
import csv
import re
import statistics
import sys
from collections import defaultdict


def robots_in(family):
    """The robot count a family's name carries ("disc-grid-500"), or 0."""
    m = re.search(r"-(\d+)", family)
    return int(m.group(1)) if m else 0


def read(path, limit):
    rows = defaultdict(list)  # (family, planner) -> [(seconds or limit, solved, memory MB)]
    fleets = defaultdict(list)  # (family, planner) -> [(makespan, distance ratios, moving)]
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            family = re.sub(r"-\d+$", "", row["scene"])
            ok = row["status"] == "found"
            seconds = min(float(row["seconds"]), limit) if ok else limit
            memory = float(row["peak_memory_mb"] or 0)
            rows[(family, row["planner"])].append((seconds, ok, memory))
            if ok and row.get("makespan_bound"):
                fleets[(family, row["planner"])].append(
                    (float(row["makespan"]) / float(row["makespan_bound"]),
                     float(row["distance"]) / float(row["distance_bound"]),
                     float(row["moving_at_once"])))
    read.fleets = fleets
    return rows


def fleet_cell(runs):
    if not runs:
        return "–"
    return " / ".join(f"{statistics.median(r[k] for r in runs):.3g}" for k in range(3))


def cell(runs, limit):
    m = statistics.median(r[0] for r in runs)
    solved = sum(1 for r in runs if r[1])
    memory = statistics.median(r[2] for r in runs)
    text = f"> {limit:g}" if m >= limit else f"{m:.3g} s"
    return f"{text} ({solved}/{len(runs)}, {memory:.0f} MB)"


def main():
    path, limit = sys.argv[1], float(sys.argv[2])
    rows = read(path, limit)
    families = sorted({f for f, _ in rows}, key=lambda f: (robots_in(f), f))
    planners = sorted({p for _, p in rows}, key=lambda p: (not p.startswith("mms"), p))
    print("| family | " + " | ".join(planners) + " |")
    print("|---|" + "---|" * len(planners))
    for family in families:
        print(f"| {family} | " + " | ".join(
            cell(rows[(family, p)], limit) if (family, p) in rows else "–" for p in planners) + " |")
    fleets = read.fleets
    print()
    print("Makespan / its bound, sum of distances / its bound, robots moving at once (medians of "
          "the solved runs):")
    print()
    print("| family | " + " | ".join(planners) + " |")
    print("|---|" + "---|" * len(planners))
    for family in families:
        print(f"| {family} | " + " | ".join(fleet_cell(fleets[(family, p)]) for p in planners)
              + " |")
    if len(sys.argv) > 3:
        sweep = read(sys.argv[3], 60)
        print()
        print("| family | robots | MMS: median time (solved) | peak memory (median) |")
        print("|---|---|---|---|")
        keys = sorted(sweep, key=lambda k: (re.sub(r"-\d+.*", "", k[0]), robots_in(k[0])))
        for family, planner in keys:
            runs = sweep[(family, planner)]
            m = statistics.median(r[0] for r in runs)
            n = robots_in(family)
            print(f"| {re.sub(r'-[0-9].*', '', family)} | {n} | {m:.3g} s ({sum(r[1] for r in runs)}/{len(runs)}) "
                  f"| {statistics.median(r[2] for r in runs):.0f} MB |")


if __name__ == "__main__":
    main()
