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
};

/// Compacts a probe()/render record.
EdgeRecord toEdgeRecord(const PathInfo& info, const SurfaceIds& ids);

/// EdgeType bits that hold between records a and b.
/// - one hits nothing, the other something: silhouette
/// - different surfaces: silhouette when the depth jumps, else intersection (+ material when the
///   materials differ)
/// - same surface: occlusion when the depth jumps, else crease (normal angle) and material
/// - blocked-light counts differ: shadow; surfaces along the secondary rays differ: reflection
uint32_t classifyPair(const EdgeRecord& a, const EdgeRecord& b, const EdgeThresholds& th);

}  // namespace rays
