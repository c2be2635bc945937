#!/usr/bin/env bash
# Sampling cost: a shipped soft-shadow scene rendered with 1 and with 16 stratified samples per
# pixel, runs alternated; prints medians and the ratio (target: at most 16 x 1.10 = 17.6).
#
#   bench/sample_cost.sh [-n RUNS] [-s WxH] [--scene NAME]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=5
size=320x240
scene=soft-shadows
while [ $# -gt 0 ]; do
  case $1 in
    -n) runs=$2; shift 2 ;;
    -s) size=$2; shift 2 ;;
    --scene) scene=$2; shift 2 ;;
    *) echo "usage: $0 [-n RUNS] [-s WxH] [--scene NAME]" >&2; exit 2 ;;
  esac
done
rays=./build/rays
[ -x "$rays" ] || { echo "build first: scripts/build.sh" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
now() { date +%s.%N; }
median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }
: > "$tmp/one"; : > "$tmp/sixteen"
for ((i = 0; i < runs; i++)); do
  t0=$(now); "$rays" render --scene "$scene" -W "${size%x*}" -H "${size#*x}" --spp 1 --aa stratified -o "$tmp/a.png" -q
  t1=$(now); "$rays" render --scene "$scene" -W "${size%x*}" -H "${size#*x}" --spp 16 --aa stratified -o "$tmp/b.png" -q
  t2=$(now)
  echo "$t1 - $t0" | bc -l >> "$tmp/one"; echo "$t2 - $t1" | bc -l >> "$tmp/sixteen"
done
a=$(median < "$tmp/one"); b=$(median < "$tmp/sixteen")
printf "scene %s %s, %d runs: 1 spp %.3f s, 16 spp %.3f s, ratio %.2f (target <= 17.6)\n" "$scene" "$size" "$runs" "$a" "$b" "$(echo "$b / $a" | bc -l)"
