// TriangleBvh against a brute-force double-precision reference, watertightness on closed and
// flat meshes, edge cases (empty, one triangle, degenerate input), thread-count determinism and
// the memory budget.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "rays/accel/triangle_bvh.h"
#include "support/icosphere.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

struct Mesh {
    std::vector<float> pos;
    std::vector<uint32_t> idx;
    size_t vertexCount() const { return pos.size() / 3; }
    size_t triangleCount() const { return idx.size() / 3; }
    uint32_t addVertex(double x, double y, double z) {
        pos.push_back(float(x));
        pos.push_back(float(y));
        pos.push_back(float(z));
        return uint32_t(vertexCount() - 1);
    }
    void addTriangle(uint32_t a, uint32_t b, uint32_t c) {
        idx.push_back(a);
        idx.push_back(b);
        idx.push_back(c);
    }
    std::array<double, 3> vertex(uint32_t i) const {
        return {double(pos[3 * i]), double(pos[3 * i + 1]), double(pos[3 * i + 2])};
    }
};

/// Closed icosphere, subdivided `levels` times (20 * 4^levels triangles), radius perturbed by up
/// to `bumps` (relative) per vertex so the surface is not symmetric.
Mesh icosphere(int levels, double bumps, uint32_t seed, double radius = 1.0, std::array<double, 3> c = {0, 0, 0}) {
    const test::Icosphere sphere = test::unitIcosphere(levels);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> bump(1.0 - bumps, 1.0);
    Mesh m;
    for (const auto& p : sphere.vertices) {
        const double r = radius * bump(rng);
        m.addVertex(c[0] + r * p[0], c[1] + r * p[1], c[2] + r * p[2]);
    }
    for (const auto& tri : sphere.faces) m.addTriangle(tri[0], tri[1], tri[2]);
    return m;
}

/// Flat n x n grid of unit squares in the plane z = 0 (vertices on integer coordinates), two
/// triangles per square with alternating diagonals.
Mesh flatGrid(int n) {
    Mesh m;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) m.addVertex(x, y, 0);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const uint32_t a = uint32_t(y * (n + 1) + x), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
            if ((x + y) % 2) {
                m.addTriangle(a, b, d);
                m.addTriangle(a, d, c);
            } else {
                m.addTriangle(a, b, c);
                m.addTriangle(b, d, c);
            }
        }
    return m;
}

/// Height-field grid (n x n squares, 2 n^2 triangles).
Mesh bumpyGrid(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> h(-0.3, 0.3);
    Mesh m;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) m.addVertex(double(x) / n, double(y) / n, h(rng) / n + 0.05 * std::sin(x * 0.1));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const uint32_t a = uint32_t(y * (n + 1) + x), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
            m.addTriangle(a, b, d);
            m.addTriangle(a, d, c);
        }
    return m;
}

/// Random triangle soup in [-1, 1]^3 with sizes from tiny to large.
Mesh soup(size_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_real_distribution<double> logSize(-3.0, -0.3);
    Mesh m;
    for (size_t i = 0; i < count; ++i) {
        const double c[3] = {u(rng), u(rng), u(rng)};
        const double s = std::pow(10.0, logSize(rng));
        uint32_t v[3];
        for (uint32_t& k : v) k = m.addVertex(c[0] + s * u(rng), c[1] + s * u(rng), c[2] + s * u(rng));
        m.addTriangle(v[0], v[1], v[2]);
    }
    return m;
}

TriangleBvh buildBvh(const Mesh& m, int threads = 0) {
    TriangleBvh bvh;
    bvh.build(m.pos.data(), m.vertexCount(), m.idx.data(), m.triangleCount(), threads);
    return bvh;
}

struct RefHit {
    bool hit = false;
    uint32_t prim = UINT32_MAX;
    double t = 0, minBary = 0;
};

/// Double-precision Möller–Trumbore over all triangles (closest hit in (tMin, tMax)).
RefHit bruteForce(const Mesh& m, const TriRay& r, double tMin, double tMax) {
    RefHit best;
    best.t = tMax;
    const double o[3] = {r.org[0], r.org[1], r.org[2]}, d[3] = {r.dir[0], r.dir[1], r.dir[2]};
    for (size_t i = 0; i < m.triangleCount(); ++i) {
        const auto a = m.vertex(m.idx[3 * i]), b = m.vertex(m.idx[3 * i + 1]), c = m.vertex(m.idx[3 * i + 2]);
        const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double p[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
        const double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
        if (det == 0.0) continue;
        const double s[3] = {o[0] - a[0], o[1] - a[1], o[2] - a[2]};
        const double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
        if (u < 0.0 || u > 1.0) continue;
        const double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
        const double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
        if (v < 0.0 || u + v > 1.0) continue;
        const double t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
        if (t > tMin && t < best.t) {
            best.hit = true;
            best.prim = uint32_t(i);
            best.t = t;
            best.minBary = std::min({u, v, 1.0 - u - v});
        }
    }
    return best;
}

struct Agreement {
    size_t rays = 0, hits = 0, edgeCases = 0, hardMismatches = 0, occludedMismatches = 0;
};

/// Compares intersect and occluded with the brute-force reference. Disagreements where the
/// reference or the BVH hit lies within 1e-5 (barycentric) of an edge are counted as edge cases.
Agreement compare(const Mesh& m, const TriangleBvh& bvh, const std::vector<TriRay>& rays, float tMin, float tMax) {
    Agreement a;
    for (const TriRay& r : rays) {
        ++a.rays;
        const RefHit ref = bruteForce(m, r, tMin, tMax);
        TriHit h;
        const bool hit = bvh.intersect(r, tMin, tMax, h);
        const bool occ = bvh.occluded(r, tMin, tMax);
        a.hits += ref.hit;
        const double bvhEdge = hit ? std::min({double(h.u), double(h.v), 1.0 - h.u - h.v}) : 1.0;
        const bool nearEdge = (ref.hit && ref.minBary < 1e-5) || (hit && bvhEdge < 1e-5);
        if (hit != ref.hit) {
            ++(nearEdge ? a.edgeCases : a.hardMismatches);
        } else if (hit) {
            // Relative 1e-5; for hits very close to the origin the float test's absolute error
            // (~1e-7 of the distance to the vertices) dominates, hence the floor of 0.1.
            const double rel = std::fabs(double(h.t) - ref.t) / std::max(0.1, std::fabs(ref.t));
            if (rel > 1e-5) {
                ++(nearEdge ? a.edgeCases : a.hardMismatches);
            } else if (h.prim != ref.prim && !nearEdge) {
                // Different triangles at the same distance (intersecting soup triangles): fine.
            }
            if (h.prim < m.triangleCount()) {
                EXPECT_GE(h.u, -1e-6f);
                EXPECT_GE(h.v, -1e-6f);
                EXPECT_LE(h.u + h.v, 1.0f + 1e-5f);
            } else {
                ADD_FAILURE() << "prim out of range: " << h.prim;
            }
        }
        if (occ != hit) ++a.occludedMismatches;
    }
    return a;
}

std::vector<TriRay> randomRays(size_t count, uint32_t seed, float originBox, bool towardCenter) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1, 1);
    std::vector<TriRay> rays(count);
    for (TriRay& r : rays) {
        for (float& o : r.org) o = originBox * u(rng);
        for (int k = 0; k < 3; ++k) r.dir[k] = towardCenter ? 0.6f * u(rng) - r.org[k] : u(rng);
        // Some rays along axes (zero direction components).
        if (rng() % 16 == 0) {
            const int axis = int(rng() % 3);
            for (int k = 0; k < 3; ++k)
                if (k != axis) r.dir[k] = 0.0f;
            if (r.dir[axis] == 0.0f) r.dir[axis] = 1.0f;
        }
    }
    return rays;
}

void expectAgreement(const Agreement& a) {
    EXPECT_EQ(a.hardMismatches, 0u);
    EXPECT_LE(a.edgeCases, a.rays / 1000);
    EXPECT_EQ(a.occludedMismatches, 0u);
    EXPECT_GT(a.hits, a.rays / 10);
}

TEST(TriangleBvh, SoupMatchesBruteForce) {
    const Mesh m = soup(3000, 1);
    const TriangleBvh bvh = buildBvh(m);
    EXPECT_FALSE(bvh.empty());
    // Origins inside the soup, and from outside toward it.
    expectAgreement(compare(m, bvh, randomRays(6000, 2, 0.9f, false), 0.0f, INFINITY));
    expectAgreement(compare(m, bvh, randomRays(6000, 3, 3.0f, true), 0.0f, INFINITY));
    // Finite intervals.
    expectAgreement(compare(m, bvh, randomRays(3000, 4, 0.9f, false), 0.05f, 0.7f));
}

TEST(TriangleBvh, ClosedMeshMatchesBruteForce) {
    const Mesh m = icosphere(4, 0.3, 5);  // 5120 triangles
    const TriangleBvh bvh = buildBvh(m);
    const Agreement inside = compare(m, bvh, randomRays(3000, 6, 0.4f, false), 0.0f, INFINITY);
    expectAgreement(inside);
    EXPECT_EQ(inside.hits, inside.rays);  // every ray from inside hits the closed surface
    expectAgreement(compare(m, bvh, randomRays(3000, 7, 3.0f, true), 0.0f, INFINITY));
}

TEST(TriangleBvh, RaysThroughSharedEdgesAndVerticesNeverSlipThrough) {
    // A convex closed mesh (icosphere stretched into an ellipsoid, off the origin). Targets: every
    // vertex and random points on every edge (rounded to float, so within an ulp of the edge).
    // A ray from inside through a point of a convex surface crosses it there; so does a ray from
    // outside that is not tangent (here within ~30 degrees of the triangle's normal). Either must
    // hit at the target (t = 1), never slip through to the far side.
    Mesh m = icosphere(3, 0.0, 8);  // 1280 triangles
    const float centre[3] = {0.3f, -0.2f, 0.1f}, axes[3] = {1.7f, 1.1f, 2.3f};
    for (size_t i = 0; i < m.vertexCount(); ++i)
        for (int c = 0; c < 3; ++c) m.pos[3 * i + size_t(c)] = centre[c] + axes[c] * m.pos[3 * i + size_t(c)];
    const TriangleBvh bvh = buildBvh(m);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1, 1), s01(0, 1);
    size_t misses = 0, rays = 0;
    for (size_t tri = 0; tri < m.triangleCount(); ++tri) {
        const auto p0 = m.vertex(m.idx[3 * tri]), p1 = m.vertex(m.idx[3 * tri + 1]), p2 = m.vertex(m.idx[3 * tri + 2]);
        double n[3] = {(p1[1] - p0[1]) * (p2[2] - p0[2]) - (p1[2] - p0[2]) * (p2[1] - p0[1]),
                       (p1[2] - p0[2]) * (p2[0] - p0[0]) - (p1[0] - p0[0]) * (p2[2] - p0[2]),
                       (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0])};
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& c : n) c /= len;
        for (int e = 0; e < 3; ++e) {
            const auto a = m.vertex(m.idx[3 * tri + size_t(e)]), b = m.vertex(m.idx[3 * tri + size_t((e + 1) % 3)]);
            for (int k = 0; k < 3; ++k) {
                const float s = k == 0 ? 0.0f : s01(rng);
                float target[3];
                for (int c = 0; c < 3; ++c) target[c] = float(a[c] + s * (b[c] - a[c]));
                for (int side = 0; side < 2; ++side) {
                    TriRay r;
                    const float away = 0.5f + 2.0f * s01(rng);
                    for (int c = 0; c < 3; ++c)
                        r.org[c] = side == 0 ? centre[c] + 0.5f * axes[c] * u(rng) : target[c] + away * (float(n[c]) + 0.3f * u(rng));
                    for (int c = 0; c < 3; ++c) r.dir[c] = target[c] - r.org[c];
                    TriHit h;
                    ++rays;
                    const bool hit = bvh.intersect(r, 0.0f, INFINITY, h);
                    const bool occ = bvh.occluded(r, 0.0f, 1.001f);
                    if (!hit || !occ || std::fabs(h.t - 1.0f) > 1e-4f) ++misses;
                }
            }
        }
    }
    EXPECT_EQ(misses, 0u) << "of " << rays << " rays";
}

TEST(TriangleBvh, AxisAlignedRaysThroughGridEdgesAndVertices) {
    // Vertices and edge midpoints of a flat grid are exactly representable; rays straight down
    // (direction components exactly zero) and oblique rays must all hit the plane.
    const int n = 32;
    const Mesh m = flatGrid(n);
    const TriangleBvh bvh = buildBvh(m);
    size_t misses = 0, rays = 0;
    for (int y = 1; y < 2 * n; ++y)
        for (int x = 1; x < 2 * n; ++x) {
            const float px = 0.5f * float(x), py = 0.5f * float(y);
            const TriRay down{{px, py, 2.0f}, {0.0f, 0.0f, -1.0f}};
            const TriRay up{{px, py, -2.0f}, {0.0f, 0.0f, 3.0f}};
            const TriRay oblique{{px - 1.5f, py + 0.75f, 1.0f}, {1.5f, -0.75f, -1.0f}};
            const TriRay flatX{{px, py, 1.0f}, {0.0f, -0.25f, -0.5f}};
            for (const TriRay& r : {down, up, oblique, flatX}) {
                ++rays;
                TriHit h;
                if (!bvh.intersect(r, 0.0f, INFINITY, h) || !bvh.occluded(r, 0.0f, INFINITY)) {
                    ++misses;
                    continue;
                }
                // The hit point is the target.
                EXPECT_NEAR(r.org[2] + h.t * r.dir[2], 0.0f, 1e-5f);
            }
        }
    EXPECT_EQ(misses, 0u) << "of " << rays << " rays";
}

TEST(TriangleBvh, EmptyInput) {
    TriangleBvh bvh;
    EXPECT_TRUE(bvh.empty());
    bvh.build(nullptr, 0, nullptr, 0);
    EXPECT_TRUE(bvh.empty());
    const TriRay r{{0, 0, 0}, {0, 0, 1}};
    TriHit h;
    EXPECT_FALSE(bvh.intersect(r, 0, INFINITY, h));
    EXPECT_EQ(h.prim, UINT32_MAX);
    EXPECT_FALSE(bvh.occluded(r, 0, INFINITY));
    float lo[3], hi[3];
    bvh.bounds(lo, hi);
    EXPECT_GT(lo[0], hi[0]);
    EXPECT_LT(bvh.memoryBytes(), 1024u);
}

TEST(TriangleBvh, SingleTriangle) {
    const float pos[] = {0, 0, 5, 2, 0, 5, 0, 2, 5};
    const uint32_t idx[] = {0, 1, 2};
    TriangleBvh bvh;
    bvh.build(pos, 3, idx, 1);
    ASSERT_FALSE(bvh.empty());
    TriHit h;
    ASSERT_TRUE(bvh.intersect({{0.5f, 0.25f, 0}, {0, 0, 2}}, 0, INFINITY, h));
    EXPECT_EQ(h.prim, 0u);
    EXPECT_FLOAT_EQ(h.t, 2.5f);
    EXPECT_FLOAT_EQ(h.u, 0.25f);   // weight of vertex 1 (x = 2)
    EXPECT_FLOAT_EQ(h.v, 0.125f);  // weight of vertex 2 (y = 2)
    // From behind, and the interval bounds (open).
    EXPECT_TRUE(bvh.intersect({{0.5f, 0.25f, 10}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_FLOAT_EQ(h.t, 5.0f);
    EXPECT_FALSE(bvh.intersect({{0.5f, 0.25f, 0}, {0, 0, 2}}, 0, 2.5f, h));
    EXPECT_FALSE(bvh.occluded({{0.5f, 0.25f, 0}, {0, 0, 2}}, 2.5f, INFINITY));
    EXPECT_TRUE(bvh.occluded({{0.5f, 0.25f, 0}, {0, 0, 2}}, 2.4f, 2.6f));
    EXPECT_FALSE(bvh.intersect({{1.5f, 1.5f, 0}, {0, 0, 1}}, 0, INFINITY, h));
    float lo[3], hi[3];
    bvh.bounds(lo, hi);
    EXPECT_EQ(lo[0], 0.0f);
    EXPECT_EQ(hi[1], 2.0f);
    EXPECT_EQ(lo[2], 5.0f);
    EXPECT_EQ(hi[2], 5.0f);
}

TEST(TriangleBvh, DegenerateTrianglesAreNeverHit) {
    Mesh m;
    for (int i = 0; i < 50; ++i) {
        const uint32_t a = m.addVertex(i, 0, 0), b = m.addVertex(i + 1, 1, 1), c = m.addVertex(i + 2, 2, 2);
        m.addTriangle(a, b, c);  // collinear
        m.addTriangle(a, a, b);  // repeated vertex
        m.addTriangle(c, c, c);  // a point
    }
    const TriangleBvh bvh = buildBvh(m);
    EXPECT_TRUE(bvh.empty());
    TriHit h;
    for (int i = 0; i < 50; ++i) {
        const TriRay r{{float(i) + 1.0f, 1.0f, -3.0f}, {0, 0, 1}};
        EXPECT_FALSE(bvh.intersect(r, 0, INFINITY, h));
        EXPECT_FALSE(bvh.occluded(r, 0, INFINITY));
    }
    // Mixed with a valid triangle: only that one is hit.
    Mesh mixed = m;
    const uint32_t a = mixed.addVertex(-10, -10, 1), b = mixed.addVertex(60, -10, 1), c = mixed.addVertex(-10, 60, 1);
    mixed.addTriangle(a, b, c);
    const TriangleBvh bvh2 = buildBvh(mixed);
    EXPECT_EQ(bvh2.stats().triangles, 1u);
    ASSERT_TRUE(bvh2.intersect({{1.0f, 1.0f, -3.0f}, {0, 0, 1}}, 0, INFINITY, h));
    EXPECT_EQ(h.prim, mixed.triangleCount() - 1);
    EXPECT_FLOAT_EQ(h.t, 4.0f);
}

TEST(TriangleBvh, OneAndTwoThreadBuildsAreIdentical) {
    // Big enough for the data-parallel upper levels and parallel subtrees.
    Mesh m = soup(40000, 11);
    const Mesh sphere = icosphere(6, 0.2, 12, 0.8);  // 81920 triangles
    const uint32_t base = uint32_t(m.vertexCount());
    m.pos.insert(m.pos.end(), sphere.pos.begin(), sphere.pos.end());
    for (uint32_t i : sphere.idx) m.idx.push_back(base + i);
    const TriangleBvh one = buildBvh(m, 1), two = buildBvh(m, 2), all = buildBvh(m, 0);
    const TriangleBvh::Stats s1 = one.stats(), s2 = two.stats();
    EXPECT_EQ(s1.nodes, s2.nodes);
    EXPECT_EQ(s1.blocks, s2.blocks);
    EXPECT_EQ(s1.depth, s2.depth);
    EXPECT_EQ(s1.sahCost, s2.sahCost);
    EXPECT_EQ(one.memoryBytes(), two.memoryBytes());
    size_t differ = 0;
    for (const TriRay& r : randomRays(20000, 13, 1.2f, false)) {
        TriHit a, b, c;
        const bool ha = one.intersect(r, 0, INFINITY, a), hb = two.intersect(r, 0, INFINITY, b);
        const bool hc = all.intersect(r, 0, INFINITY, c);
        if (ha != hb || ha != hc || a.prim != b.prim || a.prim != c.prim || a.t != b.t || a.t != c.t || a.u != b.u)
            ++differ;
    }
    EXPECT_EQ(differ, 0u);
}

TEST(TriangleBvh, MemoryPerTriangleWithinBudget) {
    const Mesh grid = bumpyGrid(224, 14);  // 100,352 triangles
    const TriangleBvh bvh = buildBvh(grid);
    const double perTri = double(bvh.memoryBytes()) / double(grid.triangleCount());
    EXPECT_LE(perTri, 100.0);
    const Mesh s = soup(100000, 15);
    const TriangleBvh bvh2 = buildBvh(s);
    EXPECT_LE(double(bvh2.memoryBytes()) / double(s.triangleCount()), 100.0);
    // Sanity: the grid is still intersected correctly from above.
    TriHit h;
    EXPECT_TRUE(bvh.intersect({{0.5f, 0.5f, 3.0f}, {0.01f, 0.02f, -1.0f}}, 0, INFINITY, h));
}

TEST(TriangleBvh, RebuildReplacesContent) {
    TriangleBvh bvh;
    const Mesh a = icosphere(2, 0.0, 16);
    bvh.build(a.pos.data(), a.vertexCount(), a.idx.data(), a.triangleCount());
    TriHit h;
    EXPECT_TRUE(bvh.intersect({{0, 0, -5}, {0, 0, 1}}, 0, INFINITY, h));
    const Mesh b = icosphere(2, 0.0, 16, 1.0, {10, 0, 0});
    bvh.build(b.pos.data(), b.vertexCount(), b.idx.data(), b.triangleCount());
    EXPECT_FALSE(bvh.intersect({{0, 0, -5}, {0, 0, 1}}, 0, INFINITY, h));
    EXPECT_TRUE(bvh.intersect({{10, 0, -5}, {0, 0, 1}}, 0, INFINITY, h));
}

TEST(TriangleBvh, TraversalVariantsGiveTheSameHits) {
    const Mesh m = icosphere(4, 0.3, 17);
    const TriangleBvh bvh = buildBvh(m);
    using V = TriangleBvh::TraversalVariant;
    size_t differ = 0;
    for (const TriRay& r : randomRays(4000, 18, 1.5f, false)) {
        TriHit ref;
        const bool hit = bvh.intersect(r, 0, INFINITY, ref);
        for (V v : {V::Default, V::Unordered, V::ScalarLeaves, V::ScalarLeavesUnordered}) {
            TriHit h;
            const bool vh = bvh.intersect(r, 0, INFINITY, h, v);
            if (vh != hit || (hit && (h.t != ref.t || h.prim != ref.prim))) ++differ;
            if (bvh.occluded(r, 0, INFINITY, v) != hit) ++differ;
        }
    }
    EXPECT_EQ(differ, 0u);
}

}}  // namespace RAYS_TEST_UNIT, namespace
