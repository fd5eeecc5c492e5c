#!/usr/bin/env bash
# The speed table of docs/benchmarks.md (issue 8): MMS and OMPL's planners on the target scenes
# in one `mms bench` run, MMS on both cores (--threads 2). The report's first table compares MMS
# with the best other planner per scene and counts the manifolds the solution uses against those
# built (the oracle's distance). Usage: scripts/bench-speed.sh [OUTPUT_DIR] (default bench-speed)
# Environment: RUNS (seeds 1..RUNS, default 20), LIMIT (seconds per run, default 60), JOBS (runs
# at a time, default 1: MMS uses both cores). The full protocol takes hours: the OMPL planners
# use their whole limit on the tight scenes.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-bench-speed}
runs=${RUNS:-20}
limit=${LIMIT:-60}
jobs=${JOBS:-1}

bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target mms

s=scenarios
build/mms bench \
  $s/two-robots/random-polygons.json $s/two-robots/viking-helmet.json \
  $s/one-robot/bar-slot.json $s/one-robot/corridor-corner.json \
  $s/assembly/assembly-1.json $s/assembly/assembly-2-m-parts.json \
  --sweep-pacman 0,0.9,0.98 \
  --planners mms,rrtconnect,rrt,kpiece,bkpiece,prm,prm-bridge,uobprm \
  --param "mms=--threads 2" \
  --runs "$runs" --time-limit "$limit" --jobs "$jobs" -o "$out"
{ echo; echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(free -g | awk '/Mem/{print $2}') GiB"; } >> "$out/report.md"
echo "bench-speed: $out/report.md (first table: MMS against the best other planner), $out/results.csv"
