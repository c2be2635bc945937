// Arbitrary output variables (AOVs): what the pixel centres see besides their colour — depth,
// world normal, albedo, object and material ids — for compositing outside Rays (docs/aov.md).
#pragma once
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/math/vec3.h"
#include "rays/render/settings.h"
#include "rays/scene/scene.h"

namespace rays {

/// One bit per AOV that --aov can ask for.
enum AovBit : unsigned {
    kAovDepth = 1,
    kAovNormal = 2,
    kAovAlbedo = 4,
    kAovObjectId = 8,
    kAovMaterialId = 16,
    kAovCoverage = 32,  ///< feature-line coverage (computed by the lines, npr/feature_lines.h)
    kAovEdgeType = 64,  ///< EdgeType bits of the lines through a pixel (npr/edge_types.h)
};
inline constexpr unsigned kAovAll = 127;

/// Parses "depth,normal,albedo,objectid,materialid,coverage,edgetype" (any order, "all" for every one,
/// "" or "none" for none). Throws rays::Error "rays: error: unknown AOV 'X' (use ...)".
unsigned parseAovList(const std::string& list);

/// The --aov name of one bit ("depth", "normal", ...).
const char* aovName(AovBit bit);

/// Per-pixel AOVs, top row first; vectors of the AOVs not asked for stay empty. Background
/// (no hit): depth +inf, normal and albedo 0, ids −1.
struct AovBuffers {
    int width = 0, height = 0;
    std::vector<float> depth;       ///< distance from the camera along the unit ray (ray t)
    std::vector<Vec3> normal;       ///< world shading normal, outward (the object's side)
    std::vector<Vec3> albedo;       ///< surface colour before lighting (linear, as the EXR colour)
    std::vector<float> objectId;    ///< index into Scene::objects (sceneinfo's Object[i])
    std::vector<float> materialId;  ///< POV-Ray scenes: texture index; course scenes: object index
    std::vector<float> edgeType;    ///< filled by the caller (lineEdgeTypes); empty: 0 everywhere
};

/// Linear light of a POV-Ray working-space colour: max(c, 0)^assumedGamma, or for assumedGamma 0
/// (the colour written as it is) the sRGB-decoded colour. Unclamped above 1. Displayed (clamped
/// and sRGB-encoded) it is povOutputColor(c).
Vec3 povLinearColor(Vec3 c, double assumedGamma);

/// The AOVs in `kinds` of one pinhole ray through each pixel centre of camera s.cameraIndex
/// (first hit, no anti-aliasing: ids are never averaged). kAovCoverage and kAovEdgeType are not computed here.
AovBuffers computeAovs(const Scene& scene, const Bvh& bvh, const RenderSettings& s, unsigned kinds);

}  // namespace rays
