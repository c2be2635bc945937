// Feature-line (edge) settings: which edge types, which method, and how lines look.
#pragma once
#include <cstdint>
#include <string>

#include "rays/math/vec3.h"

namespace rays {

/// Edge types, combinable as a bit mask.
enum EdgeType : uint32_t {
    kEdgeSilhouette = 1u << 0,    ///< object against the background or against another object
    kEdgeOcclusion = 1u << 1,     ///< self-occlusion: a depth discontinuity on one surface
    kEdgeIntersection = 1u << 2,  ///< where two surfaces intersect (different surfaces, continuous depth)
    kEdgeCrease = 1u << 3,        ///< normals on one surface differ by more than the crease angle
    kEdgeMaterial = 1u << 4,      ///< material changes on one surface or across an intersection
    kEdgeShadow = 1u << 5,        ///< the number of blocked lights changes
    kEdgeReflection = 1u << 6,    ///< the surfaces seen in reflections / refractions change
    kEdgeAll = (1u << 7) - 1,
};

enum class EdgeMethod {
    Stencil,  ///< a disc of rays around each camera ray (Choudhury & Parker 2009), anti-aliased by strength
    Image,    ///< per-pixel hit records compared with neighbours, lines stamped as anti-aliased discs
};

struct EdgeSettings {
    uint32_t types = 0;          ///< EdgeType mask; 0 = no lines
    EdgeMethod method = EdgeMethod::Stencil;
    double width = 1.5;          ///< line width in pixels (0.5 to 8): ink across the line
    Vec3 color{0, 0, 0};         ///< line colour
    double creaseAngle = 30;     ///< degrees
    bool linesOnly = false;      ///< lines on white, no shading
    double depthRatio = 0.2;     ///< depth discontinuity: tangent-plane gap > depthRatio/4 · distance
    bool enabled() const { return types != 0; }
};

/// Parses "silhouette,crease,..." | "all" | "none" into a mask; throws Error naming bad names.
uint32_t parseEdgeTypes(const std::string& list);

/// The edge type names, in bit order ("silhouette", "occlusion", ...).
const char* edgeTypeName(int bit);

/// Throws Error when a value is out of range (width, crease angle).
void validateEdgeSettings(const EdgeSettings& e);

}  // namespace rays
