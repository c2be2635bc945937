// POV-Ray's bicubic_patch (reference 3.4.5.2.1 "Bicubic Patch"): the Bézier surface of 16 control
// points, drawn as POV-Ray draws it, by flat triangles with smooth normals. As measured with
// POV-Ray 3.7.0.10's trace(): the patch is cut into 2^u_steps pieces across its rows of four
// points (the second index) and 2^v_steps along them (the first), fewer where a piece is already
// flat within `flatness` (Rays' measure: the largest distance of the piece's control points from
// the bilinear surface of its corners); each piece is two triangles split along the diagonal from
// its (0, 0) corner to its (1, 1) corner, their corners on the surface, their normals the
// surface's normals at the corners interpolated; `type` 0 and 1 give the same surface. The mesh
// is an ordinary Mesh (hits, bounds, BVH); a patch has no inside.
#pragma once
#include "rays/scene/mesh.h"

namespace rays {

/// The patch's items (defaults as POV-Ray 3.7 draws a patch without them: one piece).
struct BicubicPatch {
    Vec3 points[16];  ///< as written: four rows of four
    int uSteps = 0, vSteps = 0;
    double flatness = 0;
    double uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};  ///< uv_vectors: the corners' uv (s, t) = (0,0), (1,0), (1,1), (0,1)
};

/// The patch's point at s (along a row: the first index) and t (across the rows).
Vec3 bicubicPoint(const BicubicPatch& p, double s, double t);
/// Fills the mesh (positions, normals, uvs; not finalized) with the patch's triangles.
void tessellateBicubicPatch(const BicubicPatch& p, Mesh& mesh);

}  // namespace rays
