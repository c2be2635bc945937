#include "mpi_lost_rank.h"

#include <mpi.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "../interrupt.h"
#include "mpi_session.h"

namespace rays::cli::mpi {
namespace {

// One rank of this host: its world rank, process id and flag in the shared window.
struct Neighbour {
    int rank = 0;
    pid_t pid = 0;
    volatile char* ending = nullptr;
};

std::vector<Neighbour> neighbours;  // sorted by rank, this rank included; fixed after the start
volatile char* myFlag = nullptr;
std::atomic<bool> announced{false};
char prefix[40], suffix[200];  // "rays: rank " and " on HOST died ...\n", made at the start

bool gone(const Neighbour& n) { return ::kill(n.pid, 0) == -1 && errno == ESRCH; }

// Async-signal-safe output of "prefix R suffix".
void announce(int r) {
    char digits[16];
    int n = 0;
    do digits[n++] = char('0' + r % 10), r /= 10;
    while (r > 0 && n < 16);
    char line[280];
    size_t len = 0;
    for (const char* p = prefix; *p; ++p) line[len++] = *p;
    while (n > 0) line[len++] = digits[--n];
    for (const char* p = suffix; *p && len < sizeof line; ++p) line[len++] = *p;
    ssize_t ignored = ::write(STDERR_FILENO, line, len);
    (void)ignored;
}

// True when no live neighbour has a lower rank than this one: this rank speaks for the host.
bool speaksForHost() {
    for (const Neighbour& n : neighbours) {
        if (n.rank == rank()) return true;
        if (!gone(n)) return false;
    }
    return true;
}

// The signal hook: names a neighbour that died; the interrupt messages are left to rank 0.
bool onSignal(int) {
    const int saved = errno;
    markEnding();
    const int lost = lostRankOnThisHost();
    if (lost >= 0 && speaksForHost() && !announced.exchange(true)) announce(lost);
    errno = saved;
    return lost >= 0 || rank() != 0;
}

}  // namespace

void watchForLostRanks() {
    if (size() < 2) return;
    MPI_Comm host;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &host);
    int hostSize = 0;
    MPI_Comm_size(host, &hostSize);
    char* base = nullptr;
    MPI_Win win;
    MPI_Win_allocate_shared(1, 1, MPI_INFO_NULL, host, &base, &win);
    *base = 0;
    std::vector<int> ranks(size_t(hostSize), 0);
    const int me = rank();
    MPI_Allgather(&me, 1, MPI_INT, ranks.data(), 1, MPI_INT, host);
    for (int i = 0; i < hostSize; ++i) {
        MPI_Aint bytes = 0;
        int unit = 0;
        char* flag = nullptr;
        MPI_Win_shared_query(win, i, &bytes, &unit, &flag);
        neighbours.push_back({ranks[size_t(i)], pid_t(pidOf(ranks[size_t(i)])), flag});
        if (ranks[size_t(i)] == me) myFlag = flag;
    }
    MPI_Barrier(host);  // every flag is cleared before anyone may look
    std::snprintf(prefix, sizeof prefix, "rays: rank ");
    std::snprintf(suffix, sizeof suffix, " on %s died (killed by a signal, crashed or out of memory); stopping all %d ranks\n",
                  hostName().c_str(), size());
    // The window and the communicator live as long as the process: MPI_Finalize releases them.
    setSignalHook(onSignal);
}

void markEnding() {
    if (myFlag) *myFlag = 1;
}

int lostRankOnThisHost() {
    for (const Neighbour& n : neighbours)
        if (n.rank != rank() && !*n.ending && gone(n)) return n.rank;
    return -1;
}

void dieIfTestAsks() {
    const char* r = std::getenv("RAYS_TEST_MPI_DIE_RANK");
    if (r && std::atoi(r) == rank()) ::raise(SIGKILL);
}

}  // namespace rays::cli::mpi
