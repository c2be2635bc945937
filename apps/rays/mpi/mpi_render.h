// The single-pass render spread over all MPI ranks: rank 0 hands out bands of tiles (one row of
// 16-pixel tiles each) on request, renders bands itself while it waits, and gathers the pixels.
// Every pixel is computed by the same function as in a one-process render (TileRenderer), so the
// image is byte-identical for any number of ranks and threads. Compiled only with RAYS_MPI.
#pragma once
#include "rays/accel/bvh.h"
#include "rays/image/image.h"
#include "rays/render/renderer.h"
#include "rays/scene/scene.h"
#include "mpi_summary.h"

namespace rays::cli::mpi {

/// What the ranks did in a shared render, on rank 0.
struct ShareFigures {
    std::vector<RankFigures> ranks;  ///< parse+build, busy time and rays of each rank
    double gatherSeconds = 0;        ///< rank 0's time receiving and copying the other ranks' bands
};

/// Renders the image (settings.aaEdges must be off) on every rank; all ranks call it with the
/// same scene and settings. Rank 0 returns the whole image, receives every rank's counters in
/// stats and the ranks' figures in share; other ranks return an empty image. progress is called
/// on rank 0 only, and so is onRows (as for render(): rows [y0, y1) of the image are final; called
/// once per band, from rank 0's render thread or its main thread, as the band lands). After a
/// signal the image is incomplete (the caller checks interrupted()).
ImageF renderDistributed(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, double parseBuildSeconds,
                         TraceStats& stats, const ProgressFn& progress, const RowsFn& onRows, ShareFigures& share);

}  // namespace rays::cli::mpi
