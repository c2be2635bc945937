#!/usr/bin/env bash
# Parse speed: Rays' parse phase against POV-Ray 3.7's own "Parse Time" on scenes that loop and
# call macros, alternating the two renderers run by run (the machine is shared: only figures
# from the same run compare), and on the course's big scene (parsed by the course reader).
#
#   bench/parse_speed.sh [-n RUNS] [SCENE.pov ...]
#
# Default scenes: bench/scenes/macro-loop.pov and, when povray-examples is installed, the
# example scenes whose parse is language work (not images, meshes from files or trace()):
# incdemo/shapes.pov advanced/benchmark/benchmark.pov bsp/Tango.pov incdemo/func_gradient.pov
# advanced/balcony/balcony.pov camera/mesh_camera/ess/ess-persp-camera.pov. They run from a copy
# (some scenes write files beside themselves). Rays' figure is the "parse" time of its summary
# line (reading, the language and building the scene); POV-Ray's is its "Parse Time".
# Needs povray (RAYS_BENCH_DEPS=1 scripts/install-deps.sh) and a built Rays (RAYS=..., default build/rays).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
RAYS=${RAYS:-$repo/build/rays}
runs=5
scenes=()
while [ $# -gt 0 ]; do
  case $1 in
    -n) runs=$2; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
command -v povray >/dev/null || { echo "parse_speed: povray is not installed (RAYS_BENCH_DEPS=1 scripts/install-deps.sh)" >&2; exit 2; }
[ -x "$RAYS" ] || { echo "parse_speed: $RAYS is not built (scripts/build.sh)" >&2; exit 2; }
RAYS=$(realpath "$RAYS")  # the runs below change folder

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
examples=/usr/share/doc/povray/examples
if [ ${#scenes[@]} -eq 0 ]; then
  scenes=("$repo/bench/scenes/macro-loop.pov")
  if [ -d "$examples" ]; then
    cp -r "$examples" "$work/examples"
    for s in incdemo/shapes.pov advanced/benchmark/benchmark.pov bsp/Tango.pov incdemo/func_gradient.pov \
             advanced/balcony/balcony.pov camera/mesh_camera/ess/ess-persp-camera.pov; do
      scenes+=("$work/examples/$s")
    done
  fi
fi

median() { sort -g | awk '{a[NR]=$1} END {if (NR == 0) print "nan"; else if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2]+a[NR/2+1])/2}'; }

printf '%-44s %12s %12s %8s\n' scene "POV-Ray (s)" "Rays (s)" ratio
ratios=()
for scene in "${scenes[@]}"; do
  dir=$(dirname "$scene"); base=$(basename "$scene")
  pov=(); rays=()
  for ((i = 0; i < runs; i++)); do
    p=$(cd "$dir" && povray "+I$base" "+O$work/p.png" +W32 +H24 -D -A Work_Threads=2 +L/usr/share/povray-3.7/include 2>&1 </dev/null |
        tr '\r' '\n' | sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' | head -n 1)
    r=$(cd "$dir" && "$RAYS" render "$base" 32 24 -o "$work/r.png" --threads 2 +L/usr/share/povray-3.7/include 2>&1 </dev/null |
        sed -n 's/.*: parse \([0-9.]*\) ms,.*/\1/p' | tail -n 1)
    [ -n "$p" ] || { echo "parse_speed: POV-Ray gave no parse time for $scene" >&2; exit 1; }
    [ -n "$r" ] || { echo "parse_speed: Rays gave no parse time for $scene" >&2; exit 1; }
    pov+=("$p")
    rays+=("$(awk -v m="$r" 'BEGIN {printf "%.4f", m / 1000}')")
  done
  mp=$(printf '%s\n' "${pov[@]}" | median)
  mr=$(printf '%s\n' "${rays[@]}" | median)
  ratio=$(awk -v p="$mp" -v r="$mr" 'BEGIN {if (r > 0) printf "%.2f", p / r; else print "nan"}')
  ratios+=("$ratio")
  name=${scene#"$work/examples/"}; name=${name#"$repo/"}
  printf '%-44s %12s %12s %7sx\n' "$name" "$mp" "$mr" "$ratio"
done
printf 'median ratio over %d scenes: %sx (%d runs each, alternated)\n' "${#ratios[@]}" \
  "$(printf '%s\n' "${ratios[@]}" | median)" "$runs"

# The course's big scene (course reader): Rays' parse against POV-Ray's parse of the same file.
balls=$("$repo/bench/course_scene.sh" balls2)
if [ -f "$balls" ]; then
  pov=(); rays=()
  for ((i = 0; i < runs; i++)); do
    p=$(cd "$work" && povray "+I$balls" "+O$work/p.png" +W32 +H24 -D -A Work_Threads=2 2>&1 </dev/null |
        tr '\r' '\n' | sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' | head -n 1)
    r=$("$RAYS" render "$balls" 32 24 -o "$work/r.png" --threads 2 2>&1 </dev/null | sed -n 's/.*: parse \([0-9.]*\) ms,.*/\1/p')
    [ -n "$p" ] && pov+=("$p")
    [ -n "$r" ] && rays+=("$(awk -v m="$r" 'BEGIN {printf "%.4f", m / 1000}')")
  done
  printf 'course balls2.pov (2.5 MB, course reader): POV-Ray %s s, Rays %s s\n' \
    "$(printf '%s\n' "${pov[@]}" | median)" "$(printf '%s\n' "${rays[@]}" | median)"
else
  echo "course balls2.pov: bench/scenes/course/balls2.pov.gz not found, skipped"
fi
