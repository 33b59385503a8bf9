#!/usr/bin/env bash
# Builds the project with AddressSanitizer and UndefinedBehaviorSanitizer (gcc) in build-asan and
# runs the whole test suite there. Leak checking is off: PCL and VTK keep global allocations alive.
# Usage: bash scripts/sanitize.sh
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-asan
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPCL_FLOWSEG_SANITIZE=ON -DPCL_FLOWSEG_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build" -j 2
export ASAN_OPTIONS=detect_leaks=0:detect_odr_violation=0:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$build" && ctest --output-on-failure -j 2
