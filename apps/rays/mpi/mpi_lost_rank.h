// Naming a rank that died without a word (killed by a signal, crashed, killed for lack of memory).
// Open MPI's launcher answers such a death by sending SIGTERM to every other rank (and SIGKILL
// about a second later); Ctrl-C on the launcher does the same. The ranks of one host share a
// small MPI window with one "ending knowingly" flag each, set by a rank before it ends for any
// reason Rays knows of (done, an error, a signal). When a signal arrives, the lowest live rank of
// the host looks at its neighbours: a process that is gone without its flag died, and that rank
// prints "rays: rank R on HOST died (killed by a signal, crashed or out of memory); stopping all N
// ranks". A whole host lost leaves no neighbour to tell: the launcher's own message names it.
#pragma once

namespace rays::cli::mpi {

/// At the start (collective over all ranks): shares the flags of this host's ranks and installs
/// the signal hook (interrupt.h). Does nothing for one rank.
void watchForLostRanks();

/// This rank ends knowingly (called on every way out; async-signal-safe).
void markEnding();

/// A rank of this host that is gone without having set its flag, or -1 (async-signal-safe).
int lostRankOnThisHost();

/// For the tests only (tests/mpi_render_test.sh): with RAYS_TEST_MPI_DIE_RANK=R in the
/// environment, rank R kills itself with SIGKILL when called (as it starts its share of a render).
void dieIfTestAsks();

}  // namespace rays::cli::mpi
