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

uint32_t classifyPair(const PathInfo& a, const PathInfo& b, const SurfaceIds& ids, const EdgeThresholds& th) {
    const int oa = a.count > 0 ? a.ids[0] : -1, ob = b.count > 0 ? b.ids[0] : -1;
    if (oa < 0 && ob < 0) return 0;
    if (oa < 0 || ob < 0) return kEdgeSilhouette;
    uint32_t r = 0;
    const double gap = std::max(std::fabs(dot(b.point - a.point, a.normal)), std::fabs(dot(a.point - b.point, b.normal)));
    const bool depthJump = gap > 0.25 * th.depthRatio * std::min(a.t, b.t);
    const bool materialDiffers = ids.materialOf(oa) != ids.materialOf(ob);
    if (ids.surfaceOf(oa) != ids.surfaceOf(ob)) {
        r |= depthJump ? kEdgeSilhouette : (kEdgeIntersection | (materialDiffers ? kEdgeMaterial : 0u));
    } else if (depthJump) {
        r |= kEdgeOcclusion;
    } else {
        if (dot(a.normal, b.normal) < th.cosCrease) r |= kEdgeCrease;
        if (materialDiffers) r |= kEdgeMaterial;
    }
    if (a.blockedLights != b.blockedLights) r |= kEdgeShadow;
    if (a.count > 1 || b.count > 1) {
        bool differs = a.count != b.count;
        for (int i = 1; i < a.count && !differs; ++i) differs = ids.surfaceOf(a.ids[i]) != ids.surfaceOf(b.ids[i]);
        if (differs) r |= kEdgeReflection;
    }
    return r;
}

}  // namespace rays
