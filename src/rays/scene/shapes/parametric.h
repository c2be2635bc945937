// POV-Ray's parametric (reference 3.4.5.1.9 "Parametric"): the surface (f1(u, v), f2(u, v), f3(u,
// v)) over u1 ≤ u ≤ u2, v1 ≤ v ≤ v2, kept inside its contained_by box or sphere. Rays draws it
// as a mesh: a grid of kParametricGrid × kParametricGrid pieces over the (u, v) rectangle, each two
// triangles, their normals dP/du × dP/dv at the corners (central differences) interpolated, the
// pieces with a corner outside the container left out. POV-Ray instead finds the exact surface to
// `accuracy` by subdividing (u, v) with `max_gradient`; both are read and change nothing here, as
// is `precompute`. The functions run on the function machine (u is x, v is y, z is 0).
#pragma once
#include <memory>

#include "rays/scene/mesh.h"

namespace rays {

namespace fn {
struct Program;
}

/// Grid pieces along u and along v.
constexpr int kParametricGrid = 192;

struct ParametricSpec {
    std::shared_ptr<const fn::Program> f[3];
    double u1 = 0, v1 = 0, u2 = 1, v2 = 1;
    bool sphere = false;       ///< contained_by sphere { centre, radius }, else box { lo, hi }
    Vec3 lo{-1, -1, -1}, hi{1, 1, 1};
    Vec3 centre;
    double radius = 1;
};

/// Fills the mesh (positions, normals, uvs (u, v); not finalized) with the surface's triangles.
void tessellateParametric(const ParametricSpec& spec, Mesh& mesh);

}  // namespace rays
