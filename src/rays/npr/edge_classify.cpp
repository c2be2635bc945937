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

}  // namespace rays
