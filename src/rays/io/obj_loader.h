// Wavefront OBJ (+ MTL) loading into a flat triangle mesh.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "rays/math/vec3.h"

namespace rays {

struct ObjMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;                    // may be empty
    std::vector<std::array<double, 2>> uvs;       // may be empty
    struct Face { std::array<int, 3> v, n, t; };  // indices into the arrays above; n/t = -1 when absent
    std::vector<Face> faces;                      // triangles only (polygons triangulated)
    std::vector<int> faceMaterial;                // per face, index into materials, -1 = none
    struct Material {
        std::string name;
        Vec3 diffuse{0.8, 0.8, 0.8};  // Kd as read by tinyobjloader (0 0 0 when the MTL entry has no Kd)
        std::string diffuseTexture;   // map_Kd; a relative name is prefixed with the OBJ's folder; "" = none
    };
    std::vector<Material> materials;
};

/// Loads an OBJ (and its MTL, if any, relative to the OBJ's folder) with tinyobjloader (triangulating:
/// triangles kept, quads split along the shorter diagonal, larger polygons ear-clipped). Negative
/// (relative) indices work. Errors throw rays::Error "PATH: error: ..." (missing/unreadable file) or
/// "PATH:LINE:1: error: ..." (a malformed v/vn/vt/f line, an index out of range or zero, a parse error
/// reported by tinyobjloader). Reader warnings go to stderr as "PATH: warning: ...". A PATH ending in
/// ".gz" is read through zlib (gzip-compressed OBJ; its mtllib, if any, is ignored).
ObjMesh loadObj(const std::string& path);

}  // namespace rays
