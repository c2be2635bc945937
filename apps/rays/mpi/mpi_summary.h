// The one line rank 0 prints at the end of an MPI job (docs/mpi.md): the time of each phase,
// each rank's ray rate and the load balance (the slowest rank's busy time over the mean).
#pragma once
#include <string>
#include <vector>

namespace rays::cli::mpi {

/// One rank's share of the job, in seconds (rays: rays traced).
struct RankFigures {
    double parseBuild = 0;  ///< loading the scene and building the BVH
    double render = 0;      ///< rendering
    double write = 0;       ///< encoding and writing files
    double busy = 0;        ///< working on its share (a still: rendering bands; an animation: its frames)
    double rays = 0;
};

/// Gathers every rank's figures on rank 0 (collective): rank 0 gets them in rank order, the
/// other ranks an empty vector.
std::vector<RankFigures> gatherFigures(const RankFigures& mine);

/// The phases as the line shows them, in seconds; gather < 0 leaves the gather out.
struct JobPhases {
    double parseBuild = 0, render = 0, gather = -1, write = 0;
};

/// "rays: mpi: 3 ranks on 1 host: parse+build 0.09 s, render 0.66 s (gather 0.01 s), write 0.02 s;
/// Mrays/s per rank 0.74 0.86 1.51; load balance (slowest / mean busy) 1.12"; an animation
/// (frames >= 0) says "3 ranks on 1 host, 5 frames in 1.52 s:" and its phases are summed over all
/// frames of all ranks.
std::string summaryLine(const std::vector<RankFigures>& ranks, const JobPhases& phases, int hosts, int frames = -1,
                        double wallSeconds = 0);

}  // namespace rays::cli::mpi
