#!/usr/bin/env bash
# Quick start 2 and CI (.ci/run calls exactly this): install what is missing, then
#   1. the sanitizer stages (scripts/sanitize.sh): an ASan + UBSan build running the whole test
#      suite, and a TSan build running the multithreaded tests (about 14 minutes on 2 cores);
#   2. the warning-free optimised build and the whole test suite with CTest (its summary is the
#      last line of the output).
#   scripts/test.sh --quick    step 2 only (a few minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
for arg in "$@"; do
  case "$arg" in
    --quick) quick=1 ;;
    *) echo "usage: scripts/test.sh [--quick]" >&2; exit 2 ;;
  esac
done
RAYS_TEST_DEPS=1 scripts/install-deps.sh
[ $quick -eq 1 ] || scripts/sanitize.sh asan tsan
scripts/build.sh -DRAYS_WERROR=ON
cd build
ctest --output-on-failure -j"$(nproc)"
