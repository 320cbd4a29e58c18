#!/usr/bin/env bash
# The test command (README, .ci/run): installs the Debian packages, builds with -Werror, runs every test, builds
# examples/ against the installed package, then rebuilds with AddressSanitizer + UndefinedBehaviorSanitizer and
# runs the unit tests again.
# Usage: scripts/test.sh [--no-sanitizers]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)
export MPLBACKEND=Agg

cmake --preset ci > /dev/null
cmake --build --preset ci -j "$jobs"
ctest --preset ci -j "$jobs"
bash scripts/check_install.sh build/ci   # examples/ against the installed package, not the build tree

if [ "${1:-}" != "--no-sanitizers" ]; then
  cmake --preset asan > /dev/null
  cmake --build --preset asan -j "$jobs"
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --preset asan -j "$jobs" \
    -E "cli_smoke|cli_calibrate|reproduce_lloyd2007|BenchmarkCylinderUnderGravity"
fi
