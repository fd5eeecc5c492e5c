#!/usr/bin/env bash
# Regenerates the measurements behind docs/benchmarks.md: MMS and the OMPL baselines on the
# paper's scenes and the one-robot scenes, and the Pacman tightness sweep. About 25 minutes on
# 2 cores (two runs at a time). Usage: scripts/bench-report.sh [OUTPUT_DIR] (default bench-report)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-bench-report}

bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target mms

s=scenes
build/mms bench \
  $s/two-robots/random-polygons.json $s/two-robots/viking-helmet.json \
  $s/one-robot/bar-slot.json $s/one-robot/corridor-corner.json $s/one-robot/bug-trap.json $s/one-robot/maze.json \
  --planners mms,prm,obprm,uobprm,prm-bridge,prm-gaussian,rrt,rrtconnect,kpiece,bkpiece,lazyprm \
  --runs 5 --time-limit 10 --jobs 2 -o "$out"
build/mms bench --sweep-pacman 0,0.5,0.8,0.9,0.95 \
  --planners mms,prm,obprm,uobprm,prm-bridge,rrtconnect \
  --runs 5 --time-limit 20 --jobs 2 -o "$out"
# The other five planners on one Pacman scene, so every planner runs on every scenario.
build/mms bench --sweep-pacman 0.5 \
  --planners prm-gaussian,rrt,kpiece,bkpiece,lazyprm \
  --runs 5 --time-limit 20 --jobs 2 -o "$out"
{ echo; echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(free -g | awk '/Mem/{print $2}') GiB"; } >> "$out/report.md"
echo "bench-report: $out/report.md, $out/tightness.svg, $out/results.csv, $out/ompl/*.log"
