// The stencil method (stencil.h) drawn band by band: a band of rows is drawn as soon as the pixel
// records it needs are present, so the lines can be drawn by the render's own threads while the
// render goes on (render()'s onRows), or all at once afterwards (finish()).
#pragma once
#include <memory>

#include "rays/accel/bvh.h"
#include "rays/npr/feature_lines.h"
#include "rays/render/settings.h"
#include "rays/render/tracer.h"
#include "rays/scene/scene.h"

namespace rays {

class StencilPass {
public:
    /// records must stay alive and, for each row reported to rowsDone, be final.
    StencilPass(const Scene& scene, const Bvh& bvh, const RenderSettings& s, const EdgeSettings& e,
                const LineRecords& records);
    ~StencilPass();
    StencilPass(const StencilPass&) = delete;
    StencilPass& operator=(const StencilPass&) = delete;

    /// Rows [y0, y1) (top row first) hold their final records. May be called from several
    /// threads at once; worker (in [0, resolveThreads(s.threads))) must be the caller's own index,
    /// as render() passes it. Draws, on the calling thread, every band whose records are now all
    /// present and that no other call has taken.
    void rowsDone(int y0, int y1, int worker);

    /// Draws the bands not drawn yet, in parallel (every record must be final by now), and
    /// returns the coverage. stats receives the rays cast by all the calls. Call once.
    LineCoverage finish(TraceStats& stats);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rays
