#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and UndefinedBehaviorSanitizer and runs
# each for a bounded time on a copy of its corpus (fuzz/corpus/TARGET). Crashing inputs are kept
# in build-fuzz/crashes/TARGET. Usage: bash scripts/fuzz.sh [SECONDS_PER_TARGET (60)]
set -uo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
build=build-fuzz
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPCL_FLOWSEG_FUZZ=ON \
  -DPCL_FLOWSEG_BUILD_TESTS=OFF -DPCL_FLOWSEG_BUILD_APPS=OFF -DPCL_FLOWSEG_BUILD_BENCHMARKS=OFF >/dev/null || exit 1
cmake --build "$build" -j 2 >/dev/null || { echo "fuzz: build failed"; exit 1; }
status=0
printf '| target | seconds | executions | crashes |\n|---|---|---|---|\n'
for target in point_file mesh_file image database segmentation; do
  corpus="$build/corpus/$target"
  crashes="$build/crashes/$target"
  mkdir -p "$corpus" "$crashes"
  cp -n fuzz/corpus/$target/* "$corpus/" 2>/dev/null
  log="$build/$target.log"
  ASAN_OPTIONS=detect_leaks=0 "$build/fuzz/fuzz_$target" "$corpus" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 \
    -artifact_prefix="$crashes/" -print_final_stats=1 >"$log" 2>&1
  rc=$?
  runs=$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')
  found=$(ls "$crashes" | wc -l)
  printf '| %s | %s | %s | %s |\n' "$target" "$seconds" "${runs:-?}" "$found"
  if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then status=1; tail -30 "$log"; fi
done
exit $status
