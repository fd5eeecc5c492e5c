#!/usr/bin/env bash
# The generalization suite of docs/benchmarks.md: fresh random instances of every generated
# scene family (`mms scenario NAME --seed K`), the default planner (auto), MMS alone and OMPL's
# PRM, PRM + bridge, RRT-Connect and KPIECE1 with default parameters, in one `mms bench` run.
# Tune on the tuning seeds (1-10), report on the fresh ones (100-119), which nobody looked at
# while tuning.
# Usage: scripts/bench-generalization.sh tuning|fresh|fresh2 [OUTPUT_DIR] (default
# bench-generalization-SET); fresh2 is seeds 200-219, for when a fresh seed had to be looked at.
# Environment: LIMIT (seconds per run, default 10), JOBS (cores to fill, default 2; an auto run
# takes both), RUNS (runs per scene and planner, default 1; a scene counts at its runs' median),
# FAMILIES (default: all below; FAMILY:ROBOT[,ROBOT] for the family with those robots
# translating only, e.g. niche-three:oncoming), PLANNERS (default: the six above).
# It writes OUTPUT_DIR/summary.md: per family and planner, the median over seeds (a failure
# counts as the limit) and the seeds solved, and the ratios of the best OMPL planner's median to
# auto's and to MMS's (above 1: ours is faster); summary-whole-command.md the same for the whole
# `mms plan` command (with JOBS=1 each run has the machine to itself). The OMPL planners use
# their whole limit on the tight families: about 25 min for the fresh set at the default limit.
# It resumes where it stopped.
set -euo pipefail
cd "$(dirname "$0")/.."
set_name=${1:-}
case "$set_name" in
  tuning) seeds=$(seq 1 10) ;;
  fresh) seeds=$(seq 100 119) ;;
  fresh2) seeds=$(seq 200 219) ;;  # a second fresh set, once the first has been looked at
  *) echo "usage: scripts/bench-generalization.sh tuning|fresh|fresh2 [OUTPUT_DIR]" >&2; exit 2 ;;
esac
out=${2:-bench-generalization-$set_name}
limit=${LIMIT:-10}
jobs=${JOBS:-2}
families=${FAMILIES:-carry-turn niche-swap niche-three discs-swap discs-room open-clutter bend doors keyhole swallow}
planners=${PLANNERS:-auto,mms,prm,prm-bridge,rrtconnect,kpiece}

if [[ ! -x build/mms ]]; then
  bash scripts/setup.sh
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build -j"$(nproc)" --target mms
fi
mkdir -p "$out/scenes"
scenes=()
for spec in $families; do
  # FAMILY:ROBOT[,ROBOT]: the family with those robots translating only (`--translate`).
  f=${spec%%:*}
  extra=()
  file=$f
  if [[ $spec == *:* ]]; then
    extra=(--translate "${spec#*:}")
    IFS=, read -ra robots <<<"${spec#*:}"
    for robot in "${robots[@]}"; do file+=-$robot-translates; done  # as the scene is named
  fi
  for k in $seeds; do
    build/mms scenario "$f" --seed "$k" "${extra[@]}" -o "$out/scenes/$file-$k.json" >/dev/null
    scenes+=("$out/scenes/$file-$k.json")
  done
done
build/mms bench "${scenes[@]}" --planners "$planners" --runs "${RUNS:-1}" --time-limit "$limit" \
  --jobs "$jobs" -o "$out/bench"
python3 scripts/generalization-summary.py "$out/bench/results.csv" "$limit" > "$out/summary.md"
python3 scripts/generalization-summary.py "$out/bench/results.csv" "$limit" wall_seconds \
  > "$out/summary-whole-command.md"
for f in summary summary-whole-command; do
  { echo; echo "Seeds: $set_name ($(echo $seeds | awk '{print $1"-"$NF}')), limit $limit s, $jobs job(s) on $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"; } >> "$out/$f.md"
done
cat "$out/summary.md"
