#!/usr/bin/env bash
# Measures how far `mms plan` overruns --time-limit on scenes whose single manifolds are heavy
# (random scenes with 1000, 2000 and 3000 obstacles, one and two robots) and on unsolvable
# bundled scenes (which always run to the limit), and on five discs whose motions slide along
# contacts (the certifier's pieces get as short as the contact tolerance; with --restarts, runs
# after the first path), whatever phase the limit strikes in (slices, lines, search, the motion
# along the graph path, certification, path optimisation, restarts, writing). Prints one line
# per run and the worst overrun of the whole command (loading, planning, optimising, writing)
# past the limit, against the target: 2 % of the limit or 50 ms, whichever is more.
# Usage: scripts/time-limits.sh [LIMIT ...]   (default: 1 3 6)
set -euo pipefail
cd "$(dirname "$0")/.."
limits=("$@")
[ ${#limits[@]} -gt 0 ] || limits=(1 3 6)
mms=build/mms
[ -x "$mms" ] || { echo "build first: bash scripts/test.sh" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
scenes=(scenes/one-robot/sealed-ring.json)
options=("")  # extra `mms plan` options, one entry per scene
for spec in 1:1000:1 2:3000:1 4:2000:1 3:1000:2 4:3000:2; do
  IFS=: read -r seed n robots <<<"$spec"
  f="$dir/random-$seed-$n-$robots.json"
  "$mms" scenario random --seed "$seed" --obstacles "$n" --robots "$robots" -o "$f" >/dev/null
  scenes+=("$f")
  options+=("")
done
"$mms" scenario discs-swap --seed 100 -o "$dir/discs-swap-100.json" >/dev/null
scenes+=("$dir/discs-swap-100.json" "$dir/discs-swap-100.json")
options+=("--planner mms --seed 5571691718763357052" "--planner mms --restarts 50")
worst=0 worstWall=0 worstOver=0 beyond=0
for limit in "${limits[@]}"; do
  for i in "${!scenes[@]}"; do
    scene=${scenes[$i]}
    read -r -a extra <<<"${options[$i]}"
    start=$(date +%s.%N)
    "$mms" plan "$scene" --time-limit "$limit" -o "$dir/p.json" --stats-json "$dir/s.json" -q \
      "${extra[@]}" >/dev/null || true
    end=$(date +%s.%N)
    read -r status seconds < <(python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d['status'], d['seconds'])" "$dir/s.json")
    wall=$(python3 -c "print($end - $start)")
    # A found run counts too: the motion and the optimisation must end by the limit as well.
    over=$(python3 -c "print(max(0.0, $wall - $limit))")
    allowed=$(python3 -c "print(max(0.05, 0.02 * $limit))")
    flag=$(python3 -c "print('  OVER' if $over > $allowed else '')")
    [ -n "$flag" ] && beyond=$((beyond + 1))
    printf '%-28s %-40s limit %5s s: %-9s planner %7.3f s, command %7.3f s%s\n' "$(basename "$scene")" "${options[$i]}" "$limit" "$status" "$seconds" "$wall" "$flag"
    worstOver=$(python3 -c "print(max($worstOver, $over))")
    [ "$status" = found ] && continue  # ended early: its planner time says nothing of the limit
    worst=$(python3 -c "print(max($worst, $seconds / $limit))")
    worstWall=$(python3 -c "print(max($worstWall, $wall / $limit))")
  done
done
printf 'worst overrun: planner %.1f %%, whole command %.1f %% of the limit (runs to the limit); worst past the limit %.3f s; %d run(s) beyond 2 %% or 50 ms\n' \
  "$(python3 -c "print(100 * ($worst - 1))")" "$(python3 -c "print(100 * ($worstWall - 1))")" "$worstOver" "$beyond"
