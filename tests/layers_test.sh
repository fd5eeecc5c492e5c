#!/usr/bin/env bash
# The folders of src/ read as the data flow (docs/architecture.md): a file may include from its
# own folder, from folders earlier in the flow, from util/ and from the public headers (mms/),
# never from a later folder; the public headers include nothing of src/.
#   layers_test.sh SOURCE_DIR
set -euo pipefail
src=$1/src
order=(geometry manifolds graph check path planner baselines registry io scenarios render bench assembly lab)
rank() {
  local i
  for i in "${!order[@]}"; do [ "${order[$i]}" = "$1" ] && { echo "$i"; return; }; done
  echo -1
}
bad=0
for dir in "$src"/*/; do
  from=$(basename "$dir")
  [ "$from" = util ] && continue
  r=$(rank "$from")
  if [ "$r" -lt 0 ]; then
    echo "FAIL: src/$from is not in the data flow of docs/architecture.md" >&2
    bad=1
    continue
  fi
  while IFS= read -r line; do
    file=${line%%:*}
    to=$(sed -n 's/.*#include "\([a-z]*\)\/.*/\1/p' <<<"$line")
    [ -z "$to" ] || [ "$to" = mms ] || [ "$to" = util ] && continue
    t=$(rank "$to")
    if [ "$t" -lt 0 ] || [ "$t" -gt "$r" ]; then
      echo "FAIL: ${file#"$1"/} includes $to/ (later in the flow than $from/)" >&2
      bad=1
    fi
  done < <(grep -H '#include "[a-z]*/' "$dir"*.h "$dir"*.cpp 2>/dev/null || true)
done
for f in "$1"/include/mms/*.h; do
  if grep -H '#include "' "$f" | grep -v '#include "mms/'; then
    echo "FAIL: a public header includes something other than mms/" >&2
    bad=1
  fi
done
if grep -rIl "CGAL\|boost" "$1/include/mms"; then
  echo "FAIL: the public headers name CGAL or Boost" >&2
  bad=1
fi
[ "$bad" = 0 ] && echo "layers: every include follows the data flow"
exit "$bad"
