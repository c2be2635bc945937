#!/usr/bin/env bash
# Sanitizer builds for CI (scripts/test.sh runs them before the optimised build and suite):
#   1. build-asan: the whole project with g++ -fsanitize=address,undefined (UBSan aborts on the first
#      error: -fno-sanitize-recover=all), -O1, and the whole CTest suite, including the CLI tests,
#      which run the instrumented `rays` binary.
#   2. build-tsan: the project with -fsanitize=thread and the tests that render or filter with
#      several threads (TSAN_TESTS below).
# Usage: scripts/sanitize.sh [asan|tsan]... (default: both). Exit status non-zero on the first failure.
# Both together took 14 minutes on 2 cores on 2026-11-25 (ASan build + whole suite 603 s, TSan 242 s,
# with other work on the machine).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh

jobs=$(nproc)
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(asan tsan)

# Tests with several worker threads: renders (tiles), feature lines, edge-guided AA, filters,
# the parallel BVH build and collapse, the two-piece parse, the worker pool,
# thread-count determinism, Ctrl-C handling and two threads on one function table.
TSAN_TESTS='^(Distribution\.|ParsePieces\.|Edges/EdgeMethods\.|StencilTaps\.|StencilPass\.|WorkerPool\.|WideCollapse\.TwoThread|Scenes/Golden\.|CliOptions\.ThreadCount|CliEdges\.|FilterPaths\.ResultsDoNotDependOnTheThreadCount|FilterParallel\.|TriangleBvh\.OneAndTwoThreadBuilds|Determinism|Interrupt|FnMachine\.ThreadsShareOneTable)'

configure() {  # DIR FLAGS
  cmake -S . -B "$1" -DCMAKE_BUILD_TYPE=Sanitize -DRAYS_NATIVE=OFF -DRAYS_WERROR=OFF -DRAYS_STATIC_RUNTIME=OFF -DRAYS_MPI=OFF \
    -DCMAKE_CXX_FLAGS="$2 -O1 -g -fno-omit-frame-pointer" \
    -DCMAKE_EXE_LINKER_FLAGS="$2" >/dev/null
}

elapsed() { echo "$(( $(date +%s) - $1 )) s"; }

for stage in "${stages[@]}"; do
  start=$(date +%s)
  case "$stage" in
    asan)
      echo "== ASan+UBSan: building build-asan" >&2
      configure build-asan "-fsanitize=address,undefined -fno-sanitize-recover=all"
      cmake --build build-asan -j"$jobs"
      echo "== ASan+UBSan: whole test suite" >&2
      (cd build-asan &&
        ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=0 \
        UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        ctest --output-on-failure -j"$jobs" --timeout 900)
      ;;
    tsan)
      echo "== TSan: building build-tsan" >&2
      configure build-tsan "-fsanitize=thread"
      cmake --build build-tsan -j"$jobs"
      echo "== TSan: multithreaded render tests" >&2
      (cd build-tsan &&
        TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
        ctest --output-on-failure -j"$jobs" --timeout 900 -R "$TSAN_TESTS")
      ;;
    *)
      echo "unknown stage '$stage' (asan or tsan)" >&2
      exit 2
      ;;
  esac
  echo "== $stage passed in $(elapsed "$start")" >&2
done
