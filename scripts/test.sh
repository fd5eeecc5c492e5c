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
  # Line tables (-g1) are what the sanitizers' reports need; full debug information made the
  # heaviest CGAL translation unit compile 14 % slower (105 s against 90 s) and take 1 GB more
  # memory (4.2 GB). -O1, as the sanitizers' documentation advises: the build takes 10.5 min
  # instead of 7.5 and the tests 212 s instead of 453 s on 2 cores, and a sanitized run's
  # timing is closer to a release run's (races between the portfolio's members).
  flags=(-DCMAKE_BUILD_TYPE=Debug -DMMS_SANITIZE=ON -DMMS_BUILD_BENCH=OFF "-DCMAKE_CXX_FLAGS_DEBUG=-g1 -O1")
fi

bash scripts/setup.sh
cmake -S . -B "$dir" "${flags[@]}" >/dev/null
cmake --build "$dir" -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp"
ctest --test-dir "$dir" --output-on-failure -j"$(nproc)"
