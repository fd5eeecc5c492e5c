#!/usr/bin/env bash
# Installs what is missing, builds mms, and runs the demo: validate a bundled scene, certify
# its hand-made path, and draw both as an animated SVG (demo.svg).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target mms

scene=scenarios/one-robot/bar-slot.json
path=scenarios/one-robot/bar-slot.path.json
build/mms validate "$scene"
build/mms check "$scene" "$path"
build/mms render "$scene" "$path" -o demo.svg
echo "demo: open demo.svg in a browser to watch the bar turn through the slot"
