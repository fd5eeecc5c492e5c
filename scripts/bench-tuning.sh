#!/usr/bin/env bash
# The parameter check once behind docs/benchmarks.md's "Tuning" section (in its history): the PRM family with k = 5 and
# k = 20 neighbours (10 is OMPL's default, in the main report) and RRT-Connect with a shorter and a
# longer range, on the two scenes where the baselines struggle, beside MMS in the same run.
# Usage: scripts/bench-tuning.sh [OUTPUT_DIR] (default bench-tuning); about 10 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-bench-tuning}
cmake --build build -j"$(nproc)" --target mms
scenes=(scenes/two-robots/viking-helmet.json scenes/two-robots/pacman-0.8.json)
common=(--runs 5 --time-limit 20 --jobs 2 -o "$out")
build/mms bench "${scenes[@]}" --planners mms,prm,prm-bridge,uobprm "${common[@]}"
for k in 5 20; do
  build/mms bench "${scenes[@]}" --planners prm,prm-bridge,uobprm \
    --param "prm=--k $k" --param "prm-bridge=--k $k" --param "uobprm=--k $k" "${common[@]}"
done
for range in 2 10; do
  build/mms bench "${scenes[@]}" --planners rrtconnect --param "rrtconnect=--range $range" "${common[@]}"
done
echo "bench-tuning: $out/report.md"
