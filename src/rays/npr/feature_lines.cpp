#include "rays/npr/feature_lines.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "rays/npr/edge_classify.h"
#include "rays/npr/stencil_pass.h"
#include "rays/npr/surfaces.h"

namespace rays {
namespace {

constexpr int kRowBlock = 8;  // rows per parallel work item

// Probes the centre ray of every pixel.
void probeCentres(const Tracer& tracer, const Camera& camera, const RenderSettings& s, const EdgeSettings& e,
                  std::vector<TraceContext>& ctx, LineRecords& out) {
    const CameraRays cam(camera);
    const bool shadows = e.types & kEdgeShadow, secondary = e.types & kEdgeReflection;
    parallelFor((s.height + kRowBlock - 1) / kRowBlock, s.threads, [&](int block, int w) {
        PathInfo info;
        for (int y = block * kRowBlock; y < std::min(s.height, (block + 1) * kRowBlock); ++y)
            for (int x = 0; x < s.width; ++x) {
                tracer.probe(cam.rayThrough(x + 0.5, s.height - 1 - y + 0.5, s.width, s.height), shadows, secondary,
                             ctx[size_t(w)], info);
                out.store(x, y, info);
            }
    });
}

// Anti-aliased disc stamp: coverage max(·, clamp(w/2 + ½ − d, 0, 1)) around (cx, cy).
void stamp(LineCoverage& lc, double cx, double cy, double width) {
    const double reach = width / 2 + 0.5;
    const int x0 = std::max(0, int(std::floor(cx - reach))), x1 = std::min(lc.width - 1, int(std::ceil(cx + reach)));
    const int y0 = std::max(0, int(std::floor(cy - reach))), y1 = std::min(lc.height - 1, int(std::ceil(cy + reach)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
            const float c = float(std::clamp(reach - d, 0.0, 1.0));
            float& dst = lc.coverage[size_t(y) * lc.width + x];
            dst = std::max(dst, c);
        }
}

// Image method: an edge between two neighbouring pixels is stamped at their shared midpoint.
void imageLines(LineCoverage& lc, const LineRecords::RecordVector& rec, const EdgeSettings& e) {
    const EdgeThresholds th = thresholdsFor(e);
    const int W = lc.width, H = lc.height;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const EdgeRecord& p = rec[size_t(y) * W + x];
            if (x + 1 < W && (classifyPair(p, rec[size_t(y) * W + x + 1], th) & e.types))
                stamp(lc, x + 1.0, y + 0.5, e.width);
            if (y + 1 < H && (classifyPair(p, rec[size_t(y + 1) * W + x], th) & e.types))
                stamp(lc, x + 0.5, y + 1.0, e.width);
        }
}

}  // namespace

LineRecords::LineRecords(const Scene& scene, int w, int h) : LineRecords(computeSurfaceIds(scene), w, h) {}

LineRecords::LineRecords(SurfaceIds surfaceIds, int w, int h)
    : ids(std::move(surfaceIds)), width(w), height(h), rec(size_t(w) * size_t(h)) {}

bool renderRecordsAreCentred(const Scene& scene, const RenderSettings& s) {
    const Camera& cam = scene.cameras.at(size_t(s.cameraIndex));
    const double aperture = s.aperture >= 0 ? s.aperture : cam.aperture;
    return s.aa == AaMode::Grid && s.spp == 1 && aperture <= 0 && !s.aaEdges &&
           (s.shading == ShadingModel::BlinnPhong || s.shading == ShadingModel::CookTorrance);
}

void probeLineRecords(const Scene& scene, const Bvh& bvh, const RenderSettings& s, const EdgeSettings& e,
                      LineRecords& out, TraceStats& stats) {
    const Tracer tracer(scene, bvh, s);
    std::vector<TraceContext> ctx(size_t(resolveThreads(s.threads)));
    probeCentres(tracer, scene.cameras.at(size_t(s.cameraIndex)), s, e, ctx, out);
    for (const TraceContext& c : ctx) stats.add(c.stats);
}

LineCoverage drawFeatureLines(const Scene& scene, const Bvh& bvh, const RenderSettings& s, const EdgeSettings& e,
                              const LineRecords* centre, TraceStats& stats) {
    if (!e.enabled()) return LineCoverage::empty(s.width, s.height);
    std::unique_ptr<LineRecords> probed;
    if (!centre) {
        probed = std::make_unique<LineRecords>(scene, s.width, s.height);
        probeLineRecords(scene, bvh, s, e, *probed, stats);
        centre = probed.get();
    }
    if (e.method == EdgeMethod::Image) {
        LineCoverage lc = LineCoverage::empty(s.width, s.height);
        imageLines(lc, centre->rec, e);
        return lc;
    }
    return StencilPass(scene, bvh, s, e, *centre).finish(stats);
}

void compositeLines(ImageF& img, const LineCoverage& lines, const EdgeSettings& e, int threads) {
    const int rows = img.height;
    parallelFor((rows + kRowBlock - 1) / kRowBlock, threads, [&](int block, int) {
        const size_t begin = size_t(block) * kRowBlock * size_t(img.width);
        const size_t end = std::min(img.pixels.size(), begin + size_t(kRowBlock) * size_t(img.width));
        for (size_t i = begin; i < end; ++i) {
            const double c = lines.coverage[i];
            if (c == 0 && !e.linesOnly) continue;
            const Vec3 base = e.linesOnly ? Vec3(1.0) : img.pixels[i];
            img.pixels[i] = (1 - c) * base + c * e.color;
        }
    });
}

Image8 coverageImage(const LineCoverage& lines) {
    Image8 out(lines.width, lines.height, 1);
    for (size_t i = 0; i < lines.coverage.size(); ++i) out.pixels[i] = toByte(lines.coverage[i]);
    return out;
}

}  // namespace rays
