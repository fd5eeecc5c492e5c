#!/usr/bin/env bash
# Many robots (docs/benchmarks.md, "Many robots"): the many-robot families (discs among
# triangles and on grids, the box of touching discs, carts in a warehouse) at the sizes of the
# targets, MMS (mms: the ordered planner from 8 robots), the k-robot MMS (mms-joint) and OMPL's
# RRT-Connect in the robots' compound space, in one `mms bench` run; then MMS alone on growing
# numbers of discs (20 to 500), for time and memory against the number of robots.
# Usage: scripts/bench-many-robots.sh tuning|fresh [OUTPUT_DIR] (default bench-many-robots-SET)
# Environment: LIMIT (seconds per run, default 10), JOBS (default 2), FAMILIES (default below;
# NAME:ROBOTS[:SPACING]), PLANNERS (default mms,mms-joint,rrtconnect), SIZES (the sweep's
# numbers of robots, default "20 50 100 200 500"), SWEEP_SEEDS (default 5 of the set).
# Writes OUTPUT_DIR/summary.md (medians, seeds solved, peak memory; makespan and sum of
# distances against their bounds, robots moving at once) and OUTPUT_DIR/sweep/bench
# (whose report.md has the plot robots.svg).
set -euo pipefail
cd "$(dirname "$0")/.."
set_name=${1:-}
case "$set_name" in
  tuning) seeds=$(seq 1 10) ;;
  fresh) seeds=$(seq 100 119) ;;
  *) echo "usage: scripts/bench-many-robots.sh tuning|fresh [OUTPUT_DIR]" >&2; exit 2 ;;
esac
out=${2:-bench-many-robots-$set_name}
limit=${LIMIT:-10}
jobs=${JOBS:-2}
families=${FAMILIES:-disc-triangles:20 disc-grid:50:3 disc-grid:100:5 disc-triangles:100 disc-grid:500:10 disc-box:29 warehouse:20}
planners=${PLANNERS:-mms,mms-joint,rrtconnect}
sizes=${SIZES:-20 50 100 200 500}
sweep_seeds=${SWEEP_SEEDS:-$(echo $seeds | tr ' ' '\n' | head -5 | tr '\n' ' ')}

if [[ ! -x build/mms ]]; then
  bash scripts/setup.sh
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build -j"$(nproc)" --target mms
fi
# NAME:ROBOTS[:SPACING] seed -> a scene file (named NAME-ROBOTS[-sSPACING]-SEED)
make_scene() {
  local spec=$1 k=$2 dir=$3
  IFS=: read -r name robots spacing <<<"$spec"
  local file=$name-$robots${spacing:+-s$spacing}-$k.json
  build/mms scenario "$name" --seed "$k" --robots "$robots" ${spacing:+--spacing "$spacing"} \
    -o "$dir/$file" >/dev/null
  echo "$dir/$file"
}
mkdir -p "$out/scenes" "$out/sweep/scenes"
scenes=()
for spec in $families; do
  for k in $seeds; do scenes+=("$(make_scene "$spec" "$k" "$out/scenes")"); done
done
build/mms bench "${scenes[@]}" --planners "$planners" --runs 1 --time-limit "$limit" \
  --jobs "$jobs" -o "$out/bench"
# The sweep: sparse grids and discs among triangles, MMS alone, a minute per run.
sweep=()
for n in $sizes; do
  for k in $sweep_seeds; do
    sweep+=("$(make_scene "disc-grid:$n:10" "$k" "$out/sweep/scenes")")
    sweep+=("$(make_scene "disc-triangles:$n" "$k" "$out/sweep/scenes")")
  done
done
build/mms bench "${sweep[@]}" --planners mms --runs 1 --time-limit 60 --jobs "$jobs" \
  -o "$out/sweep/bench"
python3 scripts/many-robots-summary.py "$out/bench/results.csv" "$limit" "$out/sweep/bench/results.csv" \
  > "$out/summary.md"
{ echo; echo "Seeds: $set_name ($(echo $seeds | awk '{print $1"-"$NF}')), limit $limit s, $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"; } >> "$out/summary.md"
cat "$out/summary.md"
