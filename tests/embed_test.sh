#!/usr/bin/env bash
# Installs the build into a fresh prefix, builds examples/embed against it with find_package(mms)
# (a separate CMake project, as a user's program would be), and plans scenes it has never seen:
# a one-robot and a two-robot scene generated here, each path certified by `mms check`.
#   embed_test.sh BUILD_DIR SOURCE_DIR [EXTRA_CXX_FLAGS]
set -euo pipefail
build=$1 src=$2 flags=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" >/dev/null
if grep -rIl "CGAL\|boost/graph" "$work/prefix/include/mms"; then
  echo "FAIL: the installed public headers include CGAL or the BGL" >&2
  exit 1
fi
cmake -S "$src/examples/embed" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" >/dev/null
cmake --build "$work/build" >/dev/null
embed=$work/build/embed
mms=$work/prefix/bin/mms

# Scenes the program has never seen: generated now, from seeds.
"$mms" scenario random-polygons --seed 13 -o "$work/two.json"
"$mms" scenario pacman --tightness 0.3 -o "$work/pacman.json"
cp "$src/scenes/one-robot/bar-slot.json" "$work/one.json"
for scene in one two pacman; do
  "$embed" "$work/$scene.json" "$work/$scene.path.json"
  "$mms" check "$work/$scene.json" "$work/$scene.path.json"
done

# Bad input: one line on stderr, exit 2, no output file.
echo '{"format": "mms-scene/1", "bounds": [0, 0]}' >"$work/bad.json"
set +e
"$embed" "$work/bad.json" "$work/bad.path.json" 2>"$work/err.txt"
code=$?
set -e
if [ "$code" -ne 2 ] || [ "$(wc -l <"$work/err.txt")" -ne 1 ] || [ -e "$work/bad.path.json" ]; then
  echo "FAIL: bad scene: exit $code, stderr: $(cat "$work/err.txt")" >&2
  exit 1
fi
echo "embed: 3 scenes planned and certified against the installed package; bad input refused"
