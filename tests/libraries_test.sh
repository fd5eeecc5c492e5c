#!/usr/bin/env bash
# The libraries link in the data flow's order (docs/architecture.md): no library calls a
# function that only a library later in the order defines, whichever header declared it (a
# call through a public header, such as the registry's findPlanner, counts as much as an include).
#   libraries_test.sh BUILD_DIR
set -euo pipefail
lib=$1/src
order=(mmsscene mmscore mmsbaselines mmsplanners mmsbench mmslab)
bad=0
for ((i = 0; i < ${#order[@]}; ++i)); do
  later=()
  for ((j = i + 1; j < ${#order[@]}; ++j)); do later+=("$lib/lib${order[$j]}.a"); done
  [ ${#later[@]} -eq 0 ] && continue
  defined=$(nm -C --defined-only "${later[@]}" 2>/dev/null | awk '$2 ~ /^[TW]$/ {$1 = ""; $2 = ""; sub(/^  /, ""); print}' | sort -u)
  mine=$(nm -C --defined-only "$lib/lib${order[$i]}.a" 2>/dev/null | awk '$2 ~ /^[TW]$/ {$1 = ""; $2 = ""; sub(/^  /, ""); print}' | sort -u)
  needed=$(nm -C -u "$lib/lib${order[$i]}.a" 2>/dev/null | awk '$1 == "U" {$1 = ""; sub(/^ /, ""); print}' | sort -u)
  # What this library needs, defines nowhere itself, and only a later one defines.
  cycle=$(comm -12 <(comm -23 <(echo "$needed") <(echo "$mine")) <(echo "$defined"))
  if [ -n "$cycle" ]; then
    echo "FAIL: lib${order[$i]}.a calls into a later library:" >&2
    echo "$cycle" | head -5 >&2
    bad=1
  fi
done
[ "$bad" = 0 ] && echo "libraries: each calls only into itself and the libraries before it"
exit "$bad"
