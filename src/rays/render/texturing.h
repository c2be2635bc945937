// Texture coordinates, tangent frames and map lookups at a hit point.
#pragma once
#include "rays/math/vec3.h"
#include "rays/scene/scene.h"

namespace rays {

/// Texture coordinates of object-space point p for a map type: 0 planar (u = x, v = y),
/// 1 spherical (u = angle from +x toward +z / 2π, v = ½ + asin(y/|p|)/π), 2 cylindrical
/// (u as spherical, v = y). Map type 3 (uv) is not handled here.
void mapCoordinates(int mapType, Vec3 p, double& u, double& v);

/// Derivatives of the object-space position with respect to u and v for a map type at p
/// (directions only; lengths are not meaningful).
void mapDerivatives(int mapType, Vec3 p, Vec3& dPdu, Vec3& dPdv);

/// Orthonormal tangent T and bitangent B around unit N: T follows dPdu projected onto the
/// tangent plane (any perpendicular when that vanishes), B = N × T turned toward dPdv.
void tangentFrame(Vec3 N, Vec3 dPdu, Vec3 dPdv, Vec3& T, Vec3& B);

/// Tangent-space normal from an 8-bit-style RGB texel (c·255 − 128)/127, +Z up.
Vec3 decodeNormal(Vec3 texel);

/// Surface parametrisation at a hit, for uv mapping (map type 3): mesh texture coordinates and
/// the object-space tangent dP/du.
struct SurfaceUV {
    bool valid = false;
    double u = 0, v = 0;
    Vec3 dpdu;
};

/// Applies the object's image map and normal or bump map at world point P with facing normal N:
/// color receives the pigment colour (unchanged without an image map), N the perturbed normal.
void applyMaps(const Scene& scene, const Object& o, Vec3 P, const SurfaceUV& uv, Vec3& color, Vec3& N);

}  // namespace rays
