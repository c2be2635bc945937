// Waiting for MPI without spinning. Open MPI's blocking calls (MPI_Recv, MPI_Send of a large
// message, the collectives) poll without pause, so a rank waiting for its next band, or for the
// slowest rank at the end, would take a core from the render threads of its node (or, ranks
// sharing a machine, from the other ranks). These wait by testing the request and sleeping
// 200 µs between tests: a delay far below a band's or a frame's render time.
#pragma once
#include <mpi.h>

namespace rays::cli::mpi {

/// Waits for request to complete, sleeping between tests.
void waitGently(MPI_Request& request);

/// MPI_Recv, waiting gently.
void recvGently(void* buffer, int count, MPI_Datatype type, int source, int tag);

/// MPI_Send, waiting gently (for a large message, until rank `destination` has taken it).
void sendGently(const void* buffer, int count, MPI_Datatype type, int destination, int tag);

/// MPI_Barrier over all ranks, waiting gently: the ranks that finish first sleep.
void barrierGently();

}  // namespace rays::cli::mpi
