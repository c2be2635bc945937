// MPI for the whole process, started only when a launcher (mpirun, mpiexec, srun) started the
// process: run by hand, rays never touches MPI. Compiled only with the CMake option RAYS_MPI.
#pragma once
#include <string>

namespace rays::cli::mpi {

/// Starts MPI (MPI_THREAD_FUNNELED: only the main thread calls MPI) when the environment shows a
/// launcher, and learns every rank's host and process id (one MPI_Allgather); otherwise does
/// nothing and the process is one rank of one.
void start(int* argc, char*** argv);

/// Ends MPI: MPI_Finalize after status 0; after a failure with other ranks running, MPI_Abort so
/// that the launcher stops every rank (a failure other than a signal is named first: "rays: rank R
/// on HOST failed (exit status S); stopping all N ranks"). Returns status.
int finish(int status);

/// This process's rank (0 without MPI).
int rank();

/// The number of ranks (1 without MPI).
int size();

/// The host this rank runs on (for messages).
std::string hostName();

/// The host rank r runs on, as it named itself at the start.
std::string hostOf(int r);

/// The number of distinct hosts the ranks run on.
int hostCount();

/// The process id of rank r.
int pidOf(int r);

}  // namespace rays::cli::mpi
