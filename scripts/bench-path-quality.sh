#!/usr/bin/env bash
# Path quality against OMPL in one `mms bench` run: generated scenes of six families (seeds as
# given), MMS and auto with path optimisation (and --restarts R), OMPL's RRT-Connect, KPIECE1
# and PRM with OMPL's simplifier, RRT* and BIT* (which improve their path for the whole limit).
# Prints per scene the certified length (translation summed over robots) of mms, auto and the
# best OMPL planner, the ratio mms / best OMPL, and the ratio auto / the best of the three
# simplified OMPL paths (docs/benchmarks.md, "Path quality").
# Usage: scripts/bench-path-quality.sh OUT_DIR RESTARTS SEED...   e.g. q 8 103 104 105
set -euo pipefail
cd "$(dirname "$0")/.."
out=$1 restarts=$2
shift 2
mms=${MMS:-build/mms}
mkdir -p "$out/scenes"
scenes=()
for family in bend carry-turn discs-swap doors niche-swap open-clutter; do
  for seed in "$@"; do
    f="$out/scenes/$family-$seed.json"
    "$mms" scenario "$family" --seed "$seed" -o "$f" >/dev/null
    scenes+=("$f")
  done
done
"$mms" bench "${scenes[@]}" --planners mms,auto,rrtconnect,kpiece,prm,rrtstar,bitstar \
  --param "rrtconnect=--simplify" --param "kpiece=--simplify" --param "prm=--simplify" \
  --param "mms=--restarts $restarts" --param "auto=--restarts $restarts" \
  --runs 1 --time-limit "${TIME_LIMIT:-5}" --jobs "${JOBS:-2}" -o "$out/bench" >/dev/null
python3 - "$out/bench/results.csv" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
ompl = {"rrtconnect": "RRT-Connect", "kpiece": "KPIECE1", "prm": "PRM", "rrtstar": "RRT*",
        "bitstar": "BIT*"}
simplified = ("rrtconnect", "kpiece", "prm")  # one path each, then OMPL's simplifier
print("| scene | mms length / rotation | auto | best OMPL length (planner) | mms / best OMPL | auto / best simplified |")
print("|---|---|---|---|---|---|")
ratios, auto_ratios = [], []
for scene in dict.fromkeys(r["scene"] for r in rows):
    mine = {r["planner"]: r for r in rows if r["scene"] == scene and r["status"] == "found"}
    def cell(p):
        r = mine.get(p)
        return f"{float(r['translation']):.1f} / {float(r['rotation']):.2f}" if r else "none"
    def best_of(planners):
        found = [(float(r["translation"]), ompl[p]) for p, r in mine.items() if p in planners]
        return min(found) if found else None
    best, best_simplified = best_of(ompl), best_of(simplified)
    ratio = auto_ratio = "–"
    if best and "mms" in mine:
        ratios.append(float(mine["mms"]["translation"]) / best[0])
        ratio = f"{ratios[-1]:.2f}"
    if best_simplified and "auto" in mine:
        auto_ratios.append(float(mine["auto"]["translation"]) / best_simplified[0])
        auto_ratio = f"{auto_ratios[-1]:.2f}"
    b = f"{best[0]:.1f} ({best[1]})" if best else "none solved"
    print(f"| {scene} | {cell('mms')} | {cell('auto')} | {b} | {ratio} | {auto_ratio} |")
def line(name, rs, against):
    if rs:
        print(f"\n{name} within 1.1x of {against} on {sum(r <= 1.1 for r in rs)} of {len(rs)} "
              f"scenes; median ratio {statistics.median(rs):.2f}, worst {max(rs):.2f}")
line("mms", ratios, "the best OMPL length (RRT* and BIT* included)")
line("auto", auto_ratios, "the best simplified OMPL length (RRT-Connect, KPIECE1, PRM)")
PY
