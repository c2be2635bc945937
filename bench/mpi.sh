#!/usr/bin/env bash
# MPI overhead benchmark (docs/mpi.md): the same render as one process with T threads and as R
# MPI ranks with T/R threads each (equal cores), runs alternated, medians printed, and the
# parallel efficiency = one-process time / MPI time (1.0: MPI costs nothing).
#
#   bench/mpi.sh [-n RUNS] [-s WxH] [-t THREADS] [SCENE.pov [RAYS OPTIONS...]]
#
# Defaults: 3 runs, 640x480, 2 threads (this machine's cores), the course's balls2.pov (bench/scenes/course) with --ss 2;
# ranks 1 and 2 (2 ranks x 1 thread). Wall time includes mpiexec's start of the ranks (~0.3-0.5 s
# here), "render" is the render phase Rays reports (hand-out, rendering and gathering). On a shared
# machine the figures are noisy: compare runs from one session only.
# Needs a build with RAYS_MPI (Open MPI: libopenmpi-dev, openmpi-bin) in ./build/rays.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=3
size=640x480
threads=2
while getopts "n:s:t:" opt; do
  case $opt in
    n) runs=$OPTARG ;;
    s) size=$OPTARG ;;
    t) threads=$OPTARG ;;
    *) echo "usage: $0 [-n RUNS] [-s WxH] [-t THREADS] [SCENE.pov [OPTIONS...]]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
scene=${1:-$(bench/course_scene.sh balls2)}
[ $# -gt 0 ] && shift
opts=("$@")
[ $# -eq 0 ] && opts=(--ss 2)
rays=./build/rays
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# In containers the shared-memory transport cannot attach to other processes (ptrace is denied).
export OMPI_MCA_btl_vader_single_copy_mechanism=${OMPI_MCA_btl_vader_single_copy_mechanism:-none}
launch=(mpiexec)
mpiexec --version 2>&1 | grep -qiE "open ?mpi|openrte" && launch+=(--oversubscribe)
w=${size%x*} h=${size#*x}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# run LABEL CMD...: wall seconds and the reported render ms, appended to $out/LABEL.
run() {
  local label=$1
  shift
  local t0 t1 ms
  t0=$(date +%s.%N)
  "$@" "$scene" "$w" "$h" "${opts[@]}" -o "$out/$label.png" 2>"$out/$label.err"
  t1=$(date +%s.%N)
  ms=$(grep -o 'render [0-9.]* ms' "$out/$label.err" | tail -1 | awk '{print $2}')
  echo "$(echo "$t1 - $t0" | bc -l) $ms" >>"$out/$label"
}

configs=("one" "mpi1" "mpi2")
for ((i = 0; i < runs; i++)); do
  run one "$rays" render --threads "$threads"
  run mpi1 "${launch[@]}" -np 1 "$rays" render --threads "$threads"
  run mpi2 "${launch[@]}" -np 2 "$rays" render --threads $((threads / 2 > 0 ? threads / 2 : 1))
done
cmp -s "$out/one.png" "$out/mpi2.png" && same=yes || same=NO

median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
oneWall=$(awk '{print $1}' "$out/one" | median)
oneRender=$(awk '{print $2}' "$out/one" | median)
echo "scene $scene ${w}x${h} ${opts[*]}; $threads threads in all; median of $runs runs (shared machine: noisy)"
printf "%-26s %9s %11s %12s %14s\n" config wall_s render_ms eff_wall eff_render
for c in "${configs[@]}"; do
  wall=$(awk '{print $1}' "$out/$c" | median)
  ren=$(awk '{print $2}' "$out/$c" | median)
  case $c in
    one) name="1 process x $threads threads" ;;
    mpi1) name="mpiexec -np 1 x $threads" ;;
    mpi2) name="mpiexec -np 2 x $((threads / 2 > 0 ? threads / 2 : 1))" ;;
  esac
  printf "%-26s %9.2f %11.1f %12.2f %14.2f\n" "$name" "$wall" "$ren" "$(echo "$oneWall / $wall" | bc -l)" \
    "$(echo "$oneRender / $ren" | bc -l)"
done
echo "2-rank image byte-identical to the one-process image: $same"
