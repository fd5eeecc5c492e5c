#!/usr/bin/env bash
# MMS, the default planner (auto) and OMPL's RRT-Connect on every OMPL.app planar problem (read
# from ../shared, never copied here), 5 seeds each, in one mms bench run: the table in
# docs/import.md.
#   RUNS=5 LIMIT=60 JOBS=2 PLANNERS=mms,auto,rrtconnect bash scripts/bench-omplapp.sh [OUT]
set -euo pipefail
cd "$(dirname "$0")/.."
data=${OMPLAPP_DIR:-../shared/data/omplapp-2d}
if ! ls "$data"/*.cfg >/dev/null 2>&1; then
  echo "bench-omplapp: no OMPL.app problems in $data (set OMPLAPP_DIR)" >&2
  exit 2
fi
out=${1:-bench-omplapp}
build/mms bench "$data"/*.cfg --planners "${PLANNERS:-mms,auto,rrtconnect}" --param "mms=--threads 1" \
  --runs "${RUNS:-5}" --time-limit "${LIMIT:-60}" --jobs "${JOBS:-2}" -o "$out"
echo "report: $out/report.md"
