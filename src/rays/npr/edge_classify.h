// Which edge types separate two samples' hit records.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "rays/math/vec3.h"
#include "rays/npr/edge_settings.h"
#include "rays/npr/surfaces.h"
#include "rays/render/tracer.h"

namespace rays {

struct EdgeThresholds {
    /// A depth discontinuity: one hit point lies farther than depthRatio/4 · min(t₁, t₂) from the
    /// other's tangent plane (a smooth surface stays close to its tangent plane, so grazing views
    /// of one plane never count, while a surface in front of another does).
    double depthRatio = 0.2;
    double cosCrease = 0.866; ///< normals with a smaller cosine meet at a crease
};

EdgeThresholds thresholdsFor(const EdgeSettings& e, double relax = 1.0);

/// What one sample saw, compacted for fast comparison (40 bytes).
/// Trivially constructible (large arrays of it are allocated without zero-filling); use
/// toEdgeRecord to make one.
struct EdgeRecord {
    int32_t surface;   ///< surface id of the primary hit; −1 = background
    int32_t material;  ///< material id of the primary hit
    int32_t blocked;   ///< lights blocked at the primary hit
    uint32_t path;     ///< hash of the surfaces along the secondary rays (0: none)
    float t;           ///< primary hit distance
    float p[3];        ///< primary hit point
    float n[3];        ///< primary facing normal

    Vec3 point() const { return {p[0], p[1], p[2]}; }
    Vec3 normal() const { return {n[0], n[1], n[2]}; }
};

/// Compacts a probe()/render record.
EdgeRecord toEdgeRecord(const PathInfo& info, const SurfaceIds& ids);

/// EdgeType bits that hold between records a and b.
/// - one hits nothing, the other something: silhouette
/// - different surfaces: silhouette when the depth jumps, else intersection (+ material when the
///   materials differ)
/// - same surface: occlusion when the depth jumps, else crease (normal angle) and material
/// - blocked-light counts differ: shadow; surfaces along the secondary rays differ: reflection
/// Inline: the stencil calls it 25 times per candidate pixel.
inline uint32_t classifyPair(const EdgeRecord& a, const EdgeRecord& b, const EdgeThresholds& th) {
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
