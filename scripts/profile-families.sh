#!/usr/bin/env bash
# Where MMS spends its time on each generated family: `mms plan --planner mms` on seeds of each
# family, one run at a time, and per family the median of every phase (slices, lines, connect,
# search, motion, certify, and the optimiser after the path), of the time to the path and of the
# rounds. Say which phase bounds a family before changing it, and run it again after.
# Usage: scripts/profile-families.sh [SEEDS] (default "1 2 3 4 5 6 7 8 9 10", the tuning seeds)
# Environment: FAMILIES (default: the tight families; FAMILY@SLACK for `--slack SLACK`),
# MMS (the binary, default build/mms), ARGS (more options for `mms plan`), LIMIT (default 30 s).
set -euo pipefail
cd "$(dirname "$0")/.."
seeds=${1:-1 2 3 4 5 6 7 8 9 10}
families=${FAMILIES:-keyhole keyhole@0.03 carry-turn carry-turn@0.03 swallow swallow@0.03 niche-swap doors}
mms=${MMS:-build/mms}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for spec in $families; do
  f=${spec%@*}
  slack=()
  [[ $spec == *@* ]] && slack=(--slack "${spec#*@}")
  for k in $seeds; do
    "$mms" scenario "$f" --seed "$k" "${slack[@]}" -o "$work/scene.json" >/dev/null
    "$mms" plan "$work/scene.json" -q --planner mms --seed 1 --time-limit "${LIMIT:-30}" \
      ${ARGS:-} -o "$work/path.json" --stats-json "$work/$spec-$k.json" >/dev/null || true
  done
done
python3 - "$work" $families <<'PY'
import json, os, statistics, sys
work, families = sys.argv[1], sys.argv[2:]
print("| family | solved | to the path (s) | phases to the path, largest first (median s) | optimize (s) | rounds |")
print("|---|---|---|---|---|---|")
med = statistics.median
for fam in families:
    runs = [json.load(open(os.path.join(work, n))) for n in sorted(os.listdir(work))
            if n.startswith(fam + "-") and n[len(fam) + 1:-5].isdigit()]
    found = [r for r in runs if r["status"] == "found"]
    if not found:
        print(f"| {fam} | 0/{len(runs)} | | | | |")
        continue
    names = {p for r in found for p in r["statistics"]["phases"] if p != "optimize"}
    phase = {p: med([r["statistics"]["phases"].get(p, 0) for r in found]) for p in names}
    top = sorted(phase.items(), key=lambda kv: -kv[1])[:4]
    print(f"| {fam} | {len(found)}/{len(runs)} | {med([r['seconds'] for r in found]):.3f} | "
          + ", ".join(f"{p} {v:.3f}" for p, v in top) + " | "
          + f"{med([r['statistics']['phases'].get('optimize', 0) for r in found]):.3f} | "
          + f"{med([r['statistics'].get('rounds', 0) for r in found]):g} |")
PY
