#include "rays/scene/mesh.h"

#include <cmath>
#include <string>

#include "rays/error.h"

namespace rays {
namespace {

Vec3 vec(const std::vector<float>& a, uint32_t i) { return {a[3 * i], a[3 * i + 1], a[3 * i + 2]}; }

TriRay toTriRay(const Ray& r) {
    return {{float(r.origin.x), float(r.origin.y), float(r.origin.z)}, {float(r.dir.x), float(r.dir.y), float(r.dir.z)}};
}

void checkIndices(const std::vector<uint32_t>& idx, size_t count, size_t triangles, const char* what) {
    if (idx.empty()) return;
    if (idx.size() != 3 * triangles)
        throw Error(std::string("mesh has ") + std::to_string(idx.size() / 3) + " " + what + " triangles for " +
                    std::to_string(triangles) + " faces");
    for (uint32_t i : idx)
        if (i >= count)
            throw Error(std::string("mesh ") + what + " index " + std::to_string(i) + " is out of range (" +
                        std::to_string(count) + " available)");
}

}  // namespace

void Mesh::finalize() {
    const size_t nv = positions.size() / 3, nt = triangleCount();
    checkIndices(indices, nv, nt, "vertex");
    checkIndices(normalIndices, normals.size() / 3, nt, "normal");
    checkIndices(uvIndices, uvs.size() / 2, nt, "uv");
    bounds = Bounds{};
    for (size_t i = 0; i < nv; ++i) bounds.extend(vec(positions, uint32_t(i)));
    // Per-vertex tangents: each triangle's dP/du (from its uv parametrisation) summed at its
    // vertices, weighted by area through the unnormalised formula.
    tangents.clear();
    if (hasUVs()) {
        tangents.assign(positions.size(), 0.0f);
        for (size_t f = 0; f < nt; ++f) {
            const uint32_t* vi = &indices[3 * f];
            const uint32_t* ti = &uvIndices[3 * f];
            const Vec3 p0 = vec(positions, vi[0]), e1 = vec(positions, vi[1]) - p0, e2 = vec(positions, vi[2]) - p0;
            const double du1 = uvs[2 * ti[1]] - uvs[2 * ti[0]], dv1 = uvs[2 * ti[1] + 1] - uvs[2 * ti[0] + 1];
            const double du2 = uvs[2 * ti[2]] - uvs[2 * ti[0]], dv2 = uvs[2 * ti[2] + 1] - uvs[2 * ti[0] + 1];
            const double det = du1 * dv2 - du2 * dv1;
            if (det == 0) continue;
            const Vec3 t = (dv2 * e1 - dv1 * e2) / det;
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 3; ++c) tangents[3 * vi[k] + size_t(c)] += float(t[c]);
        }
    }
    bvh.build(positions.data(), nv, indices.data(), nt);
}

void Mesh::computeVertexNormals() {
    normals.assign(positions.size(), 0.0f);
    for (size_t f = 0; f < triangleCount(); ++f) {
        const uint32_t* vi = &indices[3 * f];
        const Vec3 p0 = vec(positions, vi[0]);
        const Vec3 n = cross(vec(positions, vi[1]) - p0, vec(positions, vi[2]) - p0);  // |n| = 2·area
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) normals[3 * vi[k] + size_t(c)] += float(n[c]);
    }
    normalIndices = indices;
}

size_t Mesh::memoryBytes() const {
    return positions.capacity() * 4 + indices.capacity() * 4 + normals.capacity() * 4 + normalIndices.capacity() * 4 +
           uvs.capacity() * 4 + uvIndices.capacity() * 4 + tangents.capacity() * 4 + bvh.memoryBytes();
}

bool insideMesh(const Mesh& m, Vec3 p) {
    if (!m.hasInside) return false;
    const TriRay r = toTriRay(Ray{p, m.insideVector});
    TriHit th;
    float t = 0;
    bool inside = false;
    // Each search starts a little past the last crossing (the BVH's t is float): a ray through an
    // edge meets the second triangle at the same t and counts once.
    for (int crossings = 0; crossings < 1 << 20 && m.bvh.intersect(r, t, INFINITY, th); ++crossings) {
        inside = !inside;
        t = th.t + 1e-5f * (1 + th.t);
    }
    return inside;
}

bool intersectMesh(const Mesh& m, const Ray& ray, double tMin, double tMax, MeshHit& hit) {
    TriHit th;
    const float hi = std::isinf(tMax) ? INFINITY : float(tMax);
    if (!m.bvh.intersect(toTriRay(ray), float(tMin), hi, th)) return false;
    const uint32_t f = th.prim;
    const uint32_t* vi = &m.indices[3 * f];
    const Vec3 p0 = vec(m.positions, vi[0]), p1 = vec(m.positions, vi[1]), p2 = vec(m.positions, vi[2]);
    const double b1 = th.u, b2 = th.v, b0 = 1 - b1 - b2;
    hit.triangle = f;
    hit.b1 = b1;
    hit.b2 = b2;
    hit.t = th.t;
    hit.geomNormal = normalize(cross(p1 - p0, p2 - p0));
    hit.normal = hit.geomNormal;
    if (m.hasNormals()) {
        const uint32_t* ni = &m.normalIndices[3 * f];
        const Vec3 n0 = vec(m.normals, ni[0]), n1 = vec(m.normals, ni[1]), n2 = vec(m.normals, ni[2]);
        const Vec3 n = b0 * n0 + b1 * n1 + b2 * n2;
        if (length(n) > 0) {
            if (m.povSides && !(n0 == n1 && n1 == n2)) hit.geomNormal = triangleSides(hit.geomNormal, n);
            hit.normal = normalize(dot(n, hit.geomNormal) < 0 ? -n : n);
        }
    }
    if (m.hasUVs()) {
        const uint32_t* ti = &m.uvIndices[3 * f];
        hit.u = b0 * m.uvs[2 * ti[0]] + b1 * m.uvs[2 * ti[1]] + b2 * m.uvs[2 * ti[2]];
        hit.v = b0 * m.uvs[2 * ti[0] + 1] + b1 * m.uvs[2 * ti[1] + 1] + b2 * m.uvs[2 * ti[2] + 1];
        hit.dpdu = b0 * vec(m.tangents, vi[0]) + b1 * vec(m.tangents, vi[1]) + b2 * vec(m.tangents, vi[2]);
    } else {
        hit.u = hit.v = 0;
        hit.dpdu = Vec3{};
    }
    return true;
}

bool occludesMesh(const Mesh& m, const Ray& ray, double tMin, double tMax) {
    const float hi = std::isinf(tMax) ? INFINITY : float(tMax);
    return m.bvh.occluded(toTriRay(ray), float(tMin), hi);
}

}  // namespace rays
