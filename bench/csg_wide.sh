#!/usr/bin/env bash
# Wide CSG: a union of N spheres subtracted from a box against the same N spheres as a plain
# union (which Rays flattens into objects of its scene BVH, the anchor), rendered by Rays in
# alternated runs in one session; the ratio is what the CSG costs over the plain objects (issue
# 24: "a union of 10,000 spheres inside a difference stays near the cost of the plain objects").
# With povray installed, POV-Ray's trace time of the CSG scene is printed too.
#
#   bench/csg_wide.sh [-n RUNS] [-c SPHERES] [-s WxH]
#
# Defaults: 5 runs, 20,000 spheres, 320x240, no anti-aliasing, both renderers on all cores.
# The scenes are generated into a temporary folder (bench/ ships no copy).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=5
count=20000
size=320x240
while getopts "n:c:s:" opt; do
  case $opt in
    n) runs=$OPTARG ;;
    c) count=$OPTARG ;;
    s) size=$OPTARG ;;
    *) echo "usage: $0 [-n RUNS] [-c SPHERES] [-s WxH]" >&2; exit 2 ;;
  esac
done
w=${size%x*}
h=${size#*x}
rays=${RAYS:-$(pwd)/build/rays}
[ -x "$rays" ] || { echo "build first: scripts/build.sh" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene() {  # name, the CSG's opening, the CSG's first child
  cat > "$work/$1.pov" <<POV
#version 3.7;
#declare R = seed(3);
$2
  $3
  union {
    #for (I, 1, $count) sphere { <rand(R), rand(R), rand(R)> * 20 - 10, 0.3 } #end
  }
  pigment { rgb 1 }
}
camera { location <0, 0, -40> look_at 0 }
light_source { <10, 20, -30> rgb 1 }
POV
}
scene plain "union {" ""
scene csg "difference {" "box { -12, 12 }"
render_ms() {  # scene → Rays' render phase in ms
  "$rays" render "$work/$1.pov" "$w" "$h" -o "$work/$1.png" 2>&1 | sed -n 's/.*, render \([0-9.]*\) ms,.*/\1/p' | tail -n 1
}
median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2]+a[NR/2+1])/2}'; }
plain=(); csg=()
for ((i = 0; i < runs; ++i)); do
  plain+=("$(render_ms plain)")
  csg+=("$(render_ms csg)")
done
p=$(printf '%s\n' "${plain[@]}" | median)
c=$(printf '%s\n' "${csg[@]}" | median)
printf '%d spheres at %dx%d, medians of %d alternated runs (Rays render phase)\n' "$count" "$w" "$h" "$runs"
printf '  plain union (anchor)      %10.1f ms\n' "$p"
printf '  difference { box union }  %10.1f ms   ratio %.2fx the plain objects\n' "$c" "$(awk -v a="$c" -v b="$p" 'BEGIN {print a / b}')"
if command -v povray >/dev/null; then
  t=$(cd "$work" && povray +Icsg.pov +Opov.png "+W$w" "+H$h" -D -A 2>&1 | tr '\r' '\n' |
      sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' | head -n 1)
  printf '  POV-Ray 3.7, the difference: trace %s s (one run)\n' "$t"
fi
