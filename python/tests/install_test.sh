#!/usr/bin/env bash
# Installs the build into a fresh prefix and plans, from a fresh python3 that sees only the
# installed package, scenes it has never seen (generated here from seeds): one robot and two
# robots; the saved paths are certified by the installed `mms check`, and a malformed scene
# raises mms.InputError.
#   install_test.sh BUILD_DIR SOURCE_DIR PYTHON
set -euo pipefail
build=$1 src=$2 python=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" >/dev/null
site=$(find "$work/prefix" -path '*/site-packages/mms/__init__.py' -printf '%h\n' | head -n 1)
site=${site%/mms}
[ -n "$site" ] || { echo "FAIL: no mms package under $work/prefix" >&2; exit 1; }
mms=$work/prefix/bin/mms

"$mms" scenario bend --seed 117 -o "$work/one.json" >/dev/null
"$mms" scenario random-polygons --seed 29 -o "$work/two.json" >/dev/null
echo '{"format": "mms-scene/1", "bounds": [0, 0]}' >"$work/bad.json"

cd "$work"
env -u MMS_EXECUTABLE PYTHONPATH="$site" "$python" - "$work" <<'PY'
import os, sys
import mms
work = sys.argv[1]
assert mms.__file__.startswith(work), mms.__file__
assert mms.executable().startswith(work), mms.executable()
# MMS alone on the one-robot scene too; the two-robot scene with the default planner only (MMS
# alone takes minutes on it under the sanitizers).
for name, planners in (("one", ("auto", "mms")), ("two", ("auto",))):
    scene = mms.load_scene(os.path.join(work, name + ".json"))
    for planner in planners:
        result = mms.plan(scene, planner, seed=1, time_limit=60)
        assert result.found, (name, result)
        result.save(os.path.join(work, f"{name}-{planner}.path.json"))
        print(name, result)
try:
    mms.load_scene(os.path.join(work, "bad.json"))
    raise SystemExit("FAIL: a malformed scene was accepted")
except mms.InputError as e:
    print("bad.json:", e)
PY
for path in one-auto one-mms two-auto; do
  "$mms" check "$work/${path%-*}.json" "$work/$path.path.json"
done
echo "python: installed package planned 2 scenes, certified by mms check; bad input raised"
