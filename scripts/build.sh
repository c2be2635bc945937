#!/usr/bin/env bash
# Configures and builds Rays (Release) into build/.
#   scripts/build.sh [--target T] [CMAKE_CONFIGURE_ARGS...]
# --target builds only T (e.g. rays, as scripts/demo.sh does); other arguments go to CMake's
# configure step. scripts/demo.sh and scripts/test.sh configure with the same flags, so the
# second reuses what the first compiled.
set -euo pipefail
cd "$(dirname "$0")/.."
target=()
if [ "${1:-}" = "--target" ]; then
  target=(--target "$2")
  shift 2
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j"$(nproc)" "${target[@]}"
