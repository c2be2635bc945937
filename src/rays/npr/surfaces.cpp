#include "rays/npr/surfaces.h"

#include <cstring>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>

namespace rays {
namespace {

struct UnionFind {
    std::vector<int> parent;
    explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int x) {
        while (parent[size_t(x)] != x) {
            parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
            x = parent[size_t(x)];
        }
        return x;
    }
    void unite(int a, int b) { parent[size_t(find(a))] = find(b); }
};

struct VertexKey {
    double x, y, z;
    bool operator==(const VertexKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct VertexHash {
    size_t operator()(const VertexKey& k) const {
        uint64_t h = 1469598103934665603ULL;
        for (double d : {k.x, k.y, k.z}) {
            uint64_t bits;
            std::memcpy(&bits, &d, sizeof bits);
            h = (h ^ bits) * 1099511628211ULL;
        }
        return size_t(h);
    }
};

Vec3 worldVertex(const Object& o, Vec3 p) { return o.transformed ? o.toObject.inverse().point(p) : p; }

using MaterialKey = std::tuple<double, double, double, double, double, double, double, double, double, double, double>;
MaterialKey keyOf(const Material& m) {
    return {m.color.x, m.color.y, m.color.z, m.filter, m.ambient, m.diffuse, m.specular, m.roughness,
            m.reflection, m.ior, m.metallic};
}

}  // namespace

SurfaceIds computeSurfaceIds(const Scene& scene) {
    const size_t n = scene.objects.size();
    UnionFind uf(n);
    std::unordered_map<VertexKey, int, VertexHash> firstUse;
    for (size_t i = 0; i < n; ++i) {
        const Object& o = scene.objects[i];
        if (o.type != ShapeType::Triangle) continue;
        for (Vec3 p : {o.p0, o.p1, o.p2}) {
            const Vec3 w = worldVertex(o, p);
            auto [it, inserted] = firstUse.try_emplace(VertexKey{w.x, w.y, w.z}, int(i));
            if (!inserted) uf.unite(int(i), it->second);
        }
    }
    SurfaceIds ids;
    ids.surface.resize(n);
    ids.material.resize(n);
    std::map<MaterialKey, int> materials;
    for (size_t i = 0; i < n; ++i) {
        ids.surface[i] = uf.find(int(i));
        ids.material[i] = materials.try_emplace(keyOf(scene.objects[i].material), int(materials.size())).first->second;
    }
    return ids;
}

}  // namespace rays
