#!/usr/bin/env bash
# Installs what is missing, builds mms, and runs the demo: plan the paper's Pacman scenario (a
# C-shaped robot must swallow a square, turn around it and release it so the two can swap ends
# of a corridor), certify the motion, and draw it as an animated SVG (demo.svg) and an HTML
# player (demo.html).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target mms

scene=scenes/two-robots/pacman-0.5.json
build/mms validate "$scene"
build/mms plan "$scene" --planner mms --seed 1 -o demo-path.json --svg demo.svg \
  --record demo-record.json
build/mms check "$scene" demo-path.json
build/mms view "$scene" demo-path.json --record demo-record.json -o demo.html
echo "demo: open demo.html (player: play/pause, slider, speed; below it, a second slider steps through what MMS built) or demo.svg in a browser to watch the Pacman swallow the square and the two swap places"
