#!/usr/bin/env bash
# Feature-line cost: bunny.pov (bench/scenes/course/) at 640x480 rendered without lines and with --edges all (default
# stencil method, and the image method), runs alternated; prints the median render time (render
# + lines phases from rays' own summary line, parse and write excluded) and the ratio.
# Target: --edges all costs at most 1.5x the plain render.
#
#   bench/edges.sh [-n RUNS] [SCENE.pov]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=7
if [ "${1:-}" = "-n" ]; then runs=$2; shift 2; fi
scene=${1:-$(bench/course_scene.sh bunny)}
[ -f "$scene" ] || { echo "missing scene $scene" >&2; exit 2; }
rays=./build/rays
[ -x "$rays" ] || { echo "build first: scripts/build.sh" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }
# render + lines milliseconds from the summary line
phase_ms() { awk '{r=0; l=0; for (i = 1; i <= NF; i++) { if ($i == "render") r = $(i+1); if ($i == "lines") l = $(i+1) } print r + l}'; }
: > "$tmp/plain"; : > "$tmp/stencil"; : > "$tmp/image"
for ((i = 0; i < runs; i++)); do
  "$rays" render "$scene" 640 480 -o "$tmp/a.png" 2>&1 | phase_ms >> "$tmp/plain"
  "$rays" render "$scene" 640 480 -o "$tmp/b.png" --edges all 2>&1 | phase_ms >> "$tmp/stencil"
  "$rays" render "$scene" 640 480 -o "$tmp/c.png" --edges all --edge-method image 2>&1 | phase_ms >> "$tmp/image"
done
p=$(median < "$tmp/plain"); s=$(median < "$tmp/stencil"); m=$(median < "$tmp/image")
printf "%s 640x480, %d runs each, medians of render(+lines) time:\n" "$(basename "$scene")" "$runs"
printf "  no lines                 %8.1f ms\n" "$p"
printf "  --edges all (stencil)    %8.1f ms   ratio %.2f (target <= 1.5)\n" "$s" "$(echo "$s / $p" | bc -l)"
printf "  --edges all (image)      %8.1f ms   ratio %.2f\n" "$m" "$(echo "$m / $p" | bc -l)"
