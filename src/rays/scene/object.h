// A scene object: one analytic shape in object space, an optional affine transform, a material.
#pragma once
#include <cstdint>
#include <string_view>

#include "rays/error.h"
#include "rays/geometry/ray.h"
#include "rays/math/transform.h"
#include "rays/scene/material.h"

namespace rays {

enum class ShapeType : unsigned char { Sphere, Plane, Triangle, Box, Cone, Mesh, Csg, Text,
    Torus, Disc, Polygon, Poly, Superellipsoid, Prism, Blob, Lathe, Sor, SphereSweep, Isosurface, HeightField, JuliaFractal, Ovus };  // scene/shapes/*.h

struct Mesh;
struct Csg;
struct TextShape;
struct ShapeData;

/// Name used in course output ("Sphere", "Plane", "Triangle", "Box", "Cone", "Mesh", "CSG", "Text", "Torus", …).
std::string_view shapeName(ShapeType t);

struct Object {
    ShapeType type = ShapeType::Sphere;
    // Shape parameters as written, in object space:
    //   Sphere   p0 centre, r0 radius          Plane  p0 unit normal, r0 distance (n·x = d)
    //            (p1, r1: the sphere actually intersected — in world space when the transform
    //            is a similarity, so the ray needs no mapping — set by prepareObject)
    //   Triangle p0 p1 p2 vertices             Box    p0 min corner, p1 max corner
    //   Cone     p0 base, r0 base radius, p1 cap, r1 cap radius (closed by flat caps unless open)
    //   Csg      csg: the tree, its leaves in world space (no transform of its own)
    //   Torus, Disc, Polygon, Poly: see their headers in scene/shapes
    Vec3 p0, p1, p2;
    double r0 = 0, r1 = 0;
    bool smooth = false;  ///< Triangle: interpolate the vertex normals n0, n1, n2; HeightField: its grid's
    Vec3 n0, n1, n2;
    bool open = false;    ///< Cone, Prism and Sor: no caps (POV-Ray's `open`)
    const Mesh* mesh = nullptr;  ///< Mesh only: the geometry (owned by the Scene)
    const Csg* csg = nullptr;    ///< Csg only: the tree (owned by the Scene)
    const TextShape* text = nullptr;  ///< Text only: the glyph outlines, in object space (owned by the Scene)
    const ShapeData* data = nullptr;  ///< Polygon, Poly, Prism, Blob, Lathe, Sor, SphereSweep, Isosurface, HeightField, JuliaFractal, Ovus: their numbers (owned by the Scene)
    Material material;
    bool transformed = false;  ///< a transform was written (the course prints the object-space ray)
    bool localSpace = false;   ///< rays are mapped through toObject before intersecting
    /// World → intersection space. M⁻¹ for transformed objects; for cones it also maps object space
    /// to the canonical cone frame (axis along z from 0 to the height). Identity otherwise.
    Transform toObject;
    int line = 0, col = 0;  ///< where the object starts in the scene file
};

/// Sets the transform from the file's M (object → world) and derives the intersection data
/// (cone frame). Call once the shape parameters are final.
void prepareObject(Object& o, const Transform& objectToWorld);

/// True when rays must be mapped through toObject before intersecting.
inline bool usesLocalSpace(const Object& o) { return o.localSpace; }

/// World-space bounds; empty for planes (unbounded).
Bounds worldBounds(const Object& o);

/// A world-space sphere (centre, radius) holding every point of o, or false when o is unbounded.
/// The sphere round its transformed box, or tighter where the shape's own sphere is (torus, sphere).
bool worldBoundingSphere(const Object& o, Vec3& centre, double& radius);

/// Object hit record: t along the ray, the outward world-space unit shading normal and the
/// geometric normal (they differ only for smooth triangles and meshes; both on the same side),
/// and for meshes with texture coordinates the uv and the object-space tangent dP/du; for CSG
/// objects the leaf hit (its material and texture space).
/// A hit on a mesh face textured per vertex (mesh2, three texture indices after a face): the
/// face (its corners' textures are ShapeData::cornerParts of the hit part's data) and the
/// barycentric weights of its second and third corners. Small: it rides in every hit.
struct CornerBlend {
    static constexpr uint32_t kNone = 0xFFFFFFFFu;
    uint32_t face = kNone;
    float b1 = 0, b2 = 0;
    bool on() const { return face != kNone; }
};

struct ShapeHit {
    double t = kInfinity;
    Vec3 normal;
    Vec3 geomNormal;
    bool hasUV = false;
    double u = 0, v = 0;
    Vec3 dpdu;
    const Object* part = nullptr;
    CornerBlend blend;  ///< set on a face textured per vertex
    /// cutaway_textures: the point lies in two or more textured leaves (part is the first), whose
    /// textures POV-Ray averages (the tracer finds them again).
    bool cutawayBlend = false;
};

/// Möller–Trumbore test of a Triangle object in the ray's space: t in (tMin, tMax) and the
/// barycentrics (u, v) of the hit, no normals. triangleNormals gives them for a hit (u, v); the
/// two together are hitTriangle, so callers that need normals only for their final hit (the BVH,
/// occlusion tests) get the same numbers.
bool triangleHitT(const Object& o, const Ray& r, double tMin, double tMax, double& t, double& u, double& v);
void triangleNormals(const Object& o, double u, double v, Vec3& geomNormal, Vec3& normal);

/// Nearest hit of the world ray with t in (tMin, tMax); returns false when none.
bool intersect(const Object& o, const Ray& worldRay, double tMin, double tMax, ShapeHit& hit);

/// Same test without computing the normal (shadow rays).
bool occludes(const Object& o, const Ray& worldRay, double tMin, double tMax);

}  // namespace rays
