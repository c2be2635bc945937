#include "mpi_summary.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>

#include "mpi_session.h"

namespace rays::cli::mpi {
namespace {

std::string format(const char* fmt, double a) {
    char text[64];
    std::snprintf(text, sizeof text, fmt, a);
    return text;
}

// "load balance (slowest / mean busy) 1.12": 1 is perfect.
std::string balanceText(const std::vector<RankFigures>& ranks) {
    double sum = 0, slowest = 0;
    for (const RankFigures& r : ranks) sum += r.busy, slowest = std::max(slowest, r.busy);
    const double mean = ranks.empty() ? 0 : sum / double(ranks.size());
    return format("load balance (slowest / mean busy) %.2f", mean > 0 ? slowest / mean : 1.0);
}

}  // namespace

std::vector<RankFigures> gatherFigures(const RankFigures& mine) {
    std::vector<RankFigures> all(rank() == 0 ? size_t(size()) : 0);
    MPI_Gather(&mine, sizeof mine, MPI_BYTE, all.data(), sizeof mine, MPI_BYTE, 0, MPI_COMM_WORLD);
    return all;
}

std::string summaryLine(const std::vector<RankFigures>& ranks, const JobPhases& p, int hosts, int frames,
                        double wallSeconds) {
    std::string line = "rays: mpi: " + std::to_string(ranks.size()) + " ranks on " + std::to_string(hosts) +
                       (hosts == 1 ? " host" : " hosts");
    if (frames >= 0) line += ", " + std::to_string(frames) + (frames == 1 ? " frame" : " frames") + format(" in %.2f s", wallSeconds);
    line += format(": parse+build %.2f s", p.parseBuild) + format(", render %.2f s", p.render);
    if (p.gather >= 0) line += format(" (gather %.2f s)", p.gather);
    line += format(", write %.2f s", p.write);
    if (frames >= 0) line += " (summed over ranks)";
    line += "; Mrays/s per rank";
    for (const RankFigures& r : ranks) line += format(" %.2f", r.busy > 0 ? r.rays / r.busy * 1e-6 : 0.0);
    return line + "; " + balanceText(ranks);
}

}  // namespace rays::cli::mpi
