#!/usr/bin/env bash
# Installs what is missing, builds mms, and runs the demo: plan a bundled one-robot scene (a bar
# that must turn to leave a bug trap), certify the path, and draw it as an animated SVG.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target mms

scene=scenarios/one-robot/bug-trap.json
build/mms validate "$scene"
build/mms plan "$scene" --seed 1 -o demo-path.json --svg demo.svg --svg-roadmap
build/mms check "$scene" demo-path.json
echo "demo: open demo.svg in a browser to watch the planned motion (green cells: the slices it uses)"
