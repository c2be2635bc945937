#!/usr/bin/env bash
# MPI benchmark (docs/mpi.md): the same still rendered by one process with T threads and by R MPI
# ranks with T/R threads each, R = 1, 2 and 4 (equal threads in all), runs alternated, medians
# printed with the ratio one-process time / MPI time (1.0: MPI costs nothing; the issue's target
# is >= 0.9). Then the parse phase: every rank parsing the scene itself (as Rays does) against rank
# 0 parsing it and broadcasting the built scene, measured as the slowest rank's parse+build at R
# ranks against one parse plus an MPI_Bcast of the scene's size in memory.
#
#   bench/mpi.sh [-n RUNS] [-s WxH] [-t THREADS] [SCENE.pov [RAYS OPTIONS...]]
#
# Defaults: 3 runs, 1920x1080, 4 threads in all, the course's balls2.pov (bench/scenes/course)
# with --ss 2. Columns: wall = the whole command (mpiexec's start of the ranks included); cpu =
# user+system seconds of all its processes (ranks waiting for MPI messages poll, and that shows
# here); render = the render phase Rays reports (hand-out, rendering and gathering). On a shared
# machine wall times follow the other load: compare runs of one session, and read cpu too.
# Needs a build with RAYS_MPI (Open MPI: libopenmpi-dev, openmpi-bin; mpicc for the broadcast).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=3
size=1920x1080
threads=4
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
rays=${RAYS:-./build/rays}  # RAYS=path: another build
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# In containers the shared-memory transport cannot attach to other processes (ptrace is denied).
export OMPI_MCA_btl_vader_single_copy_mechanism=${OMPI_MCA_btl_vader_single_copy_mechanism:-none}
# Open MPI binds each rank to one core when there are at most 2 ranks (all of a rank's threads
# then share that core) and to a socket up to a full machine: --bind-to none lets every rank's
# threads run anywhere, as the one process's do.
launch=(mpiexec)
mpiexec --version 2>&1 | grep -qiE "open ?mpi|openrte" && launch+=(--oversubscribe --bind-to none)
w=${size%x*} h=${size#*x}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
rankCounts=(1 2 4)

# run LABEL CMD...: "wall cpu render_ms parse+build_ms" appended to $out/LABEL; rank 0's summary
# gives the slowest rank's parse+build under MPI, the "wrote" line one process's.
run() {
  local label=$1
  shift
  /usr/bin/time -f "%e %U %S" -o "$out/time" "$@" "$scene" "$w" "$h" "${opts[@]}" -o "$out/$label.png" 2>"$out/$label.err"
  local wall cpu ms pb
  read -r wall u s <"$out/time"
  cpu=$(echo "$u + $s" | bc -l)
  ms=$(grep -o 'render [0-9.]* ms' "$out/$label.err" | tail -1 | awk '{print $2}')
  pb=$(grep -o 'parse+build [0-9.]* s' "$out/$label.err" | tail -1 | awk '{print $2 * 1000}' || true)
  [ -n "$pb" ] || pb=$(grep -o 'parse [0-9.]* ms, build [0-9.]* ms' "$out/$label.err" | tail -1 | awk '{print $2 + $5}')
  echo "$wall $cpu $ms $pb" >>"$out/$label"
}

# runConfig LABEL: one run of that configuration.
runConfig() {
  case $1 in
    one) run one "$rays" render --threads "$threads" ;;
    *) local r=${1#mpi}
       run "$1" "${launch[@]}" -np "$r" "$rays" render --threads $((threads / r > 0 ? threads / r : 1)) ;;
  esac
}
# Alternated, and each round starts one configuration later, so none always follows the same one.
configs=(one "${rankCounts[@]/#/mpi}")
for ((i = 0; i < runs; i++)); do
  for ((k = 0; k < ${#configs[@]}; k++)); do runConfig "${configs[$(((i + k) % ${#configs[@]}))]}"; done
done

median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
col() { awk -v c="$2" '{print $c}' "$out/$1" | median; }
echo "scene $scene ${w}x${h} ${opts[*]}; $threads threads in all; median of $runs alternated runs"
printf "%-24s %8s %8s %10s %9s %9s %11s %9s\n" config wall_s cpu_s render_ms wall_x render_x parse+build identical
for c in "${configs[@]}"; do
  case $c in
    one) name="1 process x $threads" ;;
    *) r=${c#mpi}; name="mpiexec -np $r x $((threads / r > 0 ? threads / r : 1))" ;;
  esac
  same=-
  [ "$c" != one ] && { cmp -s "$out/one.png" "$out/$c.png" && same=yes || same=NO; }
  printf "%-24s %8.2f %8.2f %10.1f %9.2f %9.2f %11.1f %9s\n" "$name" "$(col "$c" 1)" "$(col "$c" 2)" "$(col "$c" 3)" \
    "$(echo "$(col one 1) / $(col "$c" 1)" | bc -l)" "$(echo "$(col one 3) / $(col "$c" 3)" | bc -l)" "$(col "$c" 4)" "$same"
done
echo "(wall_x, render_x: one-process time / this time; parse+build in ms, under MPI the slowest rank's)"

# The broadcast rank 0 would need instead: the scene's size in memory (Rays' own estimate,
# --stats), sent with MPI_Bcast to 4 ranks on this machine (a small C program built with mpicc).
bytes=$("$rays" render "$scene" 64 48 --stats -o "$out/stats.png" 2>&1 | awk '/stats: scene about/ {print int($4 * 1e6)}')
command -v mpicc >/dev/null || { echo "no mpicc: broadcast not measured"; exit 0; }
cat >"$out/bcast.c" <<'C'
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
/* Times MPI_Bcast of argv[1] bytes from rank 0 (the median of 5, after one warm-up). */
int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    long n = atol(argv[1]);
    char* buf = calloc((size_t)n, 1);
    double t[6];
    for (int i = 0; i < 6; ++i) {
        MPI_Barrier(MPI_COMM_WORLD);
        double t0 = MPI_Wtime();
        MPI_Bcast(buf, (int)n, MPI_BYTE, 0, MPI_COMM_WORLD);
        MPI_Barrier(MPI_COMM_WORLD);
        t[i] = MPI_Wtime() - t0;
    }
    for (int i = 1; i < 6; ++i)
        for (int j = i + 1; j < 6; ++j)
            if (t[j] < t[i]) { double x = t[i]; t[i] = t[j]; t[j] = x; }
    if (rank == 0) printf("%.1f\n", t[3] * 1000);
    free(buf);
    MPI_Finalize();
    return 0;
}
C
mpicc -O2 "$out/bcast.c" -o "$out/bcast"
for r in 2 4; do
  ms=$("${launch[@]}" -np "$r" "$out/bcast" "$bytes")
  echo "rank 0 parses and broadcasts to $r ranks: one parse+build ($(col one 4) ms) + MPI_Bcast of $bytes bytes ($ms ms here)"
done
