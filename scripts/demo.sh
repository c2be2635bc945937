#!/usr/bin/env bash
# Quick start 1: install what is missing, build, render the demo scene to demo.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
./build/rays render scenes/01-demo.pov 800 600 -fresnel -beers -ss=2 -o demo.png
echo "wrote $(pwd)/demo.png"
