// Renderer: turns a scene into an image, tiles rendered in parallel on a small thread pool.
#pragma once
#include <functional>

#include "rays/accel/bvh.h"
#include "rays/image/image.h"
#include "rays/render/settings.h"
#include "rays/render/tracer.h"
#include "rays/scene/scene.h"

namespace rays {

/// Called from the coordinating thread about ten times a second with the fraction done (0..1).
using ProgressFn = std::function<void(double fraction)>;

/// Colour of pixel (i, j), j counted up from the bottom row, averaged over the pixel's samples.
Vec3 renderPixel(const Tracer& tracer, const Camera& camera, const RenderSettings& s, int i, int j,
                 TraceContext& ctx);

/// Renders the whole image (top row first). Deterministic: the result is bit-identical for any
/// thread count. stats receives the summed counters.
ImageF render(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, TraceStats& stats,
              const ProgressFn& progress = {});

/// Number of worker threads used for a requested count (0 = all hardware threads).
int resolveThreads(int requested);

}  // namespace rays
