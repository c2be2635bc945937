#include "mpi_session.h"

#include <mpi.h>
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <vector>

#include "mpi_lost_rank.h"

namespace rays::cli::mpi {
namespace {

// What each rank tells the others about itself at the start.
struct PeerRecord {
    int32_t pid = 0;
    char host[60] = "";
};

bool running = false;
int worldRank = 0, worldSize = 1;
std::vector<PeerRecord> peers;

// Variables set by the launchers: Open MPI's mpirun, PMIx and PMI (MPICH, Slurm's srun --mpi=...).
bool launchedByMpi() {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
        if (std::getenv(v)) return true;
    return false;
}

void learnPeers() {
    PeerRecord mine;
    mine.pid = int32_t(getpid());
    std::snprintf(mine.host, sizeof mine.host, "%s", hostName().c_str());
    peers.resize(size_t(worldSize));
    MPI_Allgather(&mine, sizeof mine, MPI_BYTE, peers.data(), sizeof mine, MPI_BYTE, MPI_COMM_WORLD);
}

// Exit statuses of a stop by Ctrl-C or SIGTERM (interrupt.h): not a failure to name.
bool stoppedBySignal(int status) { return status == 128 + SIGINT || status == 128 + SIGTERM; }

}  // namespace

void start(int* argc, char*** argv) {
    if (!launchedByMpi()) return;
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &worldRank);
    MPI_Comm_size(MPI_COMM_WORLD, &worldSize);
    running = true;
    learnPeers();
    watchForLostRanks();
}

int finish(int status) {
    if (!running) return status;
    markEnding();  // neighbours see this rank end knowingly (mpi_lost_rank.h)
    if (status != 0 && worldSize > 1) {
        // A signal reached every rank (the launcher's answer to Ctrl-C or to a rank's death), or
        // it reached this rank alone and the launcher stops the others on this non-zero exit:
        // no MPI_Abort and its page of text.
        if (stoppedBySignal(status)) {
            std::fflush(nullptr);
            std::_Exit(status);
        }
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

std::string hostOf(int r) { return r >= 0 && size_t(r) < peers.size() ? peers[size_t(r)].host : hostName(); }

int hostCount() {
    std::set<std::string> hosts;
    for (const PeerRecord& p : peers) hosts.insert(p.host);
    return hosts.empty() ? 1 : int(hosts.size());
}

int pidOf(int r) { return r >= 0 && size_t(r) < peers.size() ? peers[size_t(r)].pid : int(getpid()); }

}  // namespace rays::cli::mpi
