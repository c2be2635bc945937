#!/usr/bin/env bash
# Whole-render benchmark: Rays against POV-Ray 3.7 on the same scenes, runs alternated in one
# session (the machines are shared and noisy), medians and the ratio printed.
#
#   bench/render.sh [-n RUNS] [-s WxH] [-g] [SCENE.pov ...]
#
# Defaults: 5 runs, 640x480, and the course scenes bunny, gnarly and balls2 (bench/scenes/course/), then
# a global-illumination row (-g: that row alone; it is left out when scenes are named): Rays
# renders the course's cornell.pov with -gi (64 + 16 samples, 2 levels), POV-Ray its own
# radiosity/cornell.pov (radiosity count 200, recursion_limit 3) from the examples folder, as
# the anchor for the same kind of work: different scenes and methods, so the ratio is a scale
# to follow over time, not a like-for-like race.
# Both renderers use all cores and one sample per pixel (POV-Ray: -A, no anti-aliasing).
# Needs the `povray` package (RAYS_BENCH_DEPS=1 scripts/install-deps.sh) and a built ./build/rays.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=5
size=640x480
gi_only=0
while getopts "n:s:g" opt; do
  case $opt in
    n) runs=$OPTARG ;;
    s) size=$OPTARG ;;
    g) gi_only=1 ;;
    *) echo "usage: $0 [-n RUNS] [-s WxH] [-g] [SCENE.pov ...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
w=${size%x*}
h=${size#*x}
scenes=("$@")
gi_row=0
if [ ${#scenes[@]} -eq 0 ]; then
  gi_row=1
  [ "$gi_only" = 1 ] || for s in bunny gnarly balls2; do scenes+=("$(bench/course_scene.sh "$s")"); done
fi
povex=/usr/share/doc/povray/examples
povinc=/usr/share/povray-3.7/include
rays=$(pwd)/build/rays
[ -x "$rays" ] || { echo "build first: scripts/build.sh" >&2; exit 2; }
command -v povray >/dev/null || { echo "povray is not installed (RAYS_BENCH_DEPS=1 scripts/install-deps.sh)" >&2; exit 2; }
threads=$(nproc)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Bash's own clock: $(date) would fork and exec a process inside every timed interval (~10 ms on
# these machines, a bias of 5-15 % against a 0.1 s render).
[ -n "${EPOCHREALTIME:-}" ] || { echo "needs bash 5 (EPOCHREALTIME)" >&2; exit 2; }
median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }

printf "%-14s %10s %10s %8s   (%s, %d runs each, %d threads, medians of wall time)\n" \
  scene "Rays s" "POV-Ray s" ratio "$size" "$runs" "$threads"
# One row: NAME, Rays' scene, POV-Ray's scene, then Rays' extra flags; runs alternated.
row() {
  local name=$1 rscene=$2 pscene=$3
  shift 3
  : > "$tmp/rays.t"
  : > "$tmp/pov.t"
  for ((i = 0; i < runs; i++)); do
    t0=$EPOCHREALTIME
    "$rays" render "$rscene" "$w" "$h" "$@" -o "$tmp/$name-rays.png" --quiet
    t1=$EPOCHREALTIME
    (cd "$tmp" && povray "+I$pscene" "+O$tmp/$name-pov.png" "+W$w" "+H$h" -D -A "Work_Threads=$threads" \
       "+L$povinc" >/dev/null 2>&1)
    t2=$EPOCHREALTIME
    echo "$t1 - $t0" | bc -l >> "$tmp/rays.t"
    echo "$t2 - $t1" | bc -l >> "$tmp/pov.t"
  done
  r=$(median < "$tmp/rays.t")
  p=$(median < "$tmp/pov.t")
  printf "%-14s %10.3f %10.3f %7.1fx\n" "$name" "$r" "$p" "$(echo "$p / $r" | bc -l)"
}
for scene in "${scenes[@]}"; do
  [ -f "$scene" ] || { echo "missing scene $scene" >&2; exit 2; }
  row "$(basename "$scene" .pov)" "$scene" "$(realpath "$scene")"
done
if [ "$gi_row" = 1 ]; then
  course=$(bench/course_scene.sh cornell)
  [ -f "$course" ] || { echo "missing scene $course" >&2; exit 2; }
  [ -f "$povex/radiosity/cornell.pov" ] || { echo "missing $povex/radiosity/cornell.pov" >&2; exit 2; }
  row "cornell -gi" "$course" "$povex/radiosity/cornell.pov" -gi
  echo "cornell -gi: Rays renders the course's cornell.pov -gi, POV-Ray its radiosity/cornell.pov"
fi
echo "ratio = POV-Ray time / Rays time (higher is better for Rays)"
