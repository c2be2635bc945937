#!/usr/bin/env bash
# POV-Ray comparison: renders POV-Ray's own example scenes with Rays and with POV-Ray 3.7 at a
# small size and compares the images (rays compare: SSIM, PSNR, diff image), with timings.
#
#   bench/povray_compare.sh [options] [SCENE.pov | FOLDER ...]
#
# Without scenes: every *.pov under the examples folder (povray-examples package). A FOLDER or
# scene may also be named relative to the examples folder (e.g. `camera`). Writes into OUT:
#   results.tsv   one row per scene (columns: docs/povray-compare.md)
#   summary.txt   counts, top error messages, SSIM bands, median speed-up (also printed)
#   index.html    contact sheet: POV-Ray, Rays and diff images with the figures
# POV-Ray's images are cached under OUT/ref/<povray version>/<W>x<H>/ (keyed also by the scene's
# checksum), so re-runs only re-render Rays; --refresh renders POV-Ray again.
# Scenes under the examples folder run from a copy of it (OUT/work/): some scenes write files
# next to themselves, and /usr/share/doc is not ours to write to.
# Needs bash 5, coreutils, povray (RAYS_BENCH_DEPS=1 scripts/install-deps.sh) and a built Rays.
set -euo pipefail

usage() {
  cat <<'EOF'
usage: bench/povray_compare.sh [options] [SCENE.pov | FOLDER ...]
  -k N               only the first N scenes (sorted by path)
  -j N               scenes rendered in parallel (default 1; each renderer uses 2 threads)
  -s WxH             image size (default 160x120)
  -o DIR             output folder (default bench/out/povray-compare)
  -t SECONDS         timeout of both renderers (default 60)
  --pov-timeout S    timeout of POV-Ray (default 60)
  --rays-timeout S   timeout of Rays (default 60)
  --refresh          render the POV-Ray references again (and re-copy the examples)
  --examples DIR     the examples folder (default /usr/share/doc/povray/examples)
  -h, --help         this help
environment: RAYS=path/to/rays (default build/rays)
EOF
}

repo=$(cd "$(dirname "$0")/.." && pwd)
examples=/usr/share/doc/povray/examples
include=/usr/share/povray-3.7/include
out=$repo/bench/out/povray-compare
size=160x120
jobs=1
first=0
pov_timeout=60
rays_timeout=60
refresh=0
args=()
while [ $# -gt 0 ]; do
  case $1 in
    -k) first=$2; shift 2 ;;
    -j) jobs=$2; shift 2 ;;
    -s) size=$2; shift 2 ;;
    -o) out=$2; shift 2 ;;
    -t) pov_timeout=$2; rays_timeout=$2; shift 2 ;;
    --pov-timeout) pov_timeout=$2; shift 2 ;;
    --rays-timeout) rays_timeout=$2; shift 2 ;;
    --refresh) refresh=1; shift ;;
    --examples) examples=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    --) shift; args+=("$@"); break ;;
    -*) echo "povray_compare: unknown option $1" >&2; usage >&2; exit 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
for n in "$first" "$jobs" "$pov_timeout" "$rays_timeout"; do
  [[ $n =~ ^[0-9]+$ ]] || { echo "povray_compare: not a number: $n" >&2; exit 2; }
done
[[ $size =~ ^([0-9]+)x([0-9]+)$ ]] || { echo "povray_compare: -s wants WxH, got $size" >&2; exit 2; }
width=${BASH_REMATCH[1]}
height=${BASH_REMATCH[2]}
[ "$jobs" -ge 1 ] || jobs=1

[ -n "${EPOCHREALTIME:-}" ] || { echo "povray_compare: needs bash 5 (EPOCHREALTIME)" >&2; exit 2; }
command -v timeout >/dev/null || { echo "povray_compare: needs coreutils' timeout" >&2; exit 2; }
if ! command -v povray >/dev/null; then
  echo "povray_compare: povray is not installed; install it with: RAYS_BENCH_DEPS=1 scripts/install-deps.sh" >&2
  echo "  (Debian packages povray povray-includes povray-examples fonts-povray)" >&2
  exit 2
fi
rays=${RAYS:-$repo/build/rays}
[[ $rays == /* ]] || rays=$(pwd)/$rays
if [ ! -x "$rays" ]; then
  echo "povray_compare: no Rays binary at $rays (build first: scripts/build.sh, or set RAYS=...)" >&2
  exit 2
fi
examples=$(cd "$examples" 2>/dev/null && pwd) || examples=""

# ---- the scenes --------------------------------------------------------------------------------
scenes=()
add_tree() { while IFS= read -r -d '' f; do scenes+=("$f"); done < <(find "$1" -name '*.pov' -type f -print0); }
if [ ${#args[@]} -eq 0 ]; then
  [ -n "$examples" ] || { echo "povray_compare: no examples folder; install povray-examples or pass scenes" >&2; exit 2; }
  add_tree "$examples"
fi
for a in "${args[@]}"; do
  if [ ! -e "$a" ] && [ -n "$examples" ] && [ -e "$examples/$a" ]; then a=$examples/$a; fi
  if [ -d "$a" ]; then add_tree "$(cd "$a" && pwd)"
  elif [ -f "$a" ]; then scenes+=("$(cd "$(dirname "$a")" && pwd)/$(basename "$a")")
  else echo "povray_compare: no such scene or folder: $a" >&2; exit 2
  fi
done
mapfile -t scenes < <(printf '%s\n' "${scenes[@]}" | LC_ALL=C sort -u)
[ "$first" -gt 0 ] && scenes=("${scenes[@]:0:$first}")
[ ${#scenes[@]} -gt 0 ] || { echo "povray_compare: no scenes" >&2; exit 2; }

mkdir -p "$out"
out=$(cd "$out" && pwd)
pov_version=$(povray --version 2>&1 | sed -n 's/^POV-Ray \([0-9][^ ]*\).*/\1/p' | head -n 1)
[ -n "$pov_version" ] || pov_version=unknown
refdir=ref/$pov_version/${width}x$height

# The copy of the examples the scenes under it run from.
if [ -n "$examples" ]; then
  if [ "$refresh" = 1 ] || [ ! -f "$out/work/.copied" ] || [ "$(cat "$out/work/.copied")" != "$examples" ]; then
    rm -rf "$out/work"
    mkdir -p "$out/work"
    cp -R "$examples/." "$out/work/"
    chmod -R u+w "$out/work"
    echo "$examples" > "$out/work/.copied"
  fi
fi
rm -rf "$out/rows"
mkdir -p "$out/rows"

# ---- one scene ---------------------------------------------------------------------------------
# Microseconds since the epoch, from bash's own clock (no process started inside a timed interval).
now_us() { local t=${EPOCHREALTIME/./}; echo "$((10#$t))"; }
# Seconds with 3 decimals from microseconds.
seconds() { printf '%d.%03d' "$(($1 / 1000000))" "$((($1 % 1000000) / 1000))"; }
# One line: tabs and carriage returns to spaces, trimmed, at most 200 characters.
clean() { tr '\t\r' '  ' | sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' | cut -c1-200; }

# How a process ended, from its exit status, its time limit, and whether it wrote its image.
status_of() {  # rc seconds_limit wall_us image
  local rc=$1 limit=$2 wall=$3 image=$4
  if [ "$rc" = 124 ] || { [ "$rc" = 137 ] && [ "$wall" -ge $((limit * 1000000)) ]; }; then echo timeout
  elif [ "$rc" -gt 128 ]; then echo crash
  elif [ "$rc" != 0 ] || [ ! -s "$image" ]; then echo error
  else echo ok
  fi
}

# A scene with an INI file of the same name (the portfolio scenes: animations that set
# frame_number) runs with it, frame 1 only, for both renderers.
ini_args() {  # scene arrayname
  local -n into=$2
  local file=${1%.pov}.ini
  into=()
  # +FN after it: an INI may turn file output off (benchmark.ini has Output_To_File=Off).
  [ -f "$file" ] && into=("$(basename "$file")" +SF1 +EF1 +FN)
  return 0
}

# An animation's frame is written as BASE<digits>.png: rename it to BASE.png.
first_frame_image() {  # base
  [ -f "$1.png" ] && return 0
  local f
  for f in "$1"[0-9]*.png; do
    [ -f "$f" ] && mv -f "$f" "$1.png" && return 0
  done
  return 0
}

signal_name() { kill -l "$(($1 - 128))" 2>/dev/null || echo "$(($1 - 128))"; }

# Renders the POV-Ray reference unless the cache holds one for this scene's contents (a cached
# timeout counts only when its time limit was at least today's).
povray_reference() {  # scene rel rundir
  local scene=$1 rel=$2 rundir=$3
  local base=$out/$refdir/${rel%.pov}
  local sum
  sum=$(cksum < "$scene" | cut -d' ' -f1,2)
  if [ "$REFRESH" != 1 ] && [ -f "$base.meta" ] && [ "$(sed -n 's/^cksum=//p' "$base.meta")" = "$sum" ]; then
    [ "$(sed -n 's/^status=//p' "$base.meta")" != timeout ] && return 0
    [ "$(sed -n 's/^limit=//p' "$base.meta")" -ge "$POV_TIMEOUT" ] 2>/dev/null && return 0
  fi
  mkdir -p "$(dirname "$base")"
  rm -f "$base.png" "$base.part.png"
  local t0 t1 rc=0
  t0=$(now_us)
  local ini=()
  ini_args "$scene" ini
  (cd "$rundir" && timeout -k 5 "$POV_TIMEOUT" povray "${ini[@]}" "+I$(basename "$scene")" "+O$base.part.png" \
      "+W$WIDTH" "+H$HEIGHT" -D -A Work_Threads=2 "+L$INCLUDE" </dev/null >/dev/null 2>"$base.log") 2>/dev/null || rc=$?
  t1=$(now_us)
  first_frame_image "$base.part"
  local status
  status=$(status_of "$rc" "$POV_TIMEOUT" $((t1 - t0)) "$base.part.png")
  if [ "$status" = ok ]; then mv -f "$base.part.png" "$base.png"; else rm -f "$base.part.png"; fi
  local parse
  parse=$(tr '\r' '\n' < "$base.log" | sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' | head -n 1)
  printf 'cksum=%s\nstatus=%s\nrc=%s\nlimit=%s\nwall=%s\nparse=%s\n' "$sum" "$status" "$rc" "$POV_TIMEOUT" \
    "$(seconds $((t1 - t0)))" "$parse" > "$base.meta"
}

run_scene() {  # scene rel rundir
  local scene=$1 rel=$2 rundir=$3
  povray_reference "$scene" "$rel" "$rundir"
  local ref=$out/$refdir/${rel%.pov}
  local pov_status pov_wall pov_parse
  pov_status=$(sed -n 's/^status=//p' "$ref.meta")
  pov_wall=$(sed -n 's/^wall=//p' "$ref.meta")
  pov_parse=$(sed -n 's/^parse=//p' "$ref.meta")

  local img=$out/rays/${rel%.pov}
  local dif=$out/diff/${rel%.pov}
  mkdir -p "$(dirname "$img")" "$(dirname "$dif")"
  rm -f "$img.png" "$dif.png" "$dif.txt"
  local t0 t1 rc=0
  t0=$(now_us)
  local ini=()
  ini_args "$scene" ini
  if [ ${#ini[@]} -gt 0 ]; then
    (cd "$rundir" && timeout -k 5 "$RAYS_TIMEOUT" "$RAYS" "${ini[@]}" "+I$(basename "$scene")" "+O$img.png" \
        "+W$WIDTH" "+H$HEIGHT" -A Work_Threads=2 "+L$INCLUDE" </dev/null >/dev/null 2>"$img.log") 2>/dev/null || rc=$?
    first_frame_image "$img"
  else
    (cd "$rundir" && timeout -k 5 "$RAYS_TIMEOUT" "$RAYS" render "$(basename "$scene")" "$WIDTH" "$HEIGHT" -o "$img.png" \
        "+L$INCLUDE" --threads 2 </dev/null >/dev/null 2>"$img.log") 2>/dev/null || rc=$?
  fi
  t1=$(now_us)
  local status warnings notes first_error
  status=$(status_of "$rc" "$RAYS_TIMEOUT" $((t1 - t0)) "$img.png")
  warnings=$(grep -c 'warning:' "$img.log" || true)
  notes=$(grep -c 'not rendered yet' "$img.log" || true)
  first_error=$(grep -m 1 -E '(^|: )(internal )?error:' "$img.log" | clean || true)
  case $status in
    ok) [ "$warnings" -gt 0 ] && status=warn ;;
    timeout) first_error="timed out after $RAYS_TIMEOUT s" ;;
    crash) first_error="killed by signal $(signal_name "$rc")" ;;
    error) [ -n "$first_error" ] || first_error="exit status $rc, no image written" ;;
  esac

  local ssim="" psnr="" ratio=""
  if [ -s "$img.png" ] && [ -s "$ref.png" ]; then
    if "$RAYS" compare "$ref.png" "$img.png" --diff "$dif.png" > "$dif.txt" 2>&1; then
      ssim=$(sed -n 's/^ssim //p' "$dif.txt")
      psnr=$(sed -n 's/^psnr //p' "$dif.txt")
    fi
    ratio=$(awk -v p="$pov_wall" -v r="$(seconds $((t1 - t0)))" 'BEGIN { if (r > 0) printf "%.2f", p / r }')
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$rel" "$status" "$warnings" "$first_error" "$notes" \
    "$ssim" "$psnr" "$(seconds $((t1 - t0)))" "$pov_wall" "$pov_parse" "$ratio" "$pov_status" \
    > "$out/rows/$(echo "$rel" | tr '/' '%').tsv"
  printf '%-50s rays %-7s povray %-7s ssim %-8s %ss / %ss\n' "$rel" "$status" "$pov_status" "${ssim:--}" \
    "$(seconds $((t1 - t0)))" "$pov_wall" >&2
}

export out refdir REFRESH=$refresh WIDTH=$width HEIGHT=$height POV_TIMEOUT=$pov_timeout RAYS_TIMEOUT=$rays_timeout \
  RAYS=$rays INCLUDE=$include
export -f now_us seconds clean status_of signal_name ini_args first_frame_image povray_reference run_scene

# A scene's name in the results: its path under the examples folder, else other/<absolute path>.
name_of() { if [ -n "$examples" ] && [[ $1 == "$examples"/* ]]; then echo "${1#"$examples"/}"; else echo "other$1"; fi; }

# One NUL-separated record per scene: path, name, folder to run from (in the copy for examples).
for s in "${scenes[@]}"; do
  rel=$(name_of "$s")
  if [[ $rel == other/* ]]; then dir=$(dirname "$s"); else dir=$out/work/$(dirname "$rel"); fi
  printf '%s\0%s\0%s\0' "$s" "$rel" "$dir"
done | xargs -0 -n 3 -P "$jobs" bash -c 'run_scene "$@" || echo "povray_compare: $2 failed" >&2; exit 0' _

# ---- results.tsv -------------------------------------------------------------------------------
{
  printf 'scene\trays_status\twarnings\tfirst_error\tnot_rendered\tssim\tpsnr\trays_s\tpovray_s'
  printf '\tpovray_parse_s\tratio\tpovray_status\n'
  for s in "${scenes[@]}"; do
    rel=$(name_of "$s")
    row=$out/rows/$(echo "$rel" | tr '/' '%').tsv
    if [ -f "$row" ]; then cat "$row"
    else printf '%s\terror\t0\tthe comparison script failed on this scene\t0\t\t\t\t\t\t\t\n' "$rel"
    fi
  done
} > "$out/results.tsv"

# ---- summary.txt -------------------------------------------------------------------------------
awk -F'\t' -v size="${width}x$height" -v version="$pov_version" '
NR == 1 { next }
{
  n++
  if ($2 == "ok" || $2 == "warn") rendered++
  if ($2 == "ok") clean++
  status[$2]++
  if ($12 == "ok") refs++
  if ($6 != "") { compared++; if ($6 >= 0.95) s95++; if ($6 >= 0.90) s90++ }
  if ($11 != "") ratios[++nr] = $11
  if ($4 != "" && $2 != "ok" && $2 != "warn") {
    msg = $4
    sub(/^[^ ]*:[0-9]+:[0-9]+: /, "", msg)   # FILE:LINE:COL: prefix
    sub(/^[^ ]*: error: /, "error: ", msg)    # FILE: prefix
    errors[msg]++
  }
}
END {
  printf "POV-Ray comparison: %d scenes at %s, POV-Ray %s\n", n, size, version
  printf "  Rays rendered:              %d (no warning: %d)\n", rendered, clean
  printf "  Rays errors / timeouts / crashes: %d / %d / %d\n", status["error"], status["timeout"], status["crash"]
  printf "  POV-Ray rendered:           %d\n", refs
  printf "  compared (both images):     %d; SSIM >= 0.95: %d, >= 0.90: %d\n", compared, s95, s90
  if (nr > 0) {
    for (i = 2; i <= nr; i++) { v = ratios[i]; for (j = i - 1; j >= 1 && ratios[j] + 0 > v + 0; j--) ratios[j + 1] = ratios[j]; ratios[j + 1] = v }
    med = nr % 2 ? ratios[(nr + 1) / 2] : (ratios[nr / 2] + ratios[nr / 2 + 1]) / 2
    printf "  median speed-up (POV-Ray time / Rays time): %.2fx over %d scenes\n", med, nr
  } else {
    printf "  median speed-up: - (no scene rendered by both)\n"
  }
  if (length(errors) > 0) {
    printf "Rays errors by first error message (top 20):\n"
    cmd = "sort -t \"\t\" -k1,1nr -k2 | head -n 20"
    for (m in errors) printf "%d\t%s\n", errors[m], m | cmd
    close(cmd)
  }
}' "$out/results.tsv" | sed 's/^\([0-9][0-9]*\)\t/  \1  /' > "$out/summary.txt"

# ---- index.html --------------------------------------------------------------------------------
awk -F'\t' -v refdir="$refdir" -v w=$((2 * width)) -v h=$((2 * height)) -v out="$out" -v summary="$out/summary.txt" '
function esc(s) { gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); gsub(/>/, "\\&gt;", s); gsub(/"/, "\\&quot;", s); return s }
function img(path, alt) {
  if ((getline line < (out "/" path)) < 0) return "<td class=missing>-</td>"
  close(out "/" path)
  return "<td><a href=\"" esc(path) "\"><img src=\"" esc(path) "\" width=" w " height=" h " alt=\"" alt "\" loading=lazy></a></td>"
}
BEGIN {
  print "<!DOCTYPE html><html><head><meta charset=utf-8><title>Rays vs POV-Ray</title><style>"
  print "body{font:13px sans-serif;margin:1em} table{border-collapse:collapse} td,th{border:1px solid #ccc;padding:3px;vertical-align:top}"
  print "th{background:#eee;cursor:pointer} img{image-rendering:pixelated;display:block;background:#888}"
  print ".ok{background:#dfd} .warn{background:#ffd} .error,.timeout,.crash{background:#fdd} .missing{text-align:center;color:#999}"
  print ".err{max-width:28em;font-family:monospace;font-size:11px} pre{font-size:12px}"
  print "</style></head><body><h1>Rays vs POV-Ray</h1><pre>"
  while ((getline line < summary) > 0) print esc(line)
  print "</pre><p>Click a column heading to sort. Images at twice their size; diff = |POV-Ray - Rays| (rays compare --diff).</p>"
  print "<table id=t><thead><tr><th>scene</th><th>POV-Ray</th><th>Rays</th><th>diff</th><th>status</th><th>SSIM</th><th>PSNR</th>"
  print "<th>Rays s</th><th>POV-Ray s</th><th>parse s</th><th>ratio</th><th>warnings</th><th>not rendered</th><th>first error</th></tr></thead><tbody>"
}
NR > 1 {
  base = $1; sub(/\.pov$/, "", base)
  printf "<tr><td>%s</td>%s%s%s", esc($1), img(refdir "/" base ".png", "POV-Ray"), img("rays/" base ".png", "Rays"), img("diff/" base ".png", "diff")
  printf "<td class=%s>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td class=err>%s</td></tr>\n", \
    $2, $2, $6, $7, $8, $9, $10, $11, $3, $5, esc($4)
}
END {
  print "</tbody></table><script>"
  print "document.querySelectorAll(\"#t th\").forEach((th, col) => th.addEventListener(\"click\", () => {"
  print "  const body = document.querySelector(\"#t tbody\"), rows = [...body.rows];"
  print "  const key = r => r.cells[col].textContent, num = s => s === \"\" || s === \"-\" ? NaN : Number(s);"
  print "  const dir = th.dataset.dir = th.dataset.dir === \"1\" ? \"-1\" : \"1\";"
  print "  rows.sort((a, b) => { const x = num(key(a)), y = num(key(b));"
  print "    if (!isNaN(x) || !isNaN(y)) return isNaN(x) ? 1 : isNaN(y) ? -1 : (x - y) * dir;"
  print "    return key(a).localeCompare(key(b)) * dir; });"
  print "  rows.forEach(r => body.appendChild(r));"
  print "}));"
  print "</script></body></html>"
}' "$out/results.tsv" > "$out/index.html"

cat "$out/summary.txt"
echo "results: $out/results.tsv, contact sheet: $out/index.html"
