#include "mpi_session.h"

#include <mpi.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace rays::cli::mpi {
namespace {

bool running = false;
int worldRank = 0, worldSize = 1;

// Variables set by the launchers: Open MPI's mpirun, PMIx and PMI (MPICH, Slurm's srun --mpi=...).
bool launchedByMpi() {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
        if (std::getenv(v)) return true;
    return false;
}

}  // namespace

void start(int* argc, char*** argv) {
    if (!launchedByMpi()) return;
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &worldRank);
    MPI_Comm_size(MPI_COMM_WORLD, &worldSize);
    running = true;
}

int finish(int status) {
    if (!running) return status;
    if (status != 0 && worldSize > 1) {
        std::fprintf(stderr, "rays: rank %d on %s failed (exit status %d); stopping all %d ranks\n", worldRank,
                     hostName().c_str(), status, worldSize);
        MPI_Abort(MPI_COMM_WORLD, status);
    }
    MPI_Finalize();
    running = false;
    return status;
}

int rank() { return worldRank; }

int size() { return worldSize; }

std::string hostName() {
    char name[256] = "";
    gethostname(name, sizeof name - 1);
    return name;
}

}  // namespace rays::cli::mpi
