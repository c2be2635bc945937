// Feature lines over a rendered image: line coverage per pixel by the stencil or the image method,
// and compositing.
#pragma once
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/accel/huge_pages.h"
#include "rays/image/image.h"
#include "rays/npr/edge_classify.h"
#include "rays/npr/edge_settings.h"
#include "rays/npr/surfaces.h"
#include "rays/render/renderer.h"

namespace rays {

/// Line coverage in [0, 1] per pixel, top row first.
struct LineCoverage {
    int width = 0, height = 0;
    std::vector<float, tribvh::HugePageAllocator<float>> coverage;  ///< big: huge pages
    float at(int x, int y) const { return coverage[size_t(y) * size_t(width) + size_t(x)]; }
    /// No line anywhere.
    static LineCoverage empty(int w, int h) {
        LineCoverage lc;
        lc.width = w;
        lc.height = h;
        lc.coverage.assign(size_t(w) * size_t(h), 0.0f);
        return lc;
    }
};

/// True when the records render() collects can serve as pixel-centre records for the lines.
bool renderRecordsAreCentred(const Scene& scene, const RenderSettings& s);

/// Pixel-centre hit records for the lines, compacted; filled by store() (from render()'s
/// onRecord) or by drawFeatureLines itself.
struct LineRecords {
    SurfaceIds ids;
    int width = 0, height = 0;
    using RecordVector = std::vector<EdgeRecord, tribvh::HugePageAllocator<EdgeRecord>>;  // no zero fill
    RecordVector rec;  ///< top row first; every entry is written by store()
    LineRecords(const Scene& scene, int w, int h);
    /// With the scene's surface ids already computed (computeSurfaceIds).
    LineRecords(SurfaceIds surfaceIds, int w, int h);
    void store(int x, int y, const PathInfo& info) { rec[size_t(y) * size_t(width) + size_t(x)] = toEdgeRecord(info, ids); }
};

/// Probes the centre ray of every pixel into out, as drawFeatureLines does without records (for
/// callers that need the records afterwards: the edgetype AOV). stats receives the rays cast.
void probeLineRecords(const Scene& scene, const Bvh& bvh, const RenderSettings& s, const EdgeSettings& e,
                      LineRecords& out, TraceStats& stats);

/// Computes the lines. centre: records of the pixel centres, or null to probe them here.
/// stats receives the rays cast.
LineCoverage drawFeatureLines(const Scene& scene, const Bvh& bvh, const RenderSettings& s, const EdgeSettings& e,
                              const LineRecords* centre, TraceStats& stats);

/// Blends the line colour over img by coverage; with linesOnly the image starts white.
void compositeLines(ImageF& img, const LineCoverage& lines, const EdgeSettings& e, int threads = 0);

/// The coverage as an 8-bit greyscale image (255 = full line).
Image8 coverageImage(const LineCoverage& lines);

}  // namespace rays
