#!/usr/bin/env bash
# Prints the path of a course benchmark scene (bench/scenes/course/NAME.pov.gz), decompressed into
# bench/out/scenes/ the first time (and again when the .gz is newer).
#   bench/course_scene.sh bunny     ->  /path/to/bench/out/scenes/bunny.pov
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: bench/course_scene.sh NAME   (bunny, gnarly, balls2 or cornell)" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
gz=$here/scenes/course/$1.pov.gz
[ -f "$gz" ] || { echo "bench/course_scene.sh: no scene $gz" >&2; exit 2; }
out=$here/out/scenes/$1.pov
mkdir -p "$here/out/scenes"
if [ ! -f "$out" ] || [ "$gz" -nt "$out" ]; then
  gzip -dc "$gz" > "$out.tmp" && mv "$out.tmp" "$out"
fi
echo "$out"
