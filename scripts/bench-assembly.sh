#!/usr/bin/env bash
# The assembly comparison behind docs/benchmarks.md's "Assembly" section: MMS against OMPL's RRT
# and PRM (as in the paper's Further Work) on the two 4-D assembly problems, 10 seeds each, in
# one mms bench run; then how small the slack can get for MMS (5 seeds per slack, 60 s each).
# Usage: scripts/bench-assembly.sh [OUTPUT_DIR] (default bench-assembly); about 10 + 6 minutes on
# 2 cores (most of the first part is the OMPL planners running into the time limit).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-bench-assembly}
cmake --build build -j"$(nproc)" --target mms
build/mms bench scenes/assembly/assembly-1.json scenes/assembly/assembly-2-m-parts.json \
  --planners mms,rrt,prm --runs 10 --time-limit 30 --jobs 2 -o "$out"
mkdir -p "$out/slack"
scenes=()
for s in 0.02 0.01 0.005 0.002; do
  build/mms scenario assembly-1 --slack "$s" -o "$out/slack/assembly-1-$s.json"
  build/mms scenario assembly-2 --m-parts-only --slack "$s" -o "$out/slack/assembly-2-m-parts-$s.json"
  scenes+=("$out/slack/assembly-1-$s.json" "$out/slack/assembly-2-m-parts-$s.json")
done
build/mms bench "${scenes[@]}" --planners mms --runs 5 --time-limit 60 --jobs 2 -o "$out/slack"
echo "bench-assembly: $out/report.md, $out/slack/report.md"
