// Which edge types separate two samples' hit records.
#pragma once
#include <cstdint>

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

/// EdgeType bits that hold between records a and b (both from probe()).
/// - one hits nothing, the other something: silhouette
/// - different surfaces: silhouette when the depth jumps, else intersection (+ material when the
///   materials differ)
/// - same surface: occlusion when the depth jumps, else crease (normal angle) and material
/// - blocked-light counts differ: shadow; surfaces along the secondary rays differ: reflection
uint32_t classifyPair(const PathInfo& a, const PathInfo& b, const SurfaceIds& ids, const EdgeThresholds& th);

}  // namespace rays
