#include "rays/npr/edge_classify.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays {

EdgeThresholds thresholdsFor(const EdgeSettings& e, double relax) {
    EdgeThresholds t;
    t.depthRatio = e.depthRatio / relax;
    t.cosCrease = std::cos(e.creaseAngle / relax * std::numbers::pi / 180.0);
    return t;
}

EdgeRecord toEdgeRecord(const PathInfo& info, const SurfaceIds& ids) {
    EdgeRecord r{-1, -1, 0, 0, 0.0f, {0, 0, 0}, {0, 0, 0}};
    const int o = info.count > 0 ? info.ids[0] : -1;
    if (o < 0) return r;
    r.surface = ids.surfaceOf(o);
    r.material = ids.materialOf(o);
    r.blocked = info.blockedLights;
    uint32_t h = 0;
    for (int i = 1; i < info.count; ++i) h = h * 0x9E3779B1u + uint32_t(ids.surfaceOf(info.ids[i]) + 2);
    r.path = info.count > 1 ? (h ^ uint32_t(info.count)) | 1u : 0u;
    r.t = info.t;
    for (int k = 0; k < 3; ++k) {
        r.p[k] = info.point[k];
        r.n[k] = info.normal[k];
    }
    return r;
}

uint32_t classifyPair(const EdgeRecord& a, const EdgeRecord& b, const EdgeThresholds& th) {
    if (a.surface < 0 && b.surface < 0) return 0;
    if (a.surface < 0 || b.surface < 0) return kEdgeSilhouette;
    uint32_t r = 0;
    const float dx = b.p[0] - a.p[0], dy = b.p[1] - a.p[1], dz = b.p[2] - a.p[2];
    const float gap = std::max(std::fabs(dx * a.n[0] + dy * a.n[1] + dz * a.n[2]),
                               std::fabs(dx * b.n[0] + dy * b.n[1] + dz * b.n[2]));
    const bool depthJump = gap > float(0.25 * th.depthRatio) * std::min(a.t, b.t);
    const bool materialDiffers = a.material != b.material;
    if (a.surface != b.surface) {
        r |= depthJump ? kEdgeSilhouette : (kEdgeIntersection | (materialDiffers ? kEdgeMaterial : 0u));
    } else if (depthJump) {
        r |= kEdgeOcclusion;
    } else {
        if (a.n[0] * b.n[0] + a.n[1] * b.n[1] + a.n[2] * b.n[2] < float(th.cosCrease)) r |= kEdgeCrease;
        if (materialDiffers) r |= kEdgeMaterial;
    }
    if (a.blocked != b.blocked) r |= kEdgeShadow;
    if (a.path != b.path) r |= kEdgeReflection;
    return r;
}

}  // namespace rays
