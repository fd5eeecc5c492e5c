#!/usr/bin/env bash
# The speed table of docs/benchmarks.md: MMS and OMPL's planners on the target scenes
# in one `mms bench` run, MMS on both cores (--threads 2). The report's first table compares MMS
# with the best other planner per scene and counts the manifolds the solution uses against those
# built (the oracle's distance). Usage: scripts/bench-speed.sh [OUTPUT_DIR] (default bench-speed)
# Environment: RUNS (seeds 1..RUNS, default 20), LIMIT (seconds per run, default 60), JOBS (cores
# to fill, default 2: two single-threaded OMPL runs at a time, an MMS run with --threads 2 alone),
# PLANNERS (default all below), STOP_DECIDED (default 1: a planner's remaining seeds on a scene
# are not run once half of them failed, its median being decided; 0 runs them all).
# The full protocol takes about 3 hours: the OMPL planners use their whole limit on the tight
# scenes. It resumes where it stopped (Ctrl-C is safe).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-bench-speed}
runs=${RUNS:-20}
limit=${LIMIT:-60}
jobs=${JOBS:-2}
planners=${PLANNERS:-mms,rrtconnect,rrt,kpiece,bkpiece,prm,prm-bridge,uobprm}
stop=()
[[ ${STOP_DECIDED:-1} == 0 ]] || stop=(--stop-decided)

bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target mms

s=scenes
build/mms bench \
  $s/two-robots/random-polygons.json $s/two-robots/viking-helmet.json \
  $s/one-robot/bar-slot.json $s/one-robot/corridor-corner.json \
  $s/assembly/assembly-1.json $s/assembly/assembly-2-m-parts.json \
  --sweep-pacman 0,0.9,0.98 \
  --planners "$planners" \
  --param "mms=--threads 2" \
  --runs "$runs" --time-limit "$limit" --jobs "$jobs" "${stop[@]}" -o "$out"
{ echo; echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(free -g | awk '/Mem/{print $2}') GiB"; } >> "$out/report.md"
echo "bench-speed: $out/report.md (first table: MMS against the best other planner), $out/results.csv"
