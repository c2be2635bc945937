// POV-Ray's layered and patterned textures as the tracer evaluates them (POV-Ray 3.7 reference,
// "Layered Textures", "Patterned Textures", "Texture Maps"): flat, immutable tables built with the
// scene. A layered texture is a run of layers, each a plain texture with its own pigment, normal
// and finish; a patterned texture is a pattern choosing among textures (layered or patterned
// again). Objects with a plain texture do not use these tables (PovSurface::texture is -1).
#pragma once
#include <vector>

#include "rays/math/vec3.h"
#include "rays/scene/pov_surface.h"

namespace rays {

/// One plain texture of a layered or patterned texture: its surface (finish, pigment root, normal
/// root, the pigment's transmit; interior and object flags as the object's) and flat colour.
struct PovLayer {
    PovSurface surface;
    Vec3 color;         ///< the pigment's flat rgb (its mean colour when surface.pigment >= 0)
    double filter = 0;  ///< the flat pigment's filter (its transmit is surface.transmit)
};

/// A texture of the table: layers, or a pattern choosing among textures.
struct PovTextureNode {
    /// -1: layers [begin, begin + count) of PovTextures::layers, the top one first. Otherwise a
    /// root of Scene::pigments whose node's pattern and map place choose among the textures
    /// PovTextures::children[begin, begin + count) (map entry i ↔ child i; a block pattern's
    /// index i ↔ child i; an average weighs them all by the map's values).
    int pattern = -1;
    int begin = 0, count = 0;
};

struct PovTextures {
    std::vector<PovTextureNode> nodes;  ///< referenced by PovSurface::texture
    std::vector<PovLayer> layers;
    std::vector<int> children;  ///< nodes chosen by patterns
};

}  // namespace rays
