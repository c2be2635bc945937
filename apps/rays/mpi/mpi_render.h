// The single-pass render spread over all MPI ranks: rank 0 hands out bands of tiles (one row of
// 16-pixel tiles each) on request, renders bands itself while it waits, and gathers the pixels.
// Every pixel is computed by the same function as in a one-process render (TileRenderer), so the
// image is byte-identical for any number of ranks and threads. Compiled only with RAYS_MPI.
#pragma once
#include "rays/accel/bvh.h"
#include "rays/image/image.h"
#include "rays/render/renderer.h"
#include "rays/scene/scene.h"

namespace rays::cli::mpi {

/// Renders the image (settings.aaEdges must be off) on every rank; all ranks call it with the
/// same scene and settings. Rank 0 returns the whole image and receives every rank's counters in
/// stats, other ranks return an empty image. progress is called on rank 0 only; with report,
/// rank 0 prints one line with each rank's busy time and ray rate and the load balance.
ImageF renderDistributed(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, TraceStats& stats,
                         const ProgressFn& progress, bool report);

}  // namespace rays::cli::mpi
