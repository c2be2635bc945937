#include "rays/io/mesh_blocks.h"

#include <cmath>
#include <string>
#include <vector>

namespace rays::scenetext {
namespace {

// NAME { N, item, item, ... } with exactly N items of `width` components (3 or 2).
template <class F>
void countedList(TokenReader& r, const char* name, int width, F&& each) {
    const Token kw = r.token();
    r.advance();
    r.block(kw, [&] {
        const Token at = r.token();
        const double n = r.number(std::string(name) + " count");
        if (n < 0 || n != std::floor(n) || n > 4294967295.0)
            fail(r.loc(at), std::string(name) + " count must be a whole number from 0 to 4294967295");
        for (size_t i = 0; i < size_t(n); ++i) {
            r.skipCommas();
            const Token item = r.token();
            if (r.isSymbol('}')) fail(r.loc(item), std::string(name) + " has fewer items than its count " + std::to_string(size_t(n)));
            const Value v = r.expr();
            if (v.n != width) fail(r.loc(item), std::string(name) + " items must be " + std::to_string(width) + "-component vectors");
            each(v, item);
        }
        r.skipCommas();
        if (!r.isSymbol('}')) fail(r.loc(r.token()), std::string(name) + " has more items than its count " + std::to_string(size_t(n)));
    });
}

}  // namespace

// mesh { triangle { <a>, <b>, <c> [uv_vectors <uv>, <uv>, <uv>] }
//        smooth_triangle { <a>, <na>, <b>, <nb>, <c>, <nc> [uv_vectors ...] } ... }
std::unique_ptr<Mesh> readMeshTriangles(TokenReader& r) {
    auto mesh = std::make_unique<Mesh>();
    struct Corner { Vec3 p, n; double u = 0, v = 0; };
    std::vector<Corner> corners;
    bool anySmooth = false, anyUV = false;
    while (r.isIdent("triangle") || r.isIdent("smooth_triangle")) {
        const Token tri = r.token();
        const bool isSmooth = r.isIdent("smooth_triangle");
        r.advance();
        Corner c[3];
        bool hasUV = false;
        r.block(tri, [&] {
            if (hasUV) r.unknown(std::string(tri.text));
            for (int k = 0; k < 3; ++k) {
                r.skipCommas();
                c[k].p = r.vector3("mesh vertex");
                if (isSmooth) {
                    r.skipCommas();
                    const Token at = r.token();
                    c[k].n = r.vector3("mesh vertex normal");
                    if (length(c[k].n) == 0) fail(r.loc(at), "vertex normal has zero length");
                }
            }
            r.skipCommas();
            if (r.isIdent("uv_vectors")) {
                r.advance();
                for (int k = 0; k < 3; ++k) {
                    r.skipCommas();
                    const Token at = r.token();
                    const Value uv = r.expr();
                    if (uv.n != 2) fail(r.loc(at), "uv_vectors takes 2-component vectors <u, v>");
                    c[k].u = uv.c[0];
                    c[k].v = uv.c[1];
                }
                hasUV = true;
            }
            r.skipCommas();
            if (!r.isSymbol('}')) r.unknown(std::string(tri.text));
        });
        if (!isSmooth) {
            const Vec3 n = cross(c[1].p - c[0].p, c[2].p - c[0].p);
            for (Corner& k : c) k.n = length(n) > 0 ? normalize(n) : Vec3{0, 0, 1};
        }
        anySmooth |= isSmooth;
        anyUV |= hasUV;
        for (const Corner& k : c) corners.push_back(k);
    }
    for (size_t i = 0; i < corners.size(); ++i) {
        const Corner& k = corners[i];
        mesh->positions.insert(mesh->positions.end(), {float(k.p.x), float(k.p.y), float(k.p.z)});
        mesh->indices.push_back(uint32_t(i));
        if (anySmooth) {
            const Vec3 n = normalize(k.n);
            mesh->normals.insert(mesh->normals.end(), {float(n.x), float(n.y), float(n.z)});
            mesh->normalIndices.push_back(uint32_t(i));
        }
        if (anyUV) {
            mesh->uvs.insert(mesh->uvs.end(), {float(k.u), float(k.v)});
            mesh->uvIndices.push_back(uint32_t(i));
        }
    }
    return mesh;
}

// mesh2 { vertex_vectors { } [normal_vectors { }] [uv_vectors { }] face_indices { }
//         [normal_indices { }] [uv_indices { }] }, zero-based indices.
std::unique_ptr<Mesh> readMesh2Sections(TokenReader& r) {
    auto mesh = std::make_unique<Mesh>();
    Mesh& m = *mesh;
    auto toIndex = [&](const Value& v, const Token& at, std::vector<uint32_t>& out) {
        for (int k = 0; k < 3; ++k) {
            if (v.c[k] < 0 || v.c[k] != std::floor(v.c[k]) || v.c[k] > 4294967295.0)
                fail(r.loc(at), "mesh2 indices must be whole numbers from 0 to 4294967295");
            out.push_back(uint32_t(v.c[k]));
        }
    };
    for (;;) {
        r.skipCommas();
        if (r.isIdent("vertex_vectors")) {
            countedList(r, "vertex_vectors", 3, [&](const Value& v, const Token&) {
                m.positions.insert(m.positions.end(), {float(v.c[0]), float(v.c[1]), float(v.c[2])});
            });
        } else if (r.isIdent("normal_vectors")) {
            countedList(r, "normal_vectors", 3, [&](const Value& v, const Token& at) {
                Vec3 n{v.c[0], v.c[1], v.c[2]};
                if (length(n) == 0) fail(r.loc(at), "normal_vectors entry has zero length");
                n = normalize(n);
                m.normals.insert(m.normals.end(), {float(n.x), float(n.y), float(n.z)});
            });
        } else if (r.isIdent("uv_vectors")) {
            countedList(r, "uv_vectors", 2, [&](const Value& v, const Token&) {
                m.uvs.insert(m.uvs.end(), {float(v.c[0]), float(v.c[1])});
            });
        } else if (r.isIdent("face_indices")) {
            countedList(r, "face_indices", 3, [&](const Value& v, const Token& at) { toIndex(v, at, m.indices); });
        } else if (r.isIdent("normal_indices")) {
            countedList(r, "normal_indices", 3, [&](const Value& v, const Token& at) { toIndex(v, at, m.normalIndices); });
        } else if (r.isIdent("uv_indices")) {
            countedList(r, "uv_indices", 3, [&](const Value& v, const Token& at) { toIndex(v, at, m.uvIndices); });
        } else {
            break;
        }
    }
    // Without explicit index lists, normals and uvs follow the vertex indices (POV-Ray).
    if (!m.normals.empty() && m.normalIndices.empty()) m.normalIndices = m.indices;
    if (!m.uvs.empty() && m.uvIndices.empty()) m.uvIndices = m.indices;
    return mesh;
}

}  // namespace rays::scenetext
