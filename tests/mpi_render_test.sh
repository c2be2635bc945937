#!/usr/bin/env bash
# The MPI render (docs/mpi.md) against the one-process render: `mpiexec -np 3 rays render ...`
# (one thread per rank) must write the same file, byte for byte, as `rays render ... --threads 2`,
# for plain, supersampled, jittered, filtered and feature-line renders and an animation's frames
# (handed out whole when there are at least as many frames as ranks, shared band by band when
# fewer); --resume skips the frames already written; rank 0's summary line has its shape; a
# failing run must exit non-zero and leave an existing output file alone.
# Usage: mpi_render_test.sh RAYS MPIEXEC SOURCE_DIR
set -uo pipefail
rays=$1 mpiexec=$2 src=$3
. "$(dirname "$0")/mpi_launch.sh"  # Open MPI settings, `launch`, `tmp`
failures=0

# same NAME EXT ARGS...: renders ARGS once without MPI and once on 3 ranks; the files must match.
same() {
  local name=$1 ext=$2
  shift 2
  "$rays" render "$@" -q --threads 2 -o "$tmp/one_$name.$ext" || { echo "FAIL $name: one-process render failed"; failures=$((failures + 1)); return; }
  if ! "${launch[@]}" "$rays" render "$@" --threads 1 -o "$tmp/mpi_$name.$ext" 2>"$tmp/err_$name"; then
    echo "FAIL $name: MPI render failed:"; cat "$tmp/err_$name"; failures=$((failures + 1)); return
  fi
  if ! cmp -s "$tmp/one_$name.$ext" "$tmp/mpi_$name.$ext"; then
    echo "FAIL $name: images differ"; failures=$((failures + 1)); return
  fi
  # The run was really shared: rank 0's summary names three ranks, with the phases, each rank's
  # ray rate and the load balance (its shape only: the figures depend on the machine).
  if ! grep -qE "$stillSummary" "$tmp/err_$name"; then
    echo "FAIL $name: no three-rank summary line of the expected shape:"; cat "$tmp/err_$name"; failures=$((failures + 1)); return
  fi
  echo "ok   $name"
}

n='[0-9]+\.[0-9]+'
stillSummary="^rays: mpi: 3 ranks on [0-9]+ hosts?: parse\+build $n s, render $n s \(gather $n s\), write $n s; Mrays/s per rank $n $n $n; load balance \(slowest / mean busy\) $n\$"
animSummary="^rays: mpi: 3 ranks on [0-9]+ hosts?, 5 frames in $n s: parse\+build $n s, render $n s, write $n s \(summed over ranks\); Mrays/s per rank $n $n $n; load balance \(slowest / mean busy\) $n\$"

s=$src/scenes
same plain png "$s/01-demo.pov" 160 120
same ss png "$s/02-soft-shadows.pov" 96 72 --ss 2
same spp png "$s/06-depth-of-field.pov" 80 64 --spp 4 --aa random
same lines png "$s/08-bunny-lines.pov" 120 90
same lines-image png "$s/10-shadow-lines.pov" 96 72 --edges all --edge-method image
same post png "$s/04-refraction.pov" 96 72 --post gaussian_blur_3
same jpeg jpg "$s/11-textures.pov" 96 72

# Animations. Five frames on three ranks: whole frames handed out (rank 0 names the rank that
# wrote each); two frames: each shared band by band. Frames byte-identical to one process's.
cat >"$tmp/anim.pov" <<'POV'
#version 3.7;
camera { location <0, 1, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -3> color rgb 1 }
sphere { <clock * 2 - 1, 0.5, 0>, 0.5 pigment { color rgb <1, 0.3, 0.2> } }
plane { y, 0 pigment { checker color rgb 1 color rgb 0.3 } }
POV
# frames_same ONE MPI COUNT: frames 1..COUNT of ONE and MPI are identical, 1 and COUNT differ.
frames_same() {
  local i
  for ((i = 1; i <= $3; i++)); do cmp -s "$tmp/$1$i.png" "$tmp/$2$i.png" || return 1; done
  ! cmp -s "$tmp/$2""1.png" "$tmp/$2$3.png"
}
"$rays" render "$tmp/anim.pov" 64 48 +KFF5 -q --threads 2 -o "$tmp/one_anim.png"
if ! "${launch[@]}" "$rays" render "$tmp/anim.pov" 64 48 +KFF5 --threads 1 -o "$tmp/whole.png" 2>"$tmp/err_whole"; then
  echo "FAIL animation: the MPI run failed:"; cat "$tmp/err_whole"; failures=$((failures + 1))
elif ! frames_same one_anim whole 5; then
  echo "FAIL animation: frames differ or missing"; failures=$((failures + 1))
elif [ "$(grep -cE '^rays: frame [1-5] of 5 .*: wrote .*whole[1-5]\.png on rank [0-2] in ' "$tmp/err_whole")" != 5 ]; then
  echo "FAIL animation: not one line per frame naming its rank:"; cat "$tmp/err_whole"; failures=$((failures + 1))
elif ! grep -qE "$animSummary" "$tmp/err_whole"; then
  echo "FAIL animation: no summary line of the expected shape:"; cat "$tmp/err_whole"; failures=$((failures + 1))
else
  echo "ok   animation (whole frames)"
fi
# --resume (+C): frames that exist are skipped (frame 2, made a marker, stays as it is), the
# missing ones are rendered and come out the same.
echo "keep me" >"$tmp/whole2.png"
rm -f "$tmp/whole4.png" "$tmp/whole5.png"
if ! "${launch[@]}" "$rays" render "$tmp/anim.pov" 64 48 +KFF5 +C --threads 1 -o "$tmp/whole.png" 2>"$tmp/err_resume"; then
  echo "FAIL resume: the MPI run failed:"; cat "$tmp/err_resume"; failures=$((failures + 1))
elif [ "$(cat "$tmp/whole2.png")" != "keep me" ] || ! cmp -s "$tmp/one_anim4.png" "$tmp/whole4.png" ||
     ! cmp -s "$tmp/one_anim5.png" "$tmp/whole5.png"; then
  echo "FAIL resume: an existing frame was rendered again or a missing one not rendered"; failures=$((failures + 1))
elif [ "$(grep -c 'exists; skipped (resume)' "$tmp/err_resume")" != 3 ]; then
  echo "FAIL resume: not three frames skipped:"; cat "$tmp/err_resume"; failures=$((failures + 1))
else
  echo "ok   resume"
fi
"$rays" render "$tmp/anim.pov" 64 48 +KFF2 -q --threads 2 -o "$tmp/one_shared.png"
if "${launch[@]}" "$rays" render "$tmp/anim.pov" 64 48 +KFF2 --threads 1 -o "$tmp/shared.png" 2>"$tmp/err_shared" &&
   frames_same one_shared shared 2 && [ "$(grep -c "rays: mpi: 3 ranks on" "$tmp/err_shared")" = 2 ]; then
  echo "ok   animation (frames shared band by band)"
else
  echo "FAIL animation (two frames on three ranks):"; cat "$tmp/err_shared"; failures=$((failures + 1))
fi

# A run that fails on every rank exits non-zero, and the file already there stays as it was.
echo "keep me" > "$tmp/keep.png"
if "${launch[@]}" "$rays" render "$tmp/missing.pov" 32 32 --threads 1 -o "$tmp/keep.png" >/dev/null 2>&1; then
  echo "FAIL failure: a missing scene exited 0"; failures=$((failures + 1))
elif [ "$(cat "$tmp/keep.png")" != "keep me" ]; then
  echo "FAIL failure: the existing output was replaced"; failures=$((failures + 1))
else
  echo "ok   failure"
fi
exit $((failures > 0))
