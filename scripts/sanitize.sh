#!/usr/bin/env bash
# Sanitizer builds for CI (scripts/test.sh runs them before the optimised build and suite):
#   1. build-asan: the whole project with g++ -fsanitize=address,undefined (UBSan aborts on the first
#      error: -fno-sanitize-recover=all), -O1, and the whole GoogleTest suite in shards (below),
#      including the CLI tests, which run the instrumented `rays` binary.
#   2. build-tsan: the project with -fsanitize=thread and the tests that render or filter with
#      several threads (TSAN_TESTS below).
# Usage: scripts/sanitize.sh [asan|tsan]... (default: both). Exit status non-zero on the first failure.
# On 2 cores on 2026-12-07, built cold without ccache from a fresh clone (.ci/run): the ASan stage 428 s
# (build, and the suite in shards: 150 s measured alone; as one CTest process per test it was
# 526 s), the TSan stage 161 s, 60 s of it the 65 tests. The test files compile as unity batches
# (tests/CMakeLists.txt; their build times: docs/performance.md "Build time").
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh

jobs=$(nproc)
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(asan tsan)

# Tests with several worker threads: renders (tiles), feature lines, edge-guided AA, filters,
# the parallel BVH build and collapse, the two-piece parse, the worker pool,
# thread-count determinism, Ctrl-C handling and two threads on one function table.
TSAN_FILES='distribution_test.cpp;parse_pieces_test.cpp;edges_test.cpp;worker_pool_test.cpp;wide_collapse_test.cpp;golden_test.cpp;cli_test.cpp;cli_edges_test.cpp;filter_test.cpp;triangle_bvh_test.cpp;determinism_test.cpp;interrupt_test.cpp;fn_machine_test.cpp'
TSAN_TESTS='^(Distribution\.|ParsePieces\.|Edges/EdgeMethods\.|StencilTaps\.|StencilPass\.|WorkerPool\.|WideCollapse\.TwoThread|Scenes/Golden\.|CliOptions\.ThreadCount|CliEdges\.|FilterPaths\.ResultsDoNotDependOnTheThreadCount|FilterParallel\.|TriangleBvh\.OneAndTwoThreadBuilds|Determinism|Interrupt|FnMachine\.ThreadsShareOneTable)'

# The code under test at -O1 with line tables only (-g1: reports keep their file:line; full -g
# made the build a quarter slower); the test files themselves at -O0 (their compile time halves, their
# run time hardly moves: the work is in the code they call). The ASan executables are linked
# without PIE: an instrumented PIE test binary carries 1.8 million relocations, and with 1,232 test
# processes their start-up (0.58 s each, 0.31 s without PIE) was a quarter of the ASan suite.
configure() {  # DIR FLAGS [LINK-FLAGS]
  cmake -S . -B "$1" -DCMAKE_BUILD_TYPE=Sanitize -DRAYS_NATIVE=OFF -DRAYS_WERROR=OFF -DRAYS_STATIC_RUNTIME=OFF -DRAYS_MPI=OFF \
    -DCMAKE_CXX_FLAGS="$2 -O1 -g1 -fno-omit-frame-pointer" -DRAYS_TEST_COMPILE_OPTIONS=-O0 \
    -DCMAKE_EXE_LINKER_FLAGS="$2 ${3:-}" >/dev/null
}

# The ASan suite runs the test binary as GoogleTest shards, $jobs at a time, rather than one process
# per test as CTest does: an instrumented process takes 0.3 s to start, which over 1,237 tests was a
# third of the suite's time. Four shards per core even out their lengths. Every test still runs
# (the optimised suite in scripts/test.sh runs each in its own process); a failed shard prints its
# log. MPI's CTest entries are not built here.
run_shards() {
  local shards=$((4 * jobs)) i status=0
  rm -f shard-*.log shard-*.rc
  seq 0 $((shards - 1)) | xargs -P "$jobs" -I{} bash -c 'cd tests && GTEST_TOTAL_SHARDS=$0 GTEST_SHARD_INDEX={} \
    timeout 3600 ./rays_tests --gtest_brief=1 >../shard-{}.log 2>&1; echo $? >../shard-{}.rc' "$shards"
  for ((i = 0; i < shards; i++)); do
    if [ "$(cat "shard-$i.rc")" = 0 ]; then
      grep -h '^\[  PASSED  \]' "shard-$i.log" >&2
    else
      status=1
      echo "== shard $((i + 1)) of $shards failed (exit status $(cat "shard-$i.rc")): shard-$i.log" >&2
      cat "shard-$i.log" >&2
    fi
  done
  return $status
}

elapsed() { echo "$(( $(date +%s) - $1 )) s"; }

for stage in "${stages[@]}"; do
  start=$(date +%s)
  case "$stage" in
    asan)
      echo "== ASan+UBSan: building build-asan" >&2
      configure build-asan "-fsanitize=address,undefined -fno-sanitize-recover=all" -no-pie
      cmake --build build-asan -j"$jobs"
      echo "== ASan+UBSan: whole test suite" >&2
      # (No strict_string_checks: with it ASan's strcspn checks the whole rest of the string at
      # every call, and tinyobjloader reading a face of 100,000 corners took 38 s instead of 2 s,
      # against the bad-input test's 60 s limit.)
      (cd build-asan &&
        ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=0 \
        UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        run_shards)
      ;;
    tsan)
      echo "== TSan: building build-tsan" >&2
      configure build-tsan "-fsanitize=thread"
      cmake build-tsan -DRAYS_TEST_FILES="$TSAN_FILES" >/dev/null  # only the files holding TSAN_TESTS
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
