// Indexed triangle meshes (OBJ files, POV-Ray mesh and mesh2): geometry stored once, with its own
// wide SIMD BVH in object space, optional per-vertex normals (smooth shading) and texture
// coordinates with per-vertex tangents (normal mapping).
#pragma once
#include <cstdint>
#include <vector>

#include "rays/accel/triangle_bvh.h"
#include "rays/geometry/ray.h"

namespace rays {

struct Mesh {
    std::vector<float> positions;        ///< xyz per vertex
    std::vector<uint32_t> indices;       ///< 3 per triangle, into positions
    std::vector<float> normals;          ///< xyz per normal; empty = flat shading
    std::vector<uint32_t> normalIndices; ///< 3 per triangle, into normals (when normals exist)
    std::vector<float> uvs;              ///< uv per texture vertex; empty = none
    std::vector<uint32_t> uvIndices;     ///< 3 per triangle, into uvs (when uvs exist)
    std::vector<float> tangents;         ///< xyz per position vertex (from uvs; empty without)
    TriangleBvh bvh;                     ///< over positions/indices, object space
    Bounds bounds;                       ///< object-space bounds
    /// POV-Ray's inside_vector (unit, object space): a mesh with one has an inside (insideMesh).
    Vec3 insideVector;
    bool hasInside = false;
    /// POV-Ray's sides for smooth triangles (mesh, mesh2): where a triangle's three normals are not
    /// all the same, its interpolated normal at the hit, not its winding, says which side is which
    /// (intersectMesh turns geomNormal to match; see triangleSides).
    bool povSides = false;

    size_t triangleCount() const { return indices.size() / 3; }
    bool hasNormals() const { return !normalIndices.empty(); }
    bool hasUVs() const { return !uvIndices.empty(); }

    /// Checks the index arrays, computes bounds and tangents and builds the BVH. Throws Error
    /// (message without location) when an index is out of range.
    void finalize();
    /// Sets per-vertex normals to the area-weighted average of the adjacent face normals (smooth
    /// shading for meshes that have none). Call before finalize().
    void computeVertexNormals();
    size_t memoryBytes() const;
};

/// What a ray hit on a mesh, in object space.
struct MeshHit {
    uint32_t triangle = 0;
    double t = 0;
    Vec3 geomNormal;   ///< unit, from the winding (a, b, c); with povSides, see triangleSides
    Vec3 normal;       ///< interpolated vertex normal (or geomNormal), same side as geomNormal
    double u = 0, v = 0;  ///< texture coordinates (0 without uvs)
    double b1 = 0, b2 = 0;  ///< barycentric weights of the triangle's second and third corners
    Vec3 dpdu;         ///< tangent along u (zero without uvs)
};

/// The geometric normal of a smooth triangle under POV-Ray's rule for its sides: g (the winding's
/// normal) turned so that −g points along the interpolated normal n. A flat triangle shows its
/// texture where g points away from the viewer; a smooth one (its three normals not all the same)
/// where n points towards the viewer, whatever its winding (measured with POV-Ray 3.7 on one- and
/// two-triangle mesh2s: winding ignored, the side following the normals interpolated at the hit;
/// three equal normals leave the triangle flat). Smooth triangles of POV-Ray scenes only (Object
/// triangles with smooth set, meshes with povSides).
inline Vec3 triangleSides(Vec3 g, Vec3 n) { return dot(n, g) > 0 ? -g : g; }

/// Nearest hit of an object-space ray with t in (tMin, tMax).
bool intersectMesh(const Mesh& m, const Ray& ray, double tMin, double tMax, MeshHit& hit);
/// Any hit with t in (tMin, tMax).
bool occludesMesh(const Mesh& m, const Ray& ray, double tMin, double tMax);

/// True when the object-space point p is inside a mesh with an inside_vector: an odd number of its
/// triangles cross the ray from p along that vector (POV-Ray 3.7 reference, "Mesh": "a ray is
/// shot in the direction of the inside vector ... the number of intersections counted"). A ray
/// through an edge counts one crossing. False for meshes without one.
bool insideMesh(const Mesh& m, Vec3 p);

}  // namespace rays
