#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/CMakeLists.txt → build-fuzz/, clang++-14, ASan + UBSan) and runs
# them one after another, each for SECONDS (default 600), niced, one process at a time.
#
#   fuzz/run.sh [SECONDS] [TARGET ...]      targets: scene obj kernel image pov ini font (default: all seven)
#   fuzz/run.sh --scaled [SECONDS] [TARGET ...]   size-scaling mode: scene obj kernel pov ini (default)
#
# Size-scaling mode (RAYS_FUZZ_SCALE=1, entry_points.h scaledInput): the first byte of an input sets a
# count 2^(k mod 18) and each "@@...@@" region is repeated that many times, so small inputs reach the
# sizes where work that grows faster than its input shows (as a -timeout=10 report). Its seeds are in
# fuzz/seeds-scaled/TARGET, its corpora in build-fuzz/corpus-scaled/TARGET.
#
# Corpora grow in build-fuzz/corpus/TARGET (kept between runs); the seeds (project scenes, the files in
# fuzz/seeds/, generated images, the saved regression inputs in tests/regressions/, and for pov the
# POV-Ray example scenes and a few include files, its INI files and its fonts when installed) are
# added every run.
# Findings land in build-fuzz/artifacts/TARGET/ (crash-*, timeout-*, leak-*, oom-*); logs in
# build-fuzz/logs/TARGET.log. Exit status 1 when any target found something. Environment:
# FUZZ_BUILD_DIR (default build-fuzz), FUZZ_CXX (default clang++-14), FUZZ_FLAGS (extra libFuzzer flags).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

scaled=0
if [ "${1:-}" = --scaled ]; then
  scaled=1
  shift
fi
secs=${1:-600}
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  if [ $scaled = 1 ]; then targets=(scene obj kernel pov ini); else targets=(scene obj kernel image pov ini font); fi
fi
build=${FUZZ_BUILD_DIR:-build-fuzz}
case "$build" in /*) ;; *) build="$root/$build" ;; esac

echo "== building fuzzers in $build" >&2
nice -n 10 cmake -S fuzz -B "$build" -DCMAKE_CXX_COMPILER="${FUZZ_CXX:-clang++-14}" >/dev/null
nice -n 10 cmake --build "$build" -j2 >/dev/null

# ---- seed corpora ---------------------------------------------------------------------------------
seeds="$build/seeds"
rm -rf "$seeds"
mkdir -p "$seeds"/{scene,obj,kernel,image,pov,ini,font}
for f in scenes/*.pov tests/scenes/*.pov; do
  # Big scenes (05-mesh.pov, 265 KB) would raise the input size limit for every run: keep their start.
  head -c 16384 "$f" >"$seeds/scene/$(basename "$f")"
done
cp fuzz/seeds/scene/* "$seeds/scene/"
cp fuzz/seeds/obj/* "$seeds/obj/"
cp fuzz/seeds/kernel/* "$seeds/kernel/"
"$build/make_image_seeds" "$seeds/image" >/dev/null
cp fuzz/seeds/pov/* "$seeds/pov/"
cp fuzz/seeds/ini/* "$seeds/ini/"
# POV-Ray's example scenes and some of its include files (AGPL: copied at run time, never kept in the
# repository), the first 16 KB of each; names keep the folder so equal file names do not collide.
examples=/usr/share/doc/povray/examples
if [ -d "$examples" ]; then
  while IFS= read -r -d '' f; do
    rel=${f#"$examples"/}
    head -c 16384 "$f" >"$seeds/pov/example-${rel//\//-}"
  done < <(find "$examples" -name '*.pov' -print0)
fi
for inc in arrays colors consts math rand shapes strings transforms metals functions; do
  f=/usr/share/povray-3.7/include/$inc.inc
  [ -f "$f" ] && head -c 16384 "$f" >"$seeds/pov/include-$inc.inc"
done
# POV-Ray's INI files (its ini folder and the examples') and its four fonts, copied at run time too.
for f in /usr/share/povray-3.7/ini/*.ini; do [ -f "$f" ] && cp "$f" "$seeds/ini/povray-$(basename "$f")"; done
if [ -d "$examples" ]; then
  while IFS= read -r -d '' f; do
    rel=${f#"$examples"/}
    head -c 16384 "$f" >"$seeds/ini/example-${rel//\//-}"
  done < <(find "$examples" -name '*.ini' -print0)
fi
for f in /usr/share/fonts/truetype/povray/*.ttf; do [ -f "$f" ] && cp -L "$f" "$seeds/font/"; done
for t in scene obj kernel image pov ini font; do
  for f in tests/regressions/"$t"-*; do [ -e "$f" ] && cp "$f" "$seeds/$t/"; done
done

# The scene target runs in a folder holding tex.png and tiny.obj, which the seed scenes use as an
# image map and an obj_mesh.
status=0
summary=()
for t in "${targets[@]}"; do
  exe="$build/fuzz_$t"
  [ -x "$exe" ] || { echo "unknown target '$t' (scene obj kernel image pov ini font)" >&2; exit 2; }
  corpus="$build/corpus/$t"
  seedDir="$seeds/$t"
  scaleEnv=()
  if [ $scaled = 1 ]; then
    [ -d "fuzz/seeds-scaled/$t" ] || { echo "no size-scaling seeds for '$t'" >&2; exit 2; }
    corpus="$build/corpus-scaled/$t"
    seedDir="$root/fuzz/seeds-scaled/$t"
    scaleEnv=(RAYS_FUZZ_SCALE=1)
  fi
  artifacts="$build/artifacts/$t"
  work="$build/work/$t"
  log="$build/logs/$t.log"
  mkdir -p "$corpus" "$artifacts" "$work" "$build/logs"
  cp "$seeds/image/seed-16x9-c3.png" "$work/tex.png"
  cp fuzz/seeds/obj/quad-normals-uv.obj "$work/tiny.obj"
  dict=()
  [ -f "fuzz/dict/$t.dict" ] && dict=(-dict="$root/fuzz/dict/$t.dict")
  # pov: #debug text goes to stderr, closed (libFuzzer and sanitizer reports still reach the log); inputs
  # at most 16 KB like the seeds (the deep-nesting regression inputs are longer and load truncated).
  extra=()
  [ "$t" = pov ] && extra=(-close_fd_mask=2 -max_len=16384)
  # font: whole fonts (POV-Ray's are 20-40 KB).
  [ "$t" = font ] && extra=(-max_len=65536)
  mode=""
  if [ $scaled = 1 ]; then
    extra+=(-max_len=4096)
    log="$build/logs/$t-scaled.log"
    mode=" (size-scaling mode)"
  fi
  echo "== fuzz_$t for ${secs}s$mode (log: $log)" >&2
  set +e
  (cd "$work" && env "${scaleEnv[@]}" TMPDIR=${TMPDIR:-/tmp} nice -n 10 "$exe" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$artifacts/" "${dict[@]}" "${extra[@]}" ${FUZZ_FLAGS:-} "$corpus" "$seedDir") \
      </dev/null >"$log" 2>&1
  rc=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  units=$(find "$corpus" -type f | wc -l)
  if [ $rc -eq 0 ]; then
    verdict="clean"
  else
    verdict="FINDING (exit $rc): $(grep -m1 -E 'ERROR: |runtime error|==ERROR|SUMMARY' "$log" || echo 'see log')"
    status=1
  fi
  summary+=("fuzz_$t$mode: ${secs}s, ${runs:-?} executions, corpus $units files: $verdict")
done

echo "== summary" >&2
printf '%s\n' "${summary[@]}"
exit $status
