#include "rays/io/mesh_from_obj.h"

namespace rays {

std::unique_ptr<Mesh> meshFromObj(const ObjMesh& obj) {
    auto mesh = std::make_unique<Mesh>();
    Mesh& m = *mesh;
    m.positions.reserve(obj.positions.size() * 3);
    for (const Vec3& p : obj.positions) m.positions.insert(m.positions.end(), {float(p.x), float(p.y), float(p.z)});
    bool anyNormals = false, anyUVs = false;
    for (const ObjMesh::Face& f : obj.faces) {
        anyNormals |= f.n[0] >= 0 && f.n[1] >= 0 && f.n[2] >= 0;
        anyUVs |= f.t[0] >= 0 && f.t[1] >= 0 && f.t[2] >= 0;
    }
    if (anyNormals)
        for (const Vec3& n : obj.normals) m.normals.insert(m.normals.end(), {float(n.x), float(n.y), float(n.z)});
    if (anyUVs)
        for (const auto& t : obj.uvs) m.uvs.insert(m.uvs.end(), {float(t[0]), float(t[1])});
    const uint32_t zeroUV = uint32_t(m.uvs.size() / 2);
    if (anyUVs) m.uvs.insert(m.uvs.end(), {0.0f, 0.0f});
    m.indices.reserve(obj.faces.size() * 3);
    for (const ObjMesh::Face& f : obj.faces) {
        for (int k = 0; k < 3; ++k) m.indices.push_back(uint32_t(f.v[size_t(k)]));
        if (anyNormals) {
            const bool has = f.n[0] >= 0 && f.n[1] >= 0 && f.n[2] >= 0;
            if (has) {
                for (int k = 0; k < 3; ++k) m.normalIndices.push_back(uint32_t(f.n[size_t(k)]));
            } else {  // this face is flat: its own normal at all three corners
                const Vec3 a = obj.positions[size_t(f.v[0])], b = obj.positions[size_t(f.v[1])], c = obj.positions[size_t(f.v[2])];
                Vec3 n = cross(b - a, c - a);
                n = length(n) > 0 ? normalize(n) : Vec3{0, 0, 1};
                const uint32_t idx = uint32_t(m.normals.size() / 3);
                m.normals.insert(m.normals.end(), {float(n.x), float(n.y), float(n.z)});
                m.normalIndices.insert(m.normalIndices.end(), {idx, idx, idx});
            }
        }
        if (anyUVs) {
            const bool has = f.t[0] >= 0 && f.t[1] >= 0 && f.t[2] >= 0;
            for (int k = 0; k < 3; ++k) m.uvIndices.push_back(has ? uint32_t(f.t[size_t(k)]) : zeroUV);
        }
    }
    m.finalize();
    return mesh;
}

}  // namespace rays
