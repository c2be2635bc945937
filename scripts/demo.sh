#!/usr/bin/env bash
# Quick start 1: install what is missing, build the program (build/rays; not the test suite),
# render the demo scene to demo.png and print its path, then install rays (cmake --install build:
# /usr/local/bin/rays, the shipped scenes in /usr/local/share/rays/scenes, `man rays`) when the
# prefix is writable (as root; RAYS_PREFIX=DIR installs into DIR instead). The build uses
# scripts/test.sh's folder and flags, so that script's optimised build reuses these objects.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS=0
scripts/install-deps.sh
prefix_arg=()
[ -n "${RAYS_PREFIX:-}" ] && prefix_arg=("-DCMAKE_INSTALL_PREFIX=$RAYS_PREFIX")
scripts/build.sh --target rays -DRAYS_WERROR=ON "${prefix_arg[@]}"
./build/rays render scenes/01-demo.pov 800 600 -fresnel -beers -ss=2 -o demo.png
echo "wrote $(pwd)/demo.png ($SECONDS s after the start)"
prefix=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' build/CMakeCache.txt)
if [ -w "$prefix" ] || { [ ! -e "$prefix" ] && [ -w "$(dirname "$prefix")" ]; }; then
  cmake --install build >/dev/null
  echo "installed $prefix/bin/rays (scenes: $prefix/share/rays/scenes; man rays); try: rays scenes"
else
  echo "not installed ($prefix is not writable): use build/rays, or cmake --install build --prefix ~/.local"
fi
