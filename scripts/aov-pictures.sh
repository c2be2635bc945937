#!/usr/bin/env bash
# The AOV pictures of docs/aov.md: the bunny scene rendered with every AOV (one PFM each, next to
# the PNG), each turned into a small PNG by scripts/aov_png.py. Usage: scripts/aov-pictures.sh [RAYS]
set -euo pipefail
cd "$(dirname "$0")/.."
rays=${1:-build/rays}
out=docs/images/aov
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
"$rays" render --scene bunny-lines 320 240 --spp 4 \
  --edges silhouette,occlusion,intersection,crease --aov all -o "$tmp/bunny.png" -q
cp "$tmp/bunny.png" "$out/colour.png"
for aov in depth normal albedo objectid materialid coverage edgetype; do
  python3 scripts/aov_png.py "$aov" "$tmp/bunny.$aov.pfm" "$out/$aov.png"
done
ls -l "$out"
