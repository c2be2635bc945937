# Sourced by the MPI test scripts (mpi_render_test.sh, mpi_faults_test.sh) after they set
# $mpiexec: Open MPI's settings for this machine and CI, the bounded launcher command in `launch`,
# and a temporary folder `tmp` removed on exit.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI containers run as root
# In containers the shared-memory transport cannot attach to other processes (ptrace is denied).
export OMPI_MCA_btl_vader_single_copy_mechanism=${OMPI_MCA_btl_vader_single_copy_mechanism:-none}
# Ranks waiting for work yield the core instead of spinning (the suite runs tests side by side).
export OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-1}
# Every launch is bounded: a hang (seen once under heavy load, all ranks already gone) fails the
# test after 3 minutes instead of holding the suite until ctest's timeout.
launch=(timeout -k 10 180 "$mpiexec" -np 3)
"$mpiexec" --version 2>&1 | grep -qiE "open ?mpi|openrte" && launch+=(--oversubscribe)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
