// Surface and material identities for feature lines. Course scenes build meshes from separate
// triangle objects; triangles that share vertices form one surface, so a mesh draws its outline
// and creases, not every triangle edge.
#pragma once
#include <vector>

#include "rays/scene/scene.h"

namespace rays {

struct SurfaceIds {
    std::vector<int> surface;   ///< per object: connected surface id
    std::vector<int> material;  ///< per object: id of its (value-equal) material
    int surfaceOf(int object) const { return object < 0 ? -1 : surface[size_t(object)]; }
    int materialOf(int object) const { return object < 0 ? -1 : material[size_t(object)]; }
};

/// Groups triangles sharing a vertex (exact world positions) into surfaces; every other object is
/// its own surface. Materials with identical values share an id.
SurfaceIds computeSurfaceIds(const Scene& scene);

}  // namespace rays
