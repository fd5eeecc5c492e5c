#!/usr/bin/env python3
"""The comparison of scripts/bench-regression.sh: per family and planner, the median seconds
to a certified path of this build and of the base (a failure counts as the limit), the seeds
each solved, and their ratio (above 1: this build is slower).

Usage: regression-summary.py OUT_DIR TIME_LIMIT RATIO FAMILY...

Reads OUT_DIR/{base,new}/FAMILY/results.csv. Exit 1 when a family is RATIO times slower or more
and slower by more than FLOOR seconds, or solves fewer seeds; the lines under the table name
those families.
"""
import csv
import os
import statistics
import sys

FLOOR = 0.01  # seconds: below this, a median's difference is the machine's noise


def medians(path, limit):
    """planner -> (median seconds, seeds solved, seeds run) of one build's results.csv."""
    runs = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            ok = row["status"] == "found"
            seconds = min(float(row["seconds"]), limit) if ok else limit
            runs.setdefault(row["planner"], []).append((seconds, ok))
    return {p: (statistics.median(s for s, _ in v), sum(ok for _, ok in v), len(v))
            for p, v in runs.items()}


def cell(m, limit):
    seconds, solved, total = m
    text = f"> {limit:g}" if seconds >= limit else f"{seconds:.3g}"
    return f"{text} ({solved}/{total})"


def main():
    out, limit, ratio_bound = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    families = sys.argv[4:]
    print("| family | planner | base | this build | ratio |")
    print("|---|---|---|---|---|")
    slower = []
    for family in families:
        paths = [os.path.join(out, side, family, "results.csv") for side in ("base", "new")]
        if not all(os.path.exists(p) for p in paths):
            slower.append(f"{family}: no results (the bench did not finish)")
            continue
        base, new = (medians(p, limit) for p in paths)
        for planner in sorted(new):
            b, n = base.get(planner), new[planner]
            if b is None:
                print(f"| {family} | {planner} | – | {cell(n, limit)} | – |")
                continue
            ratio = n[0] / b[0] if b[0] > 0 else 1.0
            print(f"| {family} | {planner} | {cell(b, limit)} | {cell(n, limit)} | {ratio:.2f} |")
            if n[1] < b[1]:
                slower.append(f"{family} ({planner}): {n[1]} seeds solved, the base {b[1]}")
            elif ratio >= ratio_bound and n[0] - b[0] > FLOOR:
                slower.append(f"{family} ({planner}): {ratio:.2f}x the base's median")
    print()
    if slower:
        print(f"Slower than the base ({ratio_bound:g}x or more, or fewer seeds solved):")
        for line in slower:
            print(f"- {line}")
        sys.exit(1)
    print(f"No family {ratio_bound:g}x slower than the base, none solving fewer seeds.")


if __name__ == "__main__":
    main()
