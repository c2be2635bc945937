#!/usr/bin/env bash
# Whole-render benchmark: Rays against POV-Ray 3.7 on the same scenes, runs alternated in one
# session (the machines are shared and noisy), medians and the ratio printed.
#
#   bench/render.sh [-n RUNS] [-s WxH] [-a THRESHOLD] [-g | -p] [SCENE.pov ...]
#
# Defaults: 5 runs, 640x480, and the course scenes bunny, gnarly and balls2 (bench/scenes/course/), then
# a global-illumination row (-g: that row alone; it is left out when scenes are named): Rays
# renders the course's cornell.pov with -gi (64 + 16 samples, 2 levels), POV-Ray its own
# radiosity/cornell.pov (radiosity count 200, recursion_limit 3) from the examples folder, as
# the anchor for the same kind of work: different scenes and methods, so the ratio is a scale
# to follow over time, not a like-for-like race.
# Both renderers use all cores and one sample per pixel (POV-Ray: -A, no anti-aliasing), or with
# -a THRESHOLD both use POV-Ray's adaptive anti-aliasing (+A THRESHOLD, method 1, depth 3).
# -p (primitives): POV-Ray's own example scenes of its objects/ folder (objects/*.pov,
# objects/quartic, objects/csg: one scene per primitive or CSG case), at 320x240 with +A0.3 unless
# -s / -a say otherwise, each row with its target ratio (5x; 3x for the isosurface scene) and a
# closing line counting the scenes that reach it; scenes named after -p replace the folder's.
# Needs the `povray` package (RAYS_BENCH_DEPS=1 scripts/install-deps.sh) and a built ./build/rays
# (or RAYS=path/to/rays: a copy keeps a rebuild from changing the binary during a run).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=5
size=640x480
gi_only=0
primitives=0
aa=
size_given=0
while getopts "n:s:a:gp" opt; do
  case $opt in
    n) runs=$OPTARG ;;
    s) size=$OPTARG; size_given=1 ;;
    a) aa=$OPTARG ;;
    g) gi_only=1 ;;
    p) primitives=1 ;;
    *) echo "usage: $0 [-n RUNS] [-s WxH] [-a THRESHOLD] [-g | -p] [SCENE.pov ...]" >&2; exit 2 ;;
  esac
done
if [ "$primitives" = 1 ]; then
  [ "$size_given" = 1 ] || size=320x240
  [ -n "$aa" ] || aa=0.3
fi
shift $((OPTIND - 1))
w=${size%x*}
h=${size#*x}
scenes=("$@")
gi_row=0
povex=/usr/share/doc/povray/examples
if [ "$primitives" = 1 ]; then
  [ -d "$povex/objects" ] || { echo "missing $povex/objects (RAYS_BENCH_DEPS=1 scripts/install-deps.sh)" >&2; exit 2; }
  [ ${#scenes[@]} -gt 0 ] || mapfile -t scenes < <(find "$povex/objects" -name '*.pov' | LC_ALL=C sort)
elif [ ${#scenes[@]} -eq 0 ]; then
  gi_row=1
  [ "$gi_only" = 1 ] || for s in bunny gnarly balls2; do scenes+=("$(bench/course_scene.sh "$s")"); done
fi
povinc=/usr/share/povray-3.7/include
rays=${RAYS:-$(pwd)/build/rays}
[ -x "$rays" ] || { echo "build first: scripts/build.sh" >&2; exit 2; }
command -v povray >/dev/null || { echo "povray is not installed (RAYS_BENCH_DEPS=1 scripts/install-deps.sh)" >&2; exit 2; }
threads=$(nproc)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Bash's own clock: $(date) would fork and exec a process inside every timed interval (~10 ms on
# these machines, a bias of 5-15 % against a 0.1 s render).
[ -n "${EPOCHREALTIME:-}" ] || { echo "needs bash 5 (EPOCHREALTIME)" >&2; exit 2; }
median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }

# Anti-aliasing switches of both renderers.
if [ -n "$aa" ]; then
  rays_aa=("+A$aa" +AM1 +R3)
  pov_aa=("+A$aa" +AM1 +R3)
else
  rays_aa=()
  pov_aa=(-A)
fi
aa_text="no AA"
[ -n "$aa" ] && aa_text="AA $aa"
printf "%-14s %10s %10s %8s   (%s, %s, %d runs each, %d threads, medians of wall time)\n" \
  scene "Rays s" "POV-Ray s" ratio "$size" "$aa_text" "$runs" "$threads"
met=0
rows=0
# One row: NAME, Rays' scene, POV-Ray's scene, then Rays' extra flags; runs alternated.
row() {
  local name=$1 rscene=$2 pscene=$3
  local file=${name//\//-}  # output file names: objects/quartic/helix → quartic-helix
  shift 3
  : > "$tmp/rays.t"
  : > "$tmp/pov.t"
  for ((i = 0; i < runs; i++)); do
    t0=$EPOCHREALTIME
    "$rays" render "$rscene" "$w" "$h" "$@" "${rays_aa[@]}" -o "$tmp/$file-rays.png" --quiet || { echo "$name: rays failed" >&2; return 0; }
    t1=$EPOCHREALTIME
    # The scene's own folder on the library path (its includes: objects/chess.inc); a failure is
    # reported, not a silent exit.
    (cd "$tmp" && povray "+I$pscene" "+O$tmp/$file-pov.png" "+W$w" "+H$h" -D "${pov_aa[@]}" "Work_Threads=$threads" \
       "+L$(dirname "$pscene")" "+L$povinc" >/dev/null 2>&1) || { echo "$name: povray failed" >&2; return 0; }
    t2=$EPOCHREALTIME
    echo "$t1 - $t0" | bc -l >> "$tmp/rays.t"
    echo "$t2 - $t1" | bc -l >> "$tmp/pov.t"
  done
  r=$(median < "$tmp/rays.t")
  p=$(median < "$tmp/pov.t")
  local ratio
  ratio=$(echo "$p / $r" | bc -l)
  if [ "$primitives" = 1 ]; then
    local target=5
    grep -q '^[^/]*isosurface' "$rscene" && target=3
    rows=$((rows + 1))
    local verdict="below ${target}x"
    if [ "$(echo "$ratio >= $target" | bc -l)" = 1 ]; then met=$((met + 1)); verdict="ok (${target}x)"; fi
    printf "%-22s %10.3f %10.3f %7.1fx   %s\n" "$name" "$r" "$p" "$ratio" "$verdict"
  else
    printf "%-14s %10.3f %10.3f %7.1fx\n" "$name" "$r" "$p" "$ratio"
  fi
}
for scene in "${scenes[@]}"; do
  [ -f "$scene" ] || { echo "missing scene $scene" >&2; exit 2; }
  name=$(basename "$scene" .pov)
  [ "$primitives" = 1 ] && name=${scene#"$povex/objects/"} && name=${name%.pov}
  row "$name" "$scene" "$(realpath "$scene")"
done
[ "$primitives" = 1 ] && echo "primitives: $met of $rows scenes reach their target ratio (5x; 3x for isosurfaces)"

if [ "$gi_row" = 1 ]; then
  course=$(bench/course_scene.sh cornell)
  [ -f "$course" ] || { echo "missing scene $course" >&2; exit 2; }
  [ -f "$povex/radiosity/cornell.pov" ] || { echo "missing $povex/radiosity/cornell.pov" >&2; exit 2; }
  row "cornell -gi" "$course" "$povex/radiosity/cornell.pov" -gi
  echo "cornell -gi: Rays renders the course's cornell.pov -gi, POV-Ray its radiosity/cornell.pov"
fi
echo "ratio = POV-Ray time / Rays time (higher is better for Rays)"
