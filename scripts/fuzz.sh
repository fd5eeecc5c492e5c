#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) in build-fuzz/ and fuzzes each of them,
# as many at once as there are cores.
#   scripts/fuzz.sh                 60 s per target (the CI smoke run)
#   scripts/fuzz.sh --seconds S     S seconds per target
#   scripts/fuzz.sh --runs N        N executions per target (e.g. 10000000 before a release)
# The seed corpus is fuzz/corpus/<target>; what the fuzzer finds new goes to
# build-fuzz/corpus/<target>, crashing inputs to build-fuzz/crashes/. Exit 1 on any crash.
set -euo pipefail
cd "$(dirname "$0")/.."

limit=(-max_total_time=60)
case "${1:-}" in
  --seconds) limit=(-max_total_time="$2") ;;
  --runs) limit=(-runs="$2") ;;
  "") ;;
  *) echo "usage: scripts/fuzz.sh [--seconds S | --runs N]" >&2; exit 2 ;;
esac

bash scripts/setup.sh
# -O1 keeps assertions (no NDEBUG) while staying fast enough for millions of runs.
cmake -S . -B build-fuzz -DMMS_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_CXX_FLAGS="-O1" -DMMS_BUILD_TESTS=OFF -DMMS_BUILD_BENCH=OFF -DMMS_BUILD_PYTHON=OFF >/dev/null
targets="FuzzScene:scene FuzzPath:path FuzzDiscopygal:discopygal FuzzOmplCfg:cfg FuzzCollada:collada FuzzQueries:queries FuzzRecord:record FuzzPlan:plan"
cmake --build build-fuzz -j"$(nproc)" --target FuzzScene FuzzPath FuzzDiscopygal FuzzOmplCfg FuzzCollada FuzzQueries FuzzRecord FuzzPlan

export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# OMPL's own leaks (LazyPRM's cloned states), suppressed as in the tests: the planning target
# reaches them.
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp"
mkdir -p build-fuzz/crashes
# One target: its summary line on stdout, or the failure and the log's tail on stderr.
fuzz_one() {
  local target=${1%%:*} corpus=${1##*:}
  # JSON readers get the JSON dictionary; the INI and XML readers find their tokens alone.
  local dict=()
  case $corpus in scene | path | discopygal | queries | record) dict=(-dict=fuzz/json.dict) ;; esac
  mkdir -p "build-fuzz/corpus/$corpus"
  local log="build-fuzz/$target.log"
  if ! "build-fuzz/$target" "${limit[@]}" -max_len=8192 -timeout=10 -rss_limit_mb=4096 \
      "${dict[@]}" -artifact_prefix="build-fuzz/crashes/$target-" -print_final_stats=1 \
      "build-fuzz/corpus/$corpus" "fuzz/corpus/$corpus" >"$log" 2>&1; then
    echo "fuzz: $target FAILED; input in build-fuzz/crashes/, log $log:" >&2
    tail -n 40 "$log" >&2
    return 1
  fi
  local runs secs
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  secs=$(sed -n 's/^stat::.*//; s/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -n 1)
  echo "fuzz: $target: ${runs:-?} executions in ${secs:-?} s, no crash (corpus $(ls "build-fuzz/corpus/$corpus" | wc -l) inputs)"
}
# As many targets at once as there are cores: each fuzzer is one process on one core.
status=0
pids=()
for pair in $targets; do
  while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do sleep 1; done
  fuzz_one "$pair" >"build-fuzz/${pair%%:*}.out" 2>&1 &
  pids+=("$!")
done
i=0
for pair in $targets; do
  if wait "${pids[$i]}"; then
    cat "build-fuzz/${pair%%:*}.out"
  else
    status=1
    cat "build-fuzz/${pair%%:*}.out" >&2
  fi
  i=$((i + 1))
done
exit $status
