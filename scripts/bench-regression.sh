#!/usr/bin/env bash
# The speed table against a base build: every generated family (one, two and many robots) on
# fresh seeds, planned by this checkout's build and by BASE's (the last landed main), with the
# default planner (auto) and MMS alone (mms, --optimize 0). Both builds plan the same scene
# files (made by this checkout's generators), family by family in turn, so that both see the
# machine as it is then. Exit 1 when a family's median is 1.3x the base's or more (and slower by
# more than 10 ms, below which a median is noise) or fewer of its seeds are solved.
# Usage: scripts/bench-regression.sh BASE [OUTPUT_DIR]  (default bench-regression)
#   BASE: a commit, e.g. the main CI last landed. Its build is kept in $TMPDIR (default /tmp)
#   under mms-base-SHA and reused.
# Environment: SEEDS (scene seeds, default "100 101 102 103 104"), RUNS (planner seeds per
# scene, default 3: a family's median is then of 15 runs, steadier than 5 on a shared machine),
# LIMIT (seconds per run, default 10), FAMILIES (default: all below), PLANNERS (default
# auto,mms), RATIO (default 1.3). About 10 min at the defaults, besides building the base (8
# min on 2 cores, once); it resumes where it stopped. Build nothing else meanwhile: a compile
# on the other core moved single runs by 30 %.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ $# -lt 1 ]]; then
  echo "usage: scripts/bench-regression.sh BASE [OUTPUT_DIR]" >&2
  exit 2
fi
sha=$(git rev-parse --verify --quiet "$1^{commit}") || {
  echo "bench-regression: '$1' is not a commit of this repository" >&2
  exit 2
}
out=${2:-bench-regression}
seeds=${SEEDS:-100 101 102 103 104}
limit=${LIMIT:-10}
planners=${PLANNERS:-auto,mms}
families=${FAMILIES:-bend doors keyhole swallow open-clutter carry-turn niche-swap swallow-two \
niche-three discs-swap discs-room round-room disc-grid disc-triangles disc-box warehouse}

bash scripts/setup.sh >/dev/null
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target mms >/dev/null
base=${TMPDIR:-/tmp}/mms-base-$sha
if [[ ! -x $base/build/mms ]]; then
  echo "bench-regression: building $sha in $base"
  [[ -d $base ]] || git worktree add --detach -f "$base" "$sha" >/dev/null
  cmake -S "$base" -B "$base/build" -DCMAKE_BUILD_TYPE=Release -DMMS_BUILD_TESTS=OFF \
    -DMMS_BUILD_BENCH=OFF -DMMS_BUILD_PYTHON=OFF >/dev/null
  cmake --build "$base/build" -j"$(nproc)" --target mms >/dev/null
fi

mkdir -p "$out/scenes"
for f in $families; do
  scenes=()
  for k in $seeds; do
    build/mms scenario "$f" --seed "$k" -o "$out/scenes/$f-$k.json" >/dev/null
    scenes+=("$out/scenes/$f-$k.json")
  done
  # One run at a time (an auto run takes both cores), the base first, then this build.
  for side in base new; do
    exe=build/mms
    [[ $side == base ]] && exe=$base/build/mms
    "$exe" bench "${scenes[@]}" --planners "$planners" --param "mms=--optimize 0" --runs "${RUNS:-3}" \
      --time-limit "$limit" --jobs 1 -o "$out/$side/$f" >/dev/null
  done
done
python3 scripts/regression-summary.py "$out" "$limit" "${RATIO:-1.3}" $families | tee "$out/summary.md"
