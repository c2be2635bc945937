#include "rays/render/radiosity_pretrace.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "rays/render/renderer.h"
#include "rays/render/sampler.h"

namespace rays {
namespace {

/// Seeds the pretrace's random numbers apart from the final pass's camera samples.
constexpr uint32_t kPretraceSample = 0x52414400u;

/// The blocks of a pass are traced in batches of 1, 2, 4, ... up to this many; each batch sees the
/// records of the batches before it (the deeper radiosity levels are mostly found by the first ones).
constexpr int kMaxBatch = 256;

/// Traces the camera rays of blocks [first, last) of a pass (step × step pixel blocks, bx across)
/// and adds the records each made to cache, in block order.
void pretraceBatch(const Tracer& tracer, const ViewSetup& view, const RenderSettings& s, int step, int bx, int pass,
                   int first, int last, IrradianceCache& cache) {
    std::vector<std::vector<IrradianceRecord>> made(size_t(last - first));
    std::vector<TraceContext> contexts(size_t(resolveThreads(s.threads)));
    for (TraceContext& c : contexts) c.radPretrace = true;
    const std::function<void(int, int)> block = [&](int i, int worker) {
        const int k = first + i;
        const int px = std::min(s.width - 1, (k % bx) * step + step / 2);
        const int py = std::min(s.height - 1, (k / bx) * step + step / 2);
        TraceContext& ctx = contexts[size_t(worker)];
        ctx.rng = SampleRng(uint32_t(px), uint32_t(py), kPretraceSample + uint32_t(pass), s.seed);
        const Ray ray = cameraRayAt(view, px + 0.5, py + 0.5, s.width, s.height);
        if (CameraRays::missed(ray)) return;
        tracer.tracePrimary(ray, ctx);
        made[size_t(i)] = ctx.radLocal;
    };
    rays::parallelFor(last - first, s.threads, block);
    for (const std::vector<IrradianceRecord>& records : made)
        for (const IrradianceRecord& r : records) cache.add(r);
}

}  // namespace

void pretraceRadiosity(Tracer& tracer, const Scene& scene, const ViewSetup& view, const RenderSettings& s,
                       IrradianceCache& cache) {
    const PovRadiosity& rad = scene.pov.radiosity;
    if (!scene.pov.enabled || !rad.enabled) return;
    const double maxBound = rad.errorBound * std::max(1.0, rad.lowErrorFactor);
    tracer.setRadiosityCache(&cache);
    const double end = std::max(rad.pretraceEnd, 1e-6);
    double size = std::max(rad.pretraceStart, end);
    for (int pass = 0;; ++pass) {
        const int step = std::max(1, int(std::lround(size * s.width)));
        const int bx = (s.width + step - 1) / step, blocks = bx * ((s.height + step - 1) / step);
        for (int first = 0, batch = 1; first < blocks; first += batch, batch = std::min(2 * batch, kMaxBatch)) {
            pretraceBatch(tracer, view, s, step, bx, pass, first, std::min(blocks, first + batch), cache);
            cache.build(maxBound);
        }
        if (step == 1 || size / 2 < end * (1 - 1e-9)) break;
        size /= 2;
    }
}

}  // namespace rays
