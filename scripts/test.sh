#!/usr/bin/env bash
# Quick start 2 and CI (.ci/run calls exactly this): install what is missing, then
#   1. the sanitizer stages (scripts/sanitize.sh): an ASan + UBSan build running the whole test
#      suite, and a TSan build running the multithreaded tests (about 13 minutes on 2 cores, cold);
#   2. the warning-free optimised build (reusing what scripts/demo.sh compiled: same flags) and
#      the whole test suite with CTest, then each skipped test with the reason it gave.
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
status=0
ctest --output-on-failure -j"$(nproc)" --output-junit ctest-results.xml || status=$?
# Every skipped test with GoogleTest's reason (the line after "FILE:LINE: Skipped"), which CTest's
# own list of tests that did not run leaves out.
awk '/<testcase /{ n = $0; sub(/^[^"]*name="/, "", n); sub(/".*/, "", n); skip = ($0 ~ /status="notrun"/) }
     skip && prev ~ /: Skipped$/ { r = $0; gsub(/&quot;/, "\"", r); gsub(/&lt;/, "<", r); gsub(/&gt;/, ">", r);
                                   gsub(/&amp;/, "\\&", r); print "skipped: " n ": " r }
     { prev = $0 }' ctest-results.xml 2>/dev/null || true
exit $status
