#!/usr/bin/env bash
# MPI runs that end early (docs/mpi.md "Failures"): a rank that dies without a word (the hidden,
# test-only RAYS_TEST_MPI_DIE_RANK=R makes rank R kill itself with SIGKILL as it starts its share)
# fails the run with Rays' own line naming that rank and its host, for a still and an animation;
# Ctrl-C on the launcher stops every rank. In each case the exit status is non-zero, the file
# already there stays as it was and no rank is left running.
# Usage: mpi_faults_test.sh RAYS MPIEXEC SOURCE_DIR
set -uo pipefail
rays=$1 mpiexec=$2 src=$3
. "$(dirname "$0")/mpi_launch.sh"  # Open MPI settings, `launch`, `tmp`
failures=0
host=$(hostname)
scene=$src/scenes/01-demo.pov

# left NAME: no process of this test's run (its output path is on the command line) is running.
left() { pgrep -f "$tmp/$1" >/dev/null; }

# dies NAME RANK ARGS...: rank RANK kills itself; the run must fail with the line naming it. An
# animation's frames (NAME1.png ...) may be written before the run stops; a still's NAME.png not.
dies() {
  local name=$1 r=$2
  shift 2
  echo "keep me" >"$tmp/$name.png"
  if RAYS_TEST_MPI_DIE_RANK=$r "${launch[@]}" "$rays" render "$scene" "$@" --threads 1 -o "$tmp/$name.png" 2>"$tmp/err_$name"; then
    echo "FAIL $name: exit status 0"; failures=$((failures + 1))
  elif ! grep -q "^rays: rank $r on $host died (killed by a signal, crashed or out of memory); stopping all 3 ranks\$" "$tmp/err_$name"; then
    echo "FAIL $name: no line naming rank $r on $host:"; cat "$tmp/err_$name"; failures=$((failures + 1))
  elif [ "$(grep -c '^rays: rank' "$tmp/err_$name")" != 1 ]; then
    echo "FAIL $name: not exactly one line naming a rank:"; cat "$tmp/err_$name"; failures=$((failures + 1))
  elif [ "$(cat "$tmp/$name.png")" != "keep me" ]; then
    echo "FAIL $name: the existing output was replaced"; failures=$((failures + 1))
  elif sleep 1 && left "$name"; then
    echo "FAIL $name: ranks still running"; failures=$((failures + 1))
  else
    echo "ok   $name"
  fi
}

dies still-rank1 1 320 240
dies still-rank0 0 320 240
dies frames-rank2 2 64 48 +KFF6

# Ctrl-C: SIGINT to the launcher during a long render stops every rank within seconds, exits
# non-zero and writes nothing. The render is about a minute and a half of three ranks' work on a
# quiet 2-core machine (1600x1200 --ss 3 took only 4.4 s there: the signal then came after the
# write), so the signal at 4 s always lands inside it.
echo "keep me" >"$tmp/cc.png"
"${launch[@]}" "$rays" render "$scene" 4800 3600 --ss 4 --threads 1 -o "$tmp/cc.png" 2>"$tmp/err_cc" &
pid=$!
sleep 4
kill -INT "$pid"
wait "$pid"
status=$?
if [ "$status" = 0 ] || [ "$status" = 124 ] || [ "$status" = 137 ]; then
  echo "FAIL ctrl-c: exit status $status (0: not stopped; 124/137: hung until the timeout)"; cat "$tmp/err_cc"; failures=$((failures + 1))
elif [ "$(cat "$tmp/cc.png")" != "keep me" ]; then
  echo "FAIL ctrl-c: the existing output was replaced"; failures=$((failures + 1))
elif sleep 1 && left cc.png; then
  echo "FAIL ctrl-c: ranks still running"; failures=$((failures + 1))
else
  echo "ok   ctrl-c"
fi
exit $((failures > 0))
