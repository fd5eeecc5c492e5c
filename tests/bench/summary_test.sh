#!/usr/bin/env bash
# The generalization suite's summary (scripts/generalization-summary.py) on a results table
# written here: a scene run several times counts at its runs' median, not at its last run or
# their mean, and a failed run counts as the time limit.
set -euo pipefail
source_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
{
  echo "scene,planner,status,seconds,wall_seconds,solved_by"
  # fam-1: auto's runs 1, 2, 9 (median 2, mean 4, last 9); fam-2: 3, 3 and a failure (median 3).
  echo "fam-1,auto,found,1,1,rrtconnect"
  echo "fam-1,auto,found,2,2,rrtconnect"
  echo "fam-1,auto,found,9,9,mms"
  echo "fam-2,auto,found,3,3,mms"
  echo "fam-2,auto,found,3,3,mms"
  echo "fam-2,auto,timeout,,,"
  for scene in fam-1 fam-2; do
    for run in 1 2 3; do echo "$scene,rrtconnect,found,4,4,"; done
  done
} > "$work/results.csv"
out=$(python3 "$source_dir/scripts/generalization-summary.py" "$work/results.csv" 10)
echo "$out"
fail() { echo "FAIL: $*" >&2; exit 1; }
# Per family: the median over the scenes of each scene's median (2 and 3: 2.5), both solved.
grep -q '^| fam | 2.5 (2/2) | 4 (2/2) |$' <<< "$out" || fail "auto's family median is not 2.5 over 2 scenes"
# The best OMPL planner's median over ours: 4 / 2.5; per seed 4/2 and 4/3, median 1.67.
grep -q '^| fam | auto | rrtconnect: 4 | 1.6x | 1.67x | mms 3, rrtconnect 2 |$' <<< "$out" ||
  fail "the ratios are not those of the scenes' medians"
# The whole command's column is read when asked for.
out=$(python3 "$source_dir/scripts/generalization-summary.py" "$work/results.csv" 10 wall_seconds)
grep -q '^| fam | 2.5 (2/2) | 4 (2/2) |$' <<< "$out" || fail "wall_seconds is not read"
echo "ok"
