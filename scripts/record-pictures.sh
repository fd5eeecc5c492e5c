#!/usr/bin/env bash
# The pictures of docs/record.md: the Pacman planned by MMS and by RRT-Connect with a record of
# each, the viewer's page of each (MMS at its end, one subspace; RRT-Connect half-way through),
# and a headless Chromium screenshot of it (docs/record/pacman-PLANNER.png). Needs build/mms.
set -euo pipefail
cd "$(dirname "$0")/.."

scene=scenes/two-robots/pacman-0.5.json
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p docs/record
for planner in mms rrtconnect; do
  build/mms plan "$scene" --planner "$planner" --seed 1 -q -o "$work/$planner.path.json" \
    --record "$work/$planner.record.json"
  build/mms view "$scene" "$work/$planner.path.json" --record "$work/$planner.record.json" \
    -o "$work/$planner.html" >/dev/null
  at="rt=1&sub=1&layers=cells,lines,path"
  [ "$planner" = mms ] || at="rt=0.5&layers=tree"
  chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --force-device-scale-factor=1 \
    --window-size=820,470 --virtual-time-budget=5000 --user-data-dir="$work/profile" \
    --screenshot="docs/record/pacman-$planner.png" \
    "file://$work/$planner.html#fit=0&t=0&traces=0&$at" 2>/dev/null
  echo "docs/record/pacman-$planner.png"
done
