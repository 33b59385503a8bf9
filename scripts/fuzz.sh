#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and UndefinedBehaviorSanitizer and runs
# each for a bounded time on a copy of its corpus (fuzz/corpus/TARGET). Crashing inputs are kept
# in build-fuzz/crashes/TARGET. Usage: bash scripts/fuzz.sh [SECONDS_PER_TARGET (60) | 0 | ci [TARGET...]]
# (targets: point_file mesh_file image database database_update segmentation python_arguments;
# default all).
# 0 replays the kept corpus once, without mutating it.
# ci (what CI runs) replays the kept corpus, then mutates it for a fixed number of executions per
# target (a few seconds each) from a fixed seed: a short fuzz run whose inputs are the same on
# every run of the same code, so CI is red only where the code is, never by luck.
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
# run_target TARGET CORPUS CRASHES LOG LIBFUZZER_OPTION...
run_target() {
  local target=$1 corpus=$2 crashes=$3 log=$4
  shift 4
  ASAN_OPTIONS=detect_leaks=0 "$build/fuzz/fuzz_$target" "$corpus" "$@" -timeout=20 -rss_limit_mb=4096 \
    -artifact_prefix="$crashes/" -print_final_stats=1 >"$log" 2>&1
}
# Mutations of the ci mode's run beyond loading the corpus (libFuzzer's -runs counts both): about
# five seconds of each target on this machine.
ci_runs() {
  case $1 in
    segmentation) echo 300 ;;
    python_arguments) echo 200000 ;;
    *) echo 8000 ;;
  esac
}
status=0 passed=0 failed=0
printf '| target | seconds | executions | crashes |\n|---|---|---|---|\n'
for target in $targets; do
  corpus="$build/corpus/$target"
  crashes="$build/crashes/$target"
  mkdir -p "$corpus" "$crashes"
  cp -n fuzz/corpus/$target/* "$corpus/" 2>/dev/null
  log="$build/$target.log"
  if [ "$seconds" = ci ]; then
    # The replay first, then the fixed mutation run on a fresh copy of the kept corpus.
    run_target "$target" fuzz/corpus/$target "$crashes" "$log.replay" -runs=0
    rc=$?
    fresh="$build/corpus-ci/$target" # not the long runs' corpus: the ci run starts from the kept one
    rm -rf "$fresh" && mkdir -p "$fresh" && cp fuzz/corpus/$target/* "$fresh/" 2>/dev/null
    runs=$(( $(ls "$fresh" | wc -l) + $(ci_runs "$target") ))
    [ "$rc" -eq 0 ] && { run_target "$target" "$fresh" "$crashes" "$log" -seed=1 -runs="$runs"; rc=$?; }
  elif [ "$seconds" -eq 0 ]; then
    run_target "$target" fuzz/corpus/$target "$crashes" "$log" -runs=0; rc=$?
  else
    run_target "$target" "$corpus" "$crashes" "$log" -max_total_time="$seconds"; rc=$?
  fi
  runs=$(grep -m1 'stat::number_of_executed_units' "$log" 2>/dev/null | awk '{print $2}')
  found=$(ls "$crashes" | wc -l)
  printf '| %s | %s | %s | %s |\n' "$target" "$seconds" "${runs:-?}" "$found"
  if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then
    status=1; failed=$((failed + 1)); tail -30 "$log.replay" "$log" 2>/dev/null
  else passed=$((passed + 1)); fi
done
echo "fuzz: $passed passed, $failed failed"
exit $status
