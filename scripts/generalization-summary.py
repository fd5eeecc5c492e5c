#!/usr/bin/env python3
"""The generalization suite's table from an `mms bench` results.csv (one run per scene, or the
median of a scene's runs).

Usage: generalization-summary.py RESULTS_CSV TIME_LIMIT [seconds|wall_seconds]

The time is the planner's time to its first certified path (`seconds`, the default), or the
whole command as a user waits for it (`wall_seconds`: process, scene, planning, the optimiser,
the path file).

Scenes are grouped into families by their name without the trailing "-SEED". Per family and
planner: the median time over the family's seeds (a failure counts as the limit, so a median
at the limit reads "> limit") and the seeds solved. Then, for auto and mms, the ratio of the
best OMPL planner's median to theirs (above 1: ours is faster), and the median over seeds of
the per-seed ratio (the best OMPL time on that seed over ours; a failure counts as the limit,
which makes the ratio a bound).
"""
import csv
import re
import statistics
import sys
from collections import defaultdict

OURS = ("auto", "mms")


def main():
    path, limit = sys.argv[1], float(sys.argv[2])
    column = sys.argv[3] if len(sys.argv) > 3 else "seconds"
    per_run = defaultdict(lambda: defaultdict(list))  # (family, planner) -> {seed scene: [seconds]}
    solved_by = defaultdict(lambda: defaultdict(int))
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            family = re.sub(r"-\d+$", "", row["scene"])
            ok = row["status"] == "found"
            seconds = float(row[column]) if ok else limit
            per_run[(family, row["planner"])][row["scene"]].append(min(seconds, limit))
            if ok and row.get("solved_by"):
                solved_by[family][row["solved_by"]] += 1
    # Several runs of a scene (`mms bench --runs N`): their median stands for the scene.
    times = {k: {scene: statistics.median(v) for scene, v in by_scene.items()}
             for k, by_scene in per_run.items()}
    families = sorted({f for f, _ in times})
    planners = sorted({p for _, p in times}, key=lambda p: (p not in OURS, OURS.index(p) if p in OURS else 0, p))

    def median(family, planner):
        return statistics.median(times[(family, planner)].values())

    def solved(family, planner):
        return sum(1 for t in times[(family, planner)].values() if t < limit)

    def cell(family, planner):
        if (family, planner) not in times:
            return "–"
        m = median(family, planner)
        runs = len(times[(family, planner)])
        text = f"> {limit:g}" if m >= limit else f"{m:.3g}"
        return f"{text} ({solved(family, planner)}/{runs})"

    print("| family | " + " | ".join(planners) + " |")
    print("|---|" + "---|" * len(planners))
    for family in families:
        print(f"| {family} | " + " | ".join(cell(family, p) for p in planners) + " |")
    print()
    print("| family | ours | best OMPL planner (median) | ratio of medians | median per-seed ratio | auto's paths by |")
    print("|---|---|---|---|---|---|")
    for family in families:
        others = [p for p in planners if p not in OURS and (family, p) in times]
        if not others:
            continue
        best = min(others, key=lambda p: (median(family, p), -solved(family, p)))
        for ours in OURS:
            if (family, ours) not in times:
                continue
            mo, mb = median(family, ours), median(family, best)
            ratio = mb / mo if mo > 0 else float("inf")
            bound = ">= " if mb >= limit and mo < limit else ""
            per_seed = []
            for scene, t in times[(family, ours)].items():
                best_here = min(times[(family, p)].get(scene, limit) for p in others)
                per_seed.append(best_here / t if t > 0 else float("inf"))
            by = ", ".join(f"{k} {v}" for k, v in sorted(solved_by[family].items())) if ours == "auto" else ""
            best_text = f"{best}: " + (f"> {limit:g}" if mb >= limit else f"{mb:.3g}")
            print(f"| {family} | {ours} | {best_text} | {bound}{ratio:.3g}x | {statistics.median(per_seed):.3g}x | {by} |")


if __name__ == "__main__":
    main()
