#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and UndefinedBehaviorSanitizer and runs
# each for a bounded time on a copy of its corpus (fuzz/corpus/TARGET). Crashing inputs are kept
# in build-fuzz/crashes/TARGET. Usage: bash scripts/fuzz.sh [SECONDS_PER_TARGET (60) [TARGET...]]
# (targets: point_file mesh_file image database database_update segmentation python_arguments;
# default all).
# SECONDS 0 replays the kept corpus once, without mutating it: what CI runs, so that the targets
# keep building and what the corpus reaches stays fixed without making CI depend on luck.
# Installs clang with apt-get when it is missing.
set -uo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift $(( $# > 0 ? 1 : 0 ))
targets=${*:-point_file mesh_file image database database_update segmentation python_arguments}
build=${FUZZ_BUILD:-build-fuzz}
if ! command -v clang++ >/dev/null 2>&1; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends clang >/dev/null \
    || { echo "fuzz: clang is needed (apt-get install clang)"; exit 1; }
fi
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPCL_FLOWSEG_FUZZ=ON \
  -DPCL_FLOWSEG_BUILD_TESTS=OFF -DPCL_FLOWSEG_BUILD_APPS=OFF -DPCL_FLOWSEG_BUILD_BENCHMARKS=OFF >/dev/null || exit 1
cmake --build "$build" -j 2 >/dev/null || { echo "fuzz: build failed"; exit 1; }
status=0 passed=0 failed=0
printf '| target | seconds | executions | crashes |\n|---|---|---|---|\n'
for target in $targets; do
  corpus="$build/corpus/$target"
  crashes="$build/crashes/$target"
  mkdir -p "$corpus" "$crashes"
  cp -n fuzz/corpus/$target/* "$corpus/" 2>/dev/null
  log="$build/$target.log"
  if [ "$seconds" -eq 0 ]; then corpus=fuzz/corpus/$target limit=(-runs=0); else limit=(-max_total_time="$seconds"); fi
  ASAN_OPTIONS=detect_leaks=0 "$build/fuzz/fuzz_$target" "$corpus" "${limit[@]}" -timeout=20 -rss_limit_mb=4096 \
    -artifact_prefix="$crashes/" -print_final_stats=1 >"$log" 2>&1
  rc=$?
  runs=$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')
  found=$(ls "$crashes" | wc -l)
  printf '| %s | %s | %s | %s |\n' "$target" "$seconds" "${runs:-?}" "$found"
  if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then status=1; failed=$((failed + 1)); tail -30 "$log"; else passed=$((passed + 1)); fi
done
echo "fuzz: $passed passed, $failed failed"
exit $status
