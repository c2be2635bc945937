// Renderer: turns a scene into an image, tiles rendered in parallel on a small thread pool.
#pragma once
#include <atomic>
#include <functional>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/image/image.h"
#include "rays/render/settings.h"
#include "rays/render/tracer.h"
#include "rays/scene/scene.h"

namespace rays {

/// Called from the coordinating thread about ten times a second with the fraction done (0..1).
using ProgressFn = std::function<void(double fraction)>;

/// Called, from worker threads, with a pixel's first-sample PathInfo (x right, y down from the top).
using RecordFn = std::function<void(int x, int y, const PathInfo& info)>;

/// Camera and sampling parameters resolved once per render (CLI overrides applied).
struct ViewSetup {
    Camera camera;
    CameraRays rays{Camera{}};  ///< camera's ray generator (resolveView sets both)
    double aperture = 0;       ///< lens radius; 0 = pinhole
    double focalDistance = 1;  ///< along the view direction
    int samples = 1;           ///< samples per pixel (anti-aliasing and lens together)
    const pattern::NormalTable* normals = nullptr;    ///< with camera.normal ≥ 0: the scene's normals
    const pattern::PigmentTable* patterns = nullptr;  ///< and patterns
};

/// The camera ray through sub-pixel position (px, py) of a w × h image (CameraRays::rayThrough),
/// tilted by the camera's `normal` when it has one (POV-Ray): its unit direction taken as the
/// normal of a surface at the pattern point (u, v, 0), (u, v) = (px/w − ½, py/h − ½) (v up).
Ray cameraRayAt(const ViewSetup& view, double px, double py, int w, int h);

/// Resolves the camera and the sample count from the scene and the settings.
ViewSetup resolveView(const Scene& scene, const RenderSettings& s);

/// Colour of pixel (i, j), j counted up from the bottom row, over all its samples.
/// When info is non-null it receives what the pixel's first sample saw.
Vec3 renderPixel(const Tracer& tracer, const ViewSetup& view, const RenderSettings& s, int i, int j,
                 TraceContext& ctx, PathInfo* info = nullptr);

/// Single-pass pixels tile by tile, for a driver that hands the tiles out itself (the MPI render,
/// apps/rays/mpi): each tile comes out exactly as render() makes it (without aaEdges), whatever
/// the order, thread or process. Tiles are kTileSize² pixels, numbered row by row from the top left.
class TileRenderer {
public:
    static constexpr int kTileSize = 16;
    /// Prepares the camera, the shared ray origins and the tracer; threads = resolveThreads(s.threads).
    TileRenderer(const Scene& scene, const Bvh& bvh, const RenderSettings& s);
    TileRenderer(const TileRenderer&) = delete;  // the tracer points at origins_
    TileRenderer& operator=(const TileRenderer&) = delete;
    int tilesX() const { return (s_.width + kTileSize - 1) / kTileSize; }
    int tilesY() const { return (s_.height + kTileSize - 1) / kTileSize; }
    /// Writes tile t's pixels into img, whose row 0 is image row imgY0 (top row first), from worker
    /// `worker` (< resolveThreads(s.threads)); onRecord as for render(). Tiles may run concurrently
    /// on different workers.
    void renderTile(int t, int worker, ImageF& img, int imgY0 = 0, const RecordFn& onRecord = {});
    /// The counters of all tiles rendered so far (call once no tile is running).
    TraceStats stats() const;

private:
    const RenderSettings& s_;
    ViewSetup view_;
    SharedOrigins origins_;
    Tracer tracer_;
    IrradianceCache radiosity_;  ///< POV-Ray's radiosity records (pretraced by the constructor)
    PhotonMap photons_;          ///< POV-Ray's photons (shot by the constructor)
    PhotonMap mediaPhotons_;     ///< and those left in media
    bool povOutput_;
    double assumedGamma_;
    std::vector<TraceContext> perThread_;
};

/// Renders the whole image (top row first). Scenes with Scene::pov.enabled come out as POV-Ray
/// writes them (render/pov_output.h: sRGB(c^assumed_gamma), clamped to [0, 1]); course scenes as
/// traced. Deterministic: the result is bit-identical for any thread count. stats receives the summed counters. With settings.aaEdges
/// and no lens (a lens samples every pixel in full, edgePixels all set), pass one renders
/// one centre sample per pixel and pass two supersamples only pixels whose PathInfo differs
/// from a neighbour's, or with settings.aaThreshold ≥ 0 (POV-Ray's method 1) pixels whose colour
/// differs from the left or upper neighbour's by more than the threshold, and that neighbour
/// (the difference: |Δr| + |Δg| + |Δb| of linear colours clamped to [0, 1] and raised to
/// 1/aaGamma, as POV-Ray 3.7's Antialias_Gamma); edgePixels (optional) receives that mask (row-major, top row first).
/// onRecord (optional) is called, from worker threads, with each pixel's first-sample PathInfo
/// (x right, y down from the top row); calls for different pixels may run concurrently.
/// onRows (optional, single-pass renders only: not with aaEdges) is called from the worker that
/// finishes the last tile of a row of tiles, with that worker's index and the image being made,
/// once every pixel of image rows [y0, y1) (top row first) has been rendered and recorded: work
/// that needs finished rows (the feature lines, the PNG encoder) can start on the render's own
/// threads while the render goes on. It may read those rows of the image, nothing else.
using RowsFn = std::function<void(const ImageF& img, int y0, int y1, int worker)>;
ImageF render(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, TraceStats& stats,
              const ProgressFn& progress = {}, std::vector<uint8_t>* edgePixels = nullptr,
              const RecordFn& onRecord = {}, const RowsFn& onRows = {});

/// Number of worker threads used for a requested count (0 = all hardware threads).
int resolveThreads(int requested);

/// Runs body(index, worker) for index in [0, count) on `threads` workers handing out indices
/// dynamically; progress (if set) is called from the calling thread while they run. Stops early
/// (running bodies finish, no new index starts) once the cancel flag is set, see setCancelFlag.
void parallelFor(int count, int threads, const std::function<void(int index, int worker)>& body,
                 const ProgressFn& progress = {});

/// Cancellation for the command line's Ctrl-C: while *flag is true, parallelFor starts no further
/// index, so render() and the feature lines return early and the tiles not rendered stay black
/// (the caller must not use such an image as a finished one). nullptr (the default) turns it off.
/// The flag is only read (from any thread); the caller owns it.
void setCancelFlag(const std::atomic<bool>* flag);

}  // namespace rays
