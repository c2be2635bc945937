#!/bin/sh
# Renders compare_scene.pov with povray and with Rays (build/rays) at 160x120 without
# anti-aliasing and compares the 8-bit images.
# Usage: compare.sh [FLAGS [FIGURE.png]]. FLAGS (default 15) switches the glass sphere's diffuse
# (1), phong (2), reflection (4) and fade (8), and 16 makes the first light a 5×5 area light.
# FIGURE.png: Rays, POV-Ray and their difference ×8 side by side.
# Needs POV-Ray and a Release build in build/. Output goes to build-scratch/compare/.
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../../.." && pwd)
out=$root/build-scratch/compare
mkdir -p "$out"
f=${1:-15}
d="diffuse 0"; p=""; r=""; fa=""; al=""
[ $((f & 1)) -ne 0 ] && d="diffuse 0.1"
[ $((f & 2)) -ne 0 ] && p="phong 1 phong_size 80"
[ $((f & 4)) -ne 0 ] && r="reflection { 0.05, 1 fresnel on } conserve_energy"
[ $((f & 8)) -ne 0 ] && fa="fade_distance 2 fade_power 1001 fade_color <0.5,0.8,0.6>"
[ $((f & 16)) -ne 0 ] && al="area_light <2,0,0>, <0,0,2>, 5, 5"
sed "s/light_source { <-3,5,-4>, rgb 1.2 }/light_source { <-3,5,-4>, rgb 1.2 $al }/; \
s/finish { ambient 0 diffuse 0.1 phong 1 phong_size 80 reflection { 0.05, 1 fresnel on } conserve_energy }/finish { ambient 0 $d $p $r }/; \
s/interior { ior 1.5 fade_distance 2 fade_power 1001 fade_color <0.5,0.8,0.6> }/interior { ior 1.5 $fa }/" \
  "$here/compare_scene.pov" > "$out/scene$f.pov"
povray +I"$out/scene$f.pov" +O"$out/pov$f.ppm" +FP +W160 +H120 -D -A Work_Threads=1 2>/dev/null
"$root/build/rays" render "$out/scene$f.pov" 160 120 -o "$out/rays$f.ppm" 2>/dev/null
python3 "$here/compare_images.py" "$out/rays$f.ppm" "$out/pov$f.ppm" ${2:+"$2"}
