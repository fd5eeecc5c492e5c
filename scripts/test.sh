#!/usr/bin/env bash
# Installs what is missing, builds mms and its tests, and runs them with ctest.
#   scripts/test.sh              Release build in build/
#   scripts/test.sh --sanitize   Debug build with AddressSanitizer + UBSan in build-asan/
set -euo pipefail
cd "$(dirname "$0")/.."

dir=build
flags=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = "--sanitize" ]; then
  dir=build-asan
  flags=(-DCMAKE_BUILD_TYPE=Debug -DMMS_SANITIZE=ON -DMMS_BUILD_BENCH=OFF)
fi

bash scripts/setup.sh
cmake -S . -B "$dir" "${flags[@]}" >/dev/null
cmake --build "$dir" -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp"
ctest --test-dir "$dir" --output-on-failure -j"$(nproc)"
