#!/usr/bin/env bash
# Quick start 2: install what is missing, build warning-free, run the whole test suite with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh -DRAYS_WERROR=ON
cd build
ctest --output-on-failure -j"$(nproc)"
