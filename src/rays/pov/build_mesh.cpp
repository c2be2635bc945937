#include "rays/pov/build_mesh.h"

#include <algorithm>
#include <unordered_map>

#include "rays/pov/grammar.h"

namespace rays::pov {

using sdl::VType;

namespace {

void pushVec(std::vector<float>& out, Vec3 v) { out.insert(out.end(), {float(v.x), float(v.y), float(v.z)}); }

// The index of texture item t in ft (added when new). `texture { T }` counts as T, so that the
// triangles of a mesh that each name one declared texture (as converters write them) share one.
int32_t textureIndex(FaceTextures& ft, std::unordered_map<const Item*, int32_t>& seen, const Item* t) {
    const Item* key = t;
    if (t->entries.size() == 1 && t->entries[0].positional() && t->entries[0].args.size() == 1 &&
        t->entries[0].args[0].type == VType::Item && t->entries[0].args[0].item().kind == Kw::texture)
        key = &t->entries[0].args[0].item();
    const auto [at, added] = seen.emplace(key, int32_t(ft.textures.size()));
    if (added) ft.textures.push_back(t);
    return at->second;
}

std::unique_ptr<Mesh> fromTriangles(const Item& m, FaceTextures& ft) {
    auto mesh = std::make_unique<Mesh>();
    mesh->povSides = true;
    std::unordered_map<const Item*, int32_t> seen;
    bool anySmooth = false, anyUV = false;
    for (const Entry& e : m.entries)
        if (!e.positional() && e.key != kMapEntry && e.kw() == Kw::smooth_triangle) anySmooth = true;
    for (const Entry& e : m.entries) {
        if (e.positional() || e.key == kMapEntry) continue;
        if (e.kw() != Kw::triangle && e.kw() != Kw::smooth_triangle) continue;
        const Item& t = e.args[0].item();
        const std::vector<const Value*> p = positionals(t);
        const bool smooth = e.kw() == Kw::smooth_triangle;
        if (p.size() < (smooth ? 6u : 3u)) continue;
        Vec3 v[3], n[3];
        for (int k = 0; k < 3; ++k) {
            v[k] = toVec3(*p[size_t(smooth ? 2 * k : k)]);
            if (smooth) n[k] = toVec3(*p[size_t(2 * k + 1)]);
        }
        const Vec3 g = cross(v[1] - v[0], v[2] - v[0]);
        if (length(g) == 0) continue;
        const uint32_t base = uint32_t(mesh->positions.size() / 3);
        const Entry* texture = findEntry(t, Kw::texture);
        ft.face.push_back(texture ? textureIndex(ft, seen, &texture->args[0].item()) : -1);
        for (int k = 0; k < 3; ++k) {
            pushVec(mesh->positions, v[k]);
            mesh->indices.push_back(base + uint32_t(k));
            if (anySmooth) {
                const Vec3 nn = smooth && length(n[k]) > 0 ? normalize(n[k]) : normalize(g);
                pushVec(mesh->normals, nn);
                mesh->normalIndices.push_back(base + uint32_t(k));
            }
        }
        if (const Entry* uv = findEntry(t, Kw::uv_vectors); uv && uv->args.size() == 3) {
            if (!anyUV) {  // earlier triangles get zero uvs
                anyUV = true;
                mesh->uvs.assign(size_t(base) * 2, 0.0f);
                for (uint32_t i = 0; i < base; ++i) mesh->uvIndices.push_back(i);
            }
            for (int k = 0; k < 3; ++k) {
                mesh->uvs.insert(mesh->uvs.end(), {float(uv->args[size_t(k)].c[0]), float(uv->args[size_t(k)].c[1])});
                mesh->uvIndices.push_back(base + uint32_t(k));
            }
        } else if (anyUV) {
            for (int k = 0; k < 3; ++k) {
                mesh->uvs.insert(mesh->uvs.end(), {0.0f, 0.0f});
                mesh->uvIndices.push_back(base + uint32_t(k));
            }
        }
    }
    return mesh;
}

// A mesh2 section `{ count, v1, v2, ... }`: its values after the count.
std::vector<const Value*> section(const Item& m, Kw k) {
    const Entry* e = findEntry(m, k);
    if (!e) return {};
    std::vector<const Value*> v = positionals(e->args[0].item());
    if (!v.empty()) v.erase(v.begin());
    return v;
}

// Whether a texture item is textures written one after another (grammar.cpp's readTextureLayers:
// two or more bare entries, each a texture), which a texture_list holds as separate textures.
bool writtenInARow(const Item& t) {
    if (t.entries.size() < 2) return false;
    for (const Entry& e : t.entries)
        if (!e.positional() || e.args.size() != 1 || e.args[0].type != VType::Item || e.args[0].item().kind != Kw::texture)
            return false;
    return true;
}

// mesh2's texture_list: its texture items in order.
std::vector<const Item*> textureList(const Item& m) {
    std::vector<const Item*> out;
    const Entry* list = findEntry(m, Kw::texture_list);
    if (!list) return out;
    auto add = [&](const Item& t) {
        if (!writtenInARow(t)) return out.push_back(&t);
        for (const Entry& e : t.entries) out.push_back(&e.args[0].item());
    };
    for (const Entry& e : list->args[0].item().entries) {
        if (e.key == kMapEntry) continue;
        if (!e.positional() && e.kw() == Kw::texture) add(e.args[0].item());
        if (e.positional())
            for (const Value& v : e.args)
                if (v.type == VType::Item && v.item().kind == Kw::texture) add(v.item());
    }
    return out;
}

// face_indices' texture indices: after each face's vector, none, one, or three (one per corner:
// corners). False, with the reason, for an index out of the list.
bool faceTextureIndices(const Item& m, FaceTextures& ft, std::string& problem) {
    ft.textures = textureList(m);
    if (!findEntry(m, Kw::face_indices)) return true;
    const std::vector<const Value*> v = section(m, Kw::face_indices);
    int after = 0;  // numbers seen after the current face's vector
    std::vector<int32_t> named;  // 3 per face
    for (const Value* x : v) {
        if (x->type == VType::Vector) {
            ft.face.push_back(-1);
            named.insert(named.end(), {-1, -1, -1});
            after = 0;
            continue;
        }
        if (ft.face.empty() || after == 3) continue;
        const double i = x->c[0];
        if (!(i >= 0 && i < double(ft.textures.size()))) {
            problem = "mesh2 texture index " + std::to_string(long(i)) + " is out of range (" +
                      std::to_string(ft.textures.size()) + " textures in texture_list)";
            return false;
        }
        named[named.size() - 3 + size_t(after)] = int32_t(i);
        if (after++ == 0) ft.face.back() = int32_t(i);
    }
    // Faces with three indices blend them; faces with one (or two: the first) keep their face's.
    bool anyCorners = false;
    for (size_t f = 0; f < ft.face.size(); ++f) {
        if (named[3 * f + 2] >= 0) anyCorners = true;
        else named[3 * f] = named[3 * f + 1] = -1;
    }
    if (anyCorners) ft.corners = std::move(named);
    return true;
}

std::unique_ptr<Mesh> fromMesh2(const Item& m, std::string& problem) {
    auto mesh = std::make_unique<Mesh>();
    mesh->povSides = true;
    for (const Value* v : section(m, Kw::vertex_vectors)) pushVec(mesh->positions, toVec3(*v));
    for (const Value* v : section(m, Kw::normal_vectors)) {
        const Vec3 n = toVec3(*v);
        pushVec(mesh->normals, length(n) > 0 ? normalize(n) : Vec3{0, 0, 1});
    }
    for (const Value* v : section(m, Kw::uv_vectors)) mesh->uvs.insert(mesh->uvs.end(), {float(v->c[0]), float(v->c[1])});
    // face_indices: vectors <a, b, c>, each optionally followed by one or three texture indices.
    auto triples = [](const std::vector<const Value*>& vals) {
        std::vector<uint32_t> out;
        for (const Value* v : vals)
            if (v->type == VType::Vector)
                for (int k = 0; k < 3; ++k)  // clamped as a float first: 1e300 has no uint32 (then out of range below)
                    out.push_back(uint32_t(std::min(std::max(0.0, v->c[size_t(k)]), 4294967295.0)));
        return out;
    };
    mesh->indices = triples(section(m, Kw::face_indices));
    const size_t vertices = mesh->positions.size() / 3;
    for (uint32_t i : mesh->indices)
        if (i >= vertices) {
            problem = "mesh2 face index " + std::to_string(i) + " is out of range (" + std::to_string(vertices) + " vertices)";
            return nullptr;
        }
    if (!mesh->normals.empty()) {
        mesh->normalIndices = hasEntry(m, Kw::normal_indices) ? triples(section(m, Kw::normal_indices)) : mesh->indices;
        if (mesh->normalIndices.size() != mesh->indices.size()) mesh->normalIndices.clear(), mesh->normals.clear();
    }
    if (!mesh->uvs.empty()) {
        mesh->uvIndices = hasEntry(m, Kw::uv_indices) ? triples(section(m, Kw::uv_indices)) : mesh->indices;
        if (mesh->uvIndices.size() != mesh->indices.size()) mesh->uvIndices.clear(), mesh->uvs.clear();
    }
    const size_t normals = mesh->normals.size() / 3, uvs = mesh->uvs.size() / 2;
    for (uint32_t i : mesh->normalIndices)
        if (i >= normals) {
            problem = "mesh2 normal index " + std::to_string(i) + " is out of range";
            return nullptr;
        }
    for (uint32_t i : mesh->uvIndices)
        if (i >= uvs) {
            problem = "mesh2 uv index " + std::to_string(i) + " is out of range";
            return nullptr;
        }
    return mesh;
}

}  // namespace

std::unique_ptr<Mesh> meshFromItem(const Item& m, std::string& problem, FaceTextures* textures) {
    problem.clear();
    FaceTextures ft;
    std::unique_ptr<Mesh> mesh = m.kind == Kw::mesh2 ? fromMesh2(m, problem) : fromTriangles(m, ft);
    if (mesh && m.kind == Kw::mesh2 && !faceTextureIndices(m, ft, problem)) return nullptr;
    if (textures) *textures = std::move(ft);
    // inside_vector (POV-Ray 3.7 reference, "Mesh"): the direction inside tests count crossings along.
    if (const Entry* v = findEntry(m, Kw::inside_vector); mesh && v && !v->args.empty()) {
        const Vec3 d = toVec3(v->args[0]);
        if (length(d) > 0) {
            mesh->insideVector = normalize(d);
            mesh->hasInside = true;
        }
    }
    return mesh;
}

}  // namespace rays::pov
