#include "mpi_wait.h"

#include <chrono>
#include <thread>

namespace rays::cli::mpi {

void waitGently(MPI_Request& request) {
    for (;;) {
        int done = 0;
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) return;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
}

void recvGently(void* buffer, int count, MPI_Datatype type, int source, int tag) {
    MPI_Request request;
    MPI_Irecv(buffer, count, type, source, tag, MPI_COMM_WORLD, &request);
    waitGently(request);
}

void sendGently(const void* buffer, int count, MPI_Datatype type, int destination, int tag) {
    MPI_Request request;
    MPI_Isend(buffer, count, type, destination, tag, MPI_COMM_WORLD, &request);
    waitGently(request);
}

void barrierGently() {
    MPI_Request request;
    MPI_Ibarrier(MPI_COMM_WORLD, &request);
    waitGently(request);
}

}  // namespace rays::cli::mpi
