// bench_traverse: Rays' TriangleBvh against Embree 3 (rtcIntersect1 / rtcOccluded1, default
// build) on identical ray sets, in one process.
//
//   bench_traverse [--model bunny.obj] [--pov bunny.pov] [--size WxH] [--reps N] [--quick]
//                  [--mesh small|bunny|big]... [--set primary|shadow|shd-out|shd-in|diffuse]... [--1t] [--ablation]
//
// Meshes: the Stanford bunny (69,451 triangles, scenes/models/; a displaced icosphere of similar size when the
// OBJ is missing), 16 bunnies on a 4x4 grid (1.1 M triangles), and for the scaling target the
// 10,000-triangle bunny of the course scene bench/scenes/course/bunny.pov.gz (a 20k icosphere when
// missing). Model and scene files may be gzip-compressed.
// Ray sets: primary (pinhole camera framing the mesh), shadow (primary hits toward a point
// light) and one-bounce diffuse (cosine-distributed about the geometric normal at primary hits).
// The shadow rays are also timed in two parts, shd-out (those that leave the surface they start
// on: most of what a renderer traces) and shd-in (those that go into it), to show where a
// difference lies.
// Every set is traced with one thread and with all threads; the best of N passes is reported.
// Both libraries' answers are compared: a mismatch is a ray where one hits and the other does
// not, or where the triangles differ and t differs by more than 1e-4 (relative).
// --ablation instead measures the steps from a scalar binary BVH to the full TriangleBvh on one
// thread (docs/performance-bvh.md): binary BVH with scalar box and triangle tests (unordered and
// near-first), then 8-wide SIMD nodes with scalar leaves, + SIMD leaves, + near-first ordering.
#include <embree3/rtcore.h>
#include <tiny_obj_loader.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "rays/accel/binned_sah.h"  // the scalar binary baseline of --ablation
#include "support/icosphere.h"
#include "rays/accel/triangle_bvh.h"

#ifndef RAYS_SOURCE_DIR
#define RAYS_SOURCE_DIR "."
#endif

using namespace rays;

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

struct V3 {
    float x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(V3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
float dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 normalize(V3 a) { return a * (1.0f / std::sqrt(dot(a, a))); }

struct Mesh {
    std::string name;
    std::vector<float> pos;  // xyz
    std::vector<uint32_t> idx;
    size_t vertices() const { return pos.size() / 3; }
    size_t triangles() const { return idx.size() / 3; }
    V3 vertex(uint32_t i) const { return {pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]}; }
    void bounds(V3& lo, V3& hi) const {
        lo = {INFINITY, INFINITY, INFINITY};
        hi = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t i = 0; i < vertices(); ++i) {
            const V3 p = vertex(uint32_t(i));
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        }
    }
};

/// The whole text of a file, gzip-compressed or plain (zlib reads both); false when unreadable.
bool readText(const std::string& path, std::string& text) {
    gzFile f = gzopen(path.c_str(), "rb");
    if (!f) return false;
    char chunk[1 << 16];
    int n = 0;
    while ((n = gzread(f, chunk, sizeof chunk)) > 0) text.append(chunk, size_t(n));
    gzclose(f);
    return n == 0;
}

bool loadObj(const std::string& path, Mesh& m) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    tinyobj::ObjReader reader;
    std::string text;
    if (!readText(path, text) || !reader.ParseFromString(text, "", config)) return false;
    const auto& v = reader.GetAttrib().vertices;
    m.pos.assign(v.begin(), v.end());
    for (const auto& shape : reader.GetShapes())
        for (const auto& i : shape.mesh.indices) m.idx.push_back(uint32_t(i.vertex_index));
    return !m.idx.empty();
}

/// The triangles of a POV-Ray scene written as `triangle { <x,y,z>, <x,y,z>, <x,y,z> ... }`.
bool loadPovTriangles(const std::string& path, Mesh& m) {
    std::string s;
    if (!readText(path, s)) return false;
    std::map<std::array<float, 3>, uint32_t> index;
    size_t at = 0;
    while ((at = s.find("triangle", at)) != std::string::npos) {
        at += 8;
        uint32_t tri[3];
        bool ok = true;
        for (uint32_t& vi : tri) {
            const size_t open = s.find('<', at), close = s.find('>', open);
            if (open == std::string::npos || close == std::string::npos) return !m.idx.empty();
            std::array<float, 3> p{};
            ok = ok && std::sscanf(s.c_str() + open + 1, "%f , %f , %f", &p[0], &p[1], &p[2]) == 3;
            at = close + 1;
            auto it = index.find(p);
            if (it == index.end()) {
                it = index.emplace(p, uint32_t(m.vertices())).first;
                m.pos.insert(m.pos.end(), p.begin(), p.end());
            }
            vi = it->second;
        }
        if (ok) m.idx.insert(m.idx.end(), tri, tri + 3);
    }
    return !m.idx.empty();
}

/// Displaced icosphere with 20 * 4^levels triangles (stand-in when a model file is missing).
Mesh displacedIcosphere(int levels, const std::string& name) {
    const test::Icosphere sphere = test::unitIcosphere(levels);
    Mesh m;
    m.name = name;
    for (const auto& d : sphere.vertices) {
        const V3 p{float(d[0]), float(d[1]), float(d[2])};
        const float r = 0.1f * (1.0f + 0.15f * std::sin(7 * p.x) * std::sin(9 * p.y) + 0.05f * std::sin(31 * p.z));
        const V3 q = p * r;
        m.pos.insert(m.pos.end(), {q.x, q.y, q.z});
    }
    for (const auto& tri : sphere.faces) m.idx.insert(m.idx.end(), tri.begin(), tri.end());
    return m;
}

/// n x n copies of m on the ground plane (x, z), spaced by 1.15 x the footprint.
Mesh grid(const Mesh& m, int n, const std::string& name) {
    V3 lo, hi;
    m.bounds(lo, hi);
    const float sx = 1.15f * (hi.x - lo.x), sz = 1.15f * (hi.z - lo.z);
    Mesh g;
    g.name = name;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const uint32_t base = uint32_t(g.vertices());
            for (size_t k = 0; k < m.vertices(); ++k) {
                const V3 p = m.vertex(uint32_t(k));
                g.pos.insert(g.pos.end(), {p.x + float(i) * sx, p.y, p.z + float(j) * sz});
            }
            for (uint32_t k : m.idx) g.idx.push_back(base + k);
        }
    return g;
}

// ------------------------------------------------------------------------------------ ray sets
struct RaySet {
    std::string name;
    std::vector<TriRay> rays;
    float tMin = 0, tMax = INFINITY;
    bool shadow = false;  ///< traced with occluded / rtcOccluded1
    std::vector<uint8_t> leaving;  ///< shadow rays: 1 when the ray leaves the surface it starts on
};

struct Camera {
    V3 eye, forward, right, up;
};

Camera frame(const Mesh& m, bool fromAbove) {
    V3 lo, hi;
    m.bounds(lo, hi);
    const V3 c = (lo + hi) * 0.5f;
    const float radius = 0.5f * std::sqrt(dot(hi - lo, hi - lo));
    const V3 back = normalize(fromAbove ? V3{0.25f, 0.9f, 1.0f} : V3{0.25f, 0.3f, 1.0f});
    const float fovY = 40.0f * 3.14159265f / 180.0f;
    Camera cam;
    cam.eye = c + back * (radius / std::sin(fovY / 2) * (fromAbove ? 0.62f : 0.62f));
    cam.forward = normalize(c - cam.eye);
    cam.right = normalize(cross(cam.forward, {0, 1, 0}));
    cam.up = cross(cam.right, cam.forward);
    const float h = std::tan(fovY / 2);
    cam.right = cam.right * h;
    cam.up = cam.up * h;
    return cam;
}

RaySet primaryRays(const Camera& cam, int w, int h) {
    RaySet s;
    s.name = "primary";
    s.rays.reserve(size_t(w) * size_t(h));
    const float aspect = float(w) / float(h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float px = (2.0f * (float(x) + 0.5f) / float(w) - 1.0f) * aspect;
            const float py = 1.0f - 2.0f * (float(y) + 0.5f) / float(h);
            const V3 d = normalize(cam.forward + cam.right * px + cam.up * py);
            s.rays.push_back({{cam.eye.x, cam.eye.y, cam.eye.z}, {d.x, d.y, d.z}});
        }
    return s;
}

struct Result {
    uint32_t prim = UINT32_MAX;
    float t = 0;
};

/// The two parts of the shadow set: timed for information, the targets are on the whole set.
bool isShadowPart(const std::string& set) { return set == "shd-out" || set == "shd-in"; }

/// The shadow rays that leave the surface they start on ("shd-out"), or those that go into it
/// ("shd-in") and end on the mesh's far side unless they pass through a hole. Rays' renderer
/// traces the latter only for Blinn-Phong with a specular term: its other shading models ignore
/// a light behind the surface.
RaySet shadowPart(const RaySet& shadow, bool leaving) {
    RaySet part;
    part.name = leaving ? "shd-out" : "shd-in";
    part.shadow = true;
    part.tMin = shadow.tMin;
    part.tMax = shadow.tMax;
    for (size_t i = 0; i < shadow.rays.size(); ++i)
        if (bool(shadow.leaving[i]) == leaving) part.rays.push_back(shadow.rays[i]);
    return part;
}

/// Shadow and diffuse rays from the primary hits (`hits`, as found by Embree). Each shadow ray
/// notes whether the light lies on the side of the hit surface that faces the camera.
void secondaryRays(const Mesh& m, const RaySet& primary, const std::vector<Result>& hits, RaySet& shadow,
                   RaySet& diffuse) {
    V3 lo, hi;
    m.bounds(lo, hi);
    const V3 c = (lo + hi) * 0.5f;
    const float radius = 0.5f * std::sqrt(dot(hi - lo, hi - lo));
    const V3 light = c + V3{-0.6f, 1.5f, 0.9f} * radius;
    shadow.name = "shadow";
    shadow.shadow = true;
    shadow.tMin = 1e-4f;
    shadow.tMax = 1.0f - 1e-4f;
    diffuse.name = "diffuse";
    diffuse.tMin = 1e-4f * radius;
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    for (size_t i = 0; i < primary.rays.size(); ++i) {
        if (hits[i].prim == UINT32_MAX) continue;
        const TriRay& r = primary.rays[i];
        const V3 o{r.org[0], r.org[1], r.org[2]}, d{r.dir[0], r.dir[1], r.dir[2]};
        const V3 p = o + d * hits[i].t;
        const uint32_t* tri = &m.idx[3 * size_t(hits[i].prim)];
        const V3 a = m.vertex(tri[0]), b = m.vertex(tri[1]), cc = m.vertex(tri[2]);
        V3 n = normalize(cross(b - a, cc - a));
        if (dot(n, d) > 0) n = n * -1.0f;
        const V3 toLight = light - p;
        shadow.rays.push_back({{p.x, p.y, p.z}, {toLight.x, toLight.y, toLight.z}});
        shadow.leaving.push_back(dot(n, toLight) > 0);
        // Cosine-distributed direction about n.
        const float r1 = u01(rng), r2 = u01(rng);
        const float phi = 6.2831853f * r1, sr = std::sqrt(r2);
        const V3 t1 = normalize(std::fabs(n.x) > 0.5f ? cross(n, {0, 1, 0}) : cross(n, {1, 0, 0}));
        const V3 t2 = cross(n, t1);
        const V3 dd = normalize(t1 * (sr * std::cos(phi)) + t2 * (sr * std::sin(phi)) + n * std::sqrt(1.0f - r2));
        diffuse.rays.push_back({{p.x, p.y, p.z}, {dd.x, dd.y, dd.z}});
    }
}

// ------------------------------------------------------------------------------------ Embree
std::atomic<long long> gEmbreeBytes{0};

bool memoryMonitor(void*, ssize_t bytes, bool) {
    gEmbreeBytes += bytes;
    return true;
}

struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<float> vertices;  // padded copy (Embree reads 16 bytes per vertex)
    double buildSeconds = 0;
    long long bytes = 0;

    EmbreeScene(const Mesh& m, const char* config) {
        device = rtcNewDevice(config);
        rtcSetDeviceErrorFunction(
            device, [](void*, RTCError code, const char* msg) { std::fprintf(stderr, "Embree error %d: %s\n", code, msg); },
            nullptr);
        rtcSetDeviceMemoryMonitorFunction(device, memoryMonitor, nullptr);
        vertices = m.pos;
        vertices.push_back(0.0f);
        const auto t0 = Clock::now();
        const long long before = gEmbreeBytes.load();
        scene = rtcNewScene(device);
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices.data(), 0,
                                   3 * sizeof(float), m.vertices());
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m.idx.data(), 0,
                                   3 * sizeof(uint32_t), m.triangles());
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        rtcCommitScene(scene);
        buildSeconds = seconds(t0, Clock::now());
        bytes = gEmbreeBytes.load() - before;
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;
};

// ------------------------------------------------------------------------------------ timing
/// Runs body(begin, end) over [0, n) on `threads` threads (dynamic blocks); returns seconds.
double parallelRun(size_t n, int threads, const std::function<void(size_t, size_t)>& body) {
    const auto t0 = Clock::now();
    if (threads <= 1) {
        body(0, n);
    } else {
        std::atomic<size_t> next{0};
        const size_t block = 1024;
        auto work = [&] {
            for (;;) {
                const size_t b = next.fetch_add(block);
                if (b >= n) return;
                body(b, std::min(n, b + block));
            }
        };
        std::vector<std::thread> pool;
        for (int i = 1; i < threads; ++i) pool.emplace_back(work);
        work();
        for (auto& t : pool) t.join();
    }
    return seconds(t0, Clock::now());
}

double traceRays(const TriangleBvh& bvh, const RaySet& s, std::vector<Result>& out, int threads) {
    out.resize(s.rays.size());
    return parallelRun(s.rays.size(), threads, [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) {
            if (s.shadow) {
                out[i].prim = bvh.occluded(s.rays[i], s.tMin, s.tMax) ? 0 : UINT32_MAX;
            } else {
                TriHit h;
                const bool hit = bvh.intersect(s.rays[i], s.tMin, s.tMax, h);
                out[i] = {hit ? h.prim : UINT32_MAX, h.t};
            }
        }
    });
}

double traceEmbree(const EmbreeScene& es, const RaySet& s, std::vector<Result>& out, int threads) {
    out.resize(s.rays.size());
    return parallelRun(s.rays.size(), threads, [&](size_t b, size_t e) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (size_t i = b; i < e; ++i) {
            const TriRay& r = s.rays[i];
            RTCRayHit rh;
            rh.ray.org_x = r.org[0];
            rh.ray.org_y = r.org[1];
            rh.ray.org_z = r.org[2];
            rh.ray.dir_x = r.dir[0];
            rh.ray.dir_y = r.dir[1];
            rh.ray.dir_z = r.dir[2];
            rh.ray.tnear = s.tMin;
            rh.ray.tfar = s.tMax;
            rh.ray.time = 0;
            rh.ray.mask = 0xFFFFFFFFu;
            rh.ray.id = 0;
            rh.ray.flags = 0;
            if (s.shadow) {
                rtcOccluded1(es.scene, &ctx, &rh.ray);
                out[i].prim = rh.ray.tfar < 0 ? 0 : UINT32_MAX;
            } else {
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(es.scene, &ctx, &rh);
                out[i] = {rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? UINT32_MAX : rh.hit.primID, rh.ray.tfar};
            }
        }
    });
}

struct Compare {
    size_t mismatches = 0, sameTDifferentPrim = 0, hits = 0;
};

Compare compare(const std::vector<Result>& a, const std::vector<Result>& b, bool shadow) {
    Compare c;
    for (size_t i = 0; i < a.size(); ++i) {
        const bool ha = a[i].prim != UINT32_MAX, hb = b[i].prim != UINT32_MAX;
        c.hits += hb;
        if (ha != hb) {
            ++c.mismatches;
        } else if (ha && !shadow && a[i].prim != b[i].prim) {
            const float rel = std::fabs(a[i].t - b[i].t) / std::max(std::fabs(b[i].t), 1e-30f);
            ++(rel > 1e-4f ? c.mismatches : c.sameTDifferentPrim);
        }
    }
    return c;
}

struct Options {
    std::string model = std::string(RAYS_SOURCE_DIR) + "/scenes/models/stanford-bunny.obj.gz";
    std::string pov = std::string(RAYS_SOURCE_DIR) + "/bench/scenes/course/bunny.pov.gz";
    int width = 1024, height = 768, reps = 5;
    bool quick = false;
    bool oneThreadOnly = false;           ///< skip the all-threads runs
    bool ablation = false;                ///< measure the optimisation steps instead
    std::vector<std::string> meshes;      ///< subset of small, bunny, big (default: all)
    std::vector<std::string> sets;        ///< subset of primary, shadow, shd-out, shd-in, diffuse (default: all)
    bool wants(const std::string& m) const {
        return meshes.empty() || std::find(meshes.begin(), meshes.end(), m) != meshes.end();
    }
};

struct SetTimes {
    std::string set;
    size_t rays = 0, hits = 0;
    double rays1 = 0, embree1 = 0, raysN = 0, embreeN = 0;  // seconds (best of reps)
    Compare cmp;
};

struct MeshReport {
    std::string name;
    size_t triangles = 0;
    double raysBuild1 = 0, raysBuildN = 0, embreeBuild = 0, embreeBuild1 = 0;
    double raysBytesPerTri = 0, embreeBytesPerTri = 0;
    TriangleBvh::Stats stats;
    std::vector<SetTimes> sets;
};

MeshReport runMesh(const Mesh& m, const Options& o, int threads, bool fromAbove, bool allSets) {
    MeshReport rep;
    rep.name = m.name;
    rep.triangles = m.triangles();
    const int buildReps = o.quick ? 1 : 3;
    TriangleBvh bvh;
    rep.raysBuild1 = rep.raysBuildN = rep.embreeBuild = rep.embreeBuild1 = INFINITY;
    for (int i = 0; i < buildReps; ++i) {
        auto t0 = Clock::now();
        bvh.build(m.pos.data(), m.vertices(), m.idx.data(), m.triangles(), 1);
        rep.raysBuild1 = std::min(rep.raysBuild1, seconds(t0, Clock::now()));
        t0 = Clock::now();
        bvh.build(m.pos.data(), m.vertices(), m.idx.data(), m.triangles(), threads);
        rep.raysBuildN = std::min(rep.raysBuildN, seconds(t0, Clock::now()));
        EmbreeScene one(m, "threads=1");
        rep.embreeBuild1 = std::min(rep.embreeBuild1, one.buildSeconds);
    }
    rep.raysBytesPerTri = double(bvh.memoryBytes()) / double(m.triangles());
    rep.stats = bvh.stats();
    std::unique_ptr<EmbreeScene> es;
    for (int i = 0; i < buildReps; ++i) {
        es.reset();
        es = std::make_unique<EmbreeScene>(m, nullptr);
        rep.embreeBuild = std::min(rep.embreeBuild, es->buildSeconds);
    }
    rep.embreeBytesPerTri = double(es->bytes) / double(m.triangles());

    const Camera cam = frame(m, fromAbove);
    std::vector<RaySet> sets;
    sets.push_back(primaryRays(cam, o.width, o.height));
    std::vector<Result> primaryHits;
    traceEmbree(*es, sets[0], primaryHits, threads);
    if (allSets) {
        RaySet shadow, diffuse;
        secondaryRays(m, sets[0], primaryHits, shadow, diffuse);
        RaySet out = shadowPart(shadow, true), in = shadowPart(shadow, false);
        sets.push_back(std::move(shadow));
        sets.push_back(std::move(out));
        sets.push_back(std::move(in));
        sets.push_back(std::move(diffuse));
    }
    for (const RaySet& s : sets) {
        if (!o.sets.empty() && std::find(o.sets.begin(), o.sets.end(), s.name) == o.sets.end()) continue;
        SetTimes st;
        st.set = s.name;
        st.rays = s.rays.size();
        st.rays1 = st.embree1 = st.raysN = st.embreeN = INFINITY;
        std::vector<Result> a, b;
        // Interleave the libraries so that machine noise affects both alike.
        for (int rep = 0; rep < o.reps; ++rep) {
            st.rays1 = std::min(st.rays1, traceRays(bvh, s, a, 1));
            st.embree1 = std::min(st.embree1, traceEmbree(*es, s, b, 1));
            if (o.oneThreadOnly) continue;
            st.raysN = std::min(st.raysN, traceRays(bvh, s, a, threads));
            st.embreeN = std::min(st.embreeN, traceEmbree(*es, s, b, threads));
        }
        st.cmp = compare(a, b, s.shadow);
        st.hits = st.cmp.hits;
        rep.sets.push_back(st);
    }
    return rep;
}

void printReport(const MeshReport& r, int threads) {
    std::printf("\n%s: %zu triangles  |  Rays BVH: %zu nodes, %zu leaves, %zu blocks, depth %d, SAH %.1f\n", r.name.c_str(),
                r.triangles, r.stats.nodes, r.stats.leaves, r.stats.blocks, r.stats.depth, r.stats.sahCost);
    std::printf("  build: Rays %.3f s (1 thread), %.3f s (%d threads)  |  Embree %.3f s (default, %d threads), "
                "%.3f s (1 thread)  |  Rays/Embree %.2fx (all threads)\n",
                r.raysBuild1, r.raysBuildN, threads, r.embreeBuild, threads, r.embreeBuild1, r.raysBuildN / r.embreeBuild);
    std::printf("  memory: Rays %.1f B/triangle, Embree %.1f B/triangle\n", r.raysBytesPerTri, r.embreeBytesPerTri);
    std::printf("  %-8s %9s %8s | %8s %8s %6s | %8s %8s %6s | %7s %7s | %s\n", "rays", "count", "hit %", "Rays 1T",
                "Embree", "ratio", "Rays NT", "Embree", "ratio", "Rays", "Embree", "mismatches");
    std::printf("  %-8s %9s %8s | %8s %8s %6s | %8s %8s %6s | %7s %7s |\n", "", "", "", "Mrays/s", "Mrays/s", "", "Mrays/s",
                "Mrays/s", "", "NT/1T", "NT/1T");
    for (const SetTimes& s : r.sets) {
        const double n = double(s.rays) * 1e-6;
        std::printf("  %-8s %9zu %7.1f%% | %8.2f %8.2f %5.2fx | %8.2f %8.2f %5.2fx | %6.2fx %6.2fx | %zu (+%zu same-t)\n",
                    s.set.c_str(), s.rays, 100.0 * double(s.hits) / double(std::max<size_t>(1, s.rays)), n / s.rays1,
                    n / s.embree1, s.embree1 / s.rays1, n / s.raysN, n / s.embreeN, s.embreeN / s.raysN,
                    s.rays1 / s.raysN, s.embree1 / s.embreeN, s.cmp.mismatches, s.cmp.sameTDifferentPrim);
    }
    if (std::any_of(r.sets.begin(), r.sets.end(), [](const SetTimes& s) { return isShadowPart(s.set); }))
        std::printf("  (shd-out / shd-in: the shadow rays that leave / go into the surface they start on)\n");
}


// ------------------------------------------------------------------------------------ ablation
/// The scalar baseline: the same binned-SAH builder's binary tree (32-byte nodes), scalar slab
/// tests, the same watertight triangle test in scalar code on triangles copied in leaf order.
struct BinaryBaseline {
    tribvh::BinaryBvh bvh;
    struct Tri {
        float v[3][3];
        uint32_t prim;
    };
    std::vector<Tri> tris;  // in PrimRef order: leaf [first, first + count)

    explicit BinaryBaseline(const Mesh& m) {
        tribvh::TaskPool pool(1);
        tribvh::HugeArray<tribvh::PrimRef> refs(m.triangles());
        for (size_t i = 0; i < m.triangles(); ++i) {
            tribvh::PrimRef& r = refs[i];
            r.id = uint32_t(i);
            r.pad = 0;
            for (int a = 0; a < 3; ++a) {
                r.lo[a] = INFINITY;
                r.hi[a] = -INFINITY;
                for (int k = 0; k < 3; ++k) {
                    const float c = m.pos[3 * size_t(m.idx[3 * i + size_t(k)]) + size_t(a)];
                    r.lo[a] = std::min(r.lo[a], c);
                    r.hi[a] = std::max(r.hi[a], c);
                }
            }
        }
        tribvh::SahSettings settings;  // leaves of up to 4 triangles, as in the wide tree
        bvh = tribvh::buildBinnedSah(refs, settings, pool);
        tris.resize(m.triangles());
        for (size_t i = 0; i < m.triangles(); ++i) {
            const uint32_t prim = refs[i].id;
            for (int k = 0; k < 3; ++k)
                for (int a = 0; a < 3; ++a) tris[i].v[k][a] = m.pos[3 * size_t(m.idx[3 * size_t(prim) + size_t(k)]) + size_t(a)];
            tris[i].prim = prim;
        }
    }

    struct Ray {
        float rd[3], od[3], rdFar[3], odFar[3];
        int kx, ky, kz;
        float sx, sy, sz, o[3];
    };
    static Ray prepare(const TriRay& r) {
        Ray p;
        for (int a = 0; a < 3; ++a) {
            float d = r.dir[a];
            if (std::fabs(d) < 1e-30f) d = std::copysign(1e-30f, d);
            const float rd = 1.0f / d, od = r.org[a] * rd, slack = std::fabs(od) * 0x1p-20f;
            p.rd[a] = rd;
            p.od[a] = od + slack;
            p.rdFar[a] = rd * (1.0f + 0x1p-20f);
            p.odFar[a] = od * (1.0f + 0x1p-20f) - slack;
        }
        const float ax = std::fabs(r.dir[0]), ay = std::fabs(r.dir[1]), az = std::fabs(r.dir[2]);
        p.kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        p.kx = (p.kz + 1) % 3;
        p.ky = (p.kx + 1) % 3;
        if (r.dir[p.kz] < 0.0f) std::swap(p.kx, p.ky);
        p.sz = 1.0f / r.dir[p.kz];
        p.sx = r.dir[p.kx] * p.sz;
        p.sy = r.dir[p.ky] * p.sz;
        p.o[0] = r.org[p.kx];
        p.o[1] = r.org[p.ky];
        p.o[2] = r.org[p.kz];
        return p;
    }
    /// Entry distance of the box or +inf.
    static float box(const tribvh::BinaryNode& n, const Ray& p, float tMin, float tMax) {
        float t0 = tMin, t1 = tMax;
        for (int a = 0; a < 3; ++a) {
            const bool neg = p.rd[a] < 0.0f;
            const float tn = (neg ? n.hi[a] : n.lo[a]) * p.rd[a] - p.od[a];
            const float tf = (neg ? n.lo[a] : n.hi[a]) * p.rdFar[a] - p.odFar[a];
            t0 = tn > t0 ? tn : t0;
            t1 = tf < t1 ? tf : t1;
        }
        return t0 <= t1 ? t0 : INFINITY;
    }
    static bool triangle(const Tri& tr, const Ray& p, float tMin, float tHit, float& t) {
        float px[3], py[3], pz[3];
        for (int k = 0; k < 3; ++k) {
            const float dx = tr.v[k][p.kx] - p.o[0], dy = tr.v[k][p.ky] - p.o[1], dz = tr.v[k][p.kz] - p.o[2];
            px[k] = dx - p.sx * dz;
            py[k] = dy - p.sy * dz;
            pz[k] = p.sz * dz;
        }
        const float e0 = px[2] * py[1] - py[2] * px[1];
        const float e1 = px[0] * py[2] - py[0] * px[2];
        const float e2 = px[1] * py[0] - py[1] * px[0];
        if (!((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0))) return false;
        const float det = e0 + e1 + e2;
        if (det == 0.0f) return false;
        const float tt = (e0 * pz[0] + e1 * pz[1] + e2 * pz[2]) / det;
        if (!(tt > tMin && tt < tHit)) return false;
        t = tt;
        return true;
    }
    template <bool AnyHit, bool Ordered>
    bool trace(const TriRay& ray, float tMin, float tMax, Result& out) const {
        const Ray p = prepare(ray);
        struct Entry {
            uint32_t node;
            float dist;
        };
        Entry stack[256];
        int sp = 0;
        uint32_t node = bvh.root;
        float tHit = tMax;
        uint32_t prim = UINT32_MAX;
        if (box(bvh.nodes[node], p, tMin, tMax) == INFINITY) return false;
        for (;;) {
            const tribvh::BinaryNode& n = bvh.nodes[node];
            if (n.leaf()) {
                for (uint32_t i = n.first; i < n.first + n.count; ++i) {
                    float t;
                    if (triangle(tris[i], p, tMin, tHit, t)) {
                        if (AnyHit) return true;
                        tHit = t;
                        prim = tris[i].prim;
                    }
                }
            } else {
                const float d0 = box(bvh.nodes[n.first], p, tMin, tHit);
                const float d1 = box(bvh.nodes[n.first + 1], p, tMin, tHit);
                if (d0 != INFINITY && d1 != INFINITY) {
                    const bool swap = Ordered && d1 < d0;
                    stack[sp++] = {swap ? n.first : n.first + 1, swap ? d0 : d1};
                    node = swap ? n.first + 1 : n.first;
                    continue;
                }
                if (d0 != INFINITY || d1 != INFINITY) {
                    node = d0 != INFINITY ? n.first : n.first + 1;
                    continue;
                }
            }
            for (;;) {
                if (sp == 0) {
                    out = {prim, tHit};
                    return prim != UINT32_MAX;
                }
                const Entry e = stack[--sp];
                if (AnyHit || e.dist <= tHit) {
                    node = e.node;
                    break;
                }
            }
        }
    }
};

void runAblation(const Mesh& m, const Options& o) {
    const Camera cam = frame(m, m.triangles() > 500000);
    TriangleBvh bvh;
    bvh.build(m.pos.data(), m.vertices(), m.idx.data(), m.triangles(), 0);
    const BinaryBaseline bin(m);
    std::vector<RaySet> sets;
    sets.push_back(primaryRays(cam, o.width, o.height));
    std::vector<Result> hits(sets[0].rays.size());
    for (size_t i = 0; i < hits.size(); ++i) {
        TriHit h;
        if (bvh.intersect(sets[0].rays[i], sets[0].tMin, sets[0].tMax, h)) hits[i] = {h.prim, h.t};
    }
    RaySet shadow, diffuse;
    secondaryRays(m, sets[0], hits, shadow, diffuse);
    sets.push_back(std::move(shadow));
    sets.push_back(std::move(diffuse));

    using V = TriangleBvh::TraversalVariant;
    struct Step {
        const char* name;
        std::function<bool(const TriRay&, float, float, Result&, bool)> trace;
    };
    const std::vector<Step> steps = {
        {"binary BVH, scalar, unordered",
         [&](const TriRay& r, float a, float b, Result& out, bool any) {
             return any ? bin.trace<true, false>(r, a, b, out) : bin.trace<false, false>(r, a, b, out);
         }},
        {"binary BVH, scalar, near-first",
         [&](const TriRay& r, float a, float b, Result& out, bool any) {
             return any ? bin.trace<true, false>(r, a, b, out) : bin.trace<false, true>(r, a, b, out);
         }},
        {"8-wide SIMD nodes, scalar leaves, unordered",
         [&](const TriRay& r, float a, float b, Result& out, bool any) {
             TriHit h;
             const bool hit = any ? bvh.occluded(r, a, b, V::ScalarLeavesUnordered)
                                  : bvh.intersect(r, a, b, h, V::ScalarLeavesUnordered);
             out = {hit ? (any ? 0 : h.prim) : UINT32_MAX, h.t};
             return hit;
         }},
        {"  + 4-wide SIMD leaves (unordered)",
         [&](const TriRay& r, float a, float b, Result& out, bool any) {
             TriHit h;
             const bool hit = any ? bvh.occluded(r, a, b, V::Unordered) : bvh.intersect(r, a, b, h, V::Unordered);
             out = {hit ? (any ? 0 : h.prim) : UINT32_MAX, h.t};
             return hit;
         }},
        {"  + near-first ordering (= TriangleBvh)",
         [&](const TriRay& r, float a, float b, Result& out, bool any) {
             TriHit h;
             const bool hit = any ? bvh.occluded(r, a, b) : bvh.intersect(r, a, b, h);
             out = {hit ? (any ? 0 : h.prim) : UINT32_MAX, h.t};
             return hit;
         }},
    };
    std::printf("\nablation, %s (%zu triangles), one thread, Mrays/s (best of %d, steps interleaved):\n", m.name.c_str(),
                m.triangles(), o.reps);
    std::printf("  %-44s %9s %9s %9s\n", "", sets[0].name.c_str(), sets[1].name.c_str(), sets[2].name.c_str());
    std::vector<std::vector<double>> best(steps.size(), std::vector<double>(sets.size(), INFINITY));
    for (int rep = 0; rep < o.reps; ++rep)
        for (size_t k = 0; k < steps.size(); ++k)
            for (size_t si = 0; si < sets.size(); ++si) {
                const RaySet& s = sets[si];
                std::vector<Result> out(s.rays.size());
                const double sec = parallelRun(s.rays.size(), 1, [&](size_t b, size_t e) {
                    for (size_t i = b; i < e; ++i) steps[k].trace(s.rays[i], s.tMin, s.tMax, out[i], s.shadow);
                });
                best[k][si] = std::min(best[k][si], sec);
            }
    for (size_t k = 0; k < steps.size(); ++k) {
        std::printf("  %-44s", steps[k].name);
        for (size_t si = 0; si < sets.size(); ++si) std::printf(" %9.2f", double(sets[si].rays.size()) * 1e-6 / best[k][si]);
        std::printf("\n");
    }
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "missing value for %s\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--model") {
            o.model = next();
        } else if (a == "--pov") {
            o.pov = next();
        } else if (a == "--size") {
            if (std::sscanf(next().c_str(), "%dx%d", &o.width, &o.height) != 2) return 2;
        } else if (a == "--reps") {
            o.reps = std::max(1, std::atoi(next().c_str()));
        } else if (a == "--mesh") {
            o.meshes.push_back(next());
        } else if (a == "--ablation") {
            o.ablation = true;
        } else if (a == "--set") {
            o.sets.push_back(next());
        } else if (a == "--1t") {
            o.oneThreadOnly = true;
        } else if (a == "--quick") {
            o.quick = true;
            o.reps = 1;
            o.width = 512;
            o.height = 384;
        } else {
            std::fprintf(stderr,
                         "usage: %s [--model bunny.obj] [--pov bunny.pov] [--size WxH] [--reps N] [--quick]\n"
                         "          [--mesh small|bunny|big]... [--set primary|shadow|shd-out|shd-in|diffuse]... [--1t] [--ablation]\n",
                         argv[0]);
            return 2;
        }
    }
    const int threads = int(std::max(1u, std::thread::hardware_concurrency()));

    Mesh bunny;
    bunny.name = "bunny";
    if (!loadObj(o.model, bunny)) {
        std::printf("(%s not found: using a displaced icosphere instead)\n", o.model.c_str());
        bunny = displacedIcosphere(6, "icosphere-82k");
    }
    Mesh small;
    small.name = "bunny-10k";
    if (!loadPovTriangles(o.pov, small)) small = displacedIcosphere(5, "icosphere-20k");
    const Mesh big = grid(bunny, 4, bunny.name + "-x16");

    std::printf("bench_traverse: Rays TriangleBvh vs Embree %d.%d.%d, %dx%d primary rays, best of %d, %d threads\n",
                RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH, o.width, o.height, o.reps, threads);
    std::printf("Mrays/s (higher is better); ratio = Rays speed / Embree speed (>= 1: Rays faster)\n");

    if (o.ablation) {
        if (o.wants("small")) runAblation(small, o);
        if (o.wants("bunny")) runAblation(bunny, o);
        if (o.wants("big")) runAblation(big, o);
        return 0;
    }

    std::vector<MeshReport> reports;
    const MeshReport* rs = nullptr;
    const MeshReport* rg = nullptr;
    reports.reserve(3);
    if (o.wants("small")) {
        reports.push_back(runMesh(small, o, threads, false, false));
        printReport(reports.back(), threads);
        rs = &reports.back();
    }
    if (o.wants("bunny")) {
        reports.push_back(runMesh(bunny, o, threads, false, true));
        printReport(reports.back(), threads);
    }
    if (o.wants("big")) {
        reports.push_back(runMesh(big, o, threads, true, true));
        printReport(reports.back(), threads);
        rg = &reports.back();
    }

    // Targets.
    std::printf("\nTargets (one thread unless noted):\n");
    auto target = [](const std::string& what, double value, double goal, double floor, bool higherIsBetter) {
        const bool ok = higherIsBetter ? value >= goal : value <= goal;
        const bool okFloor = higherIsBetter ? value >= floor : value <= floor;
        std::printf("  %-58s %6.2f  (target %s %.2f)  %s\n", what.c_str(), value, higherIsBetter ? ">=" : "<=", goal,
                    ok ? "met" : (okFloor ? "below target, above floor" : "MISSED"));
    };
    for (const MeshReport& r : reports) {
        if (r.name == small.name) continue;
        for (const SetTimes& s : r.sets)
            if (s.set != "diffuse" && !isShadowPart(s.set)) target(r.name + " " + s.set + ": Rays / Embree speed", s.embree1 / s.rays1, 1.0, 0.8, true);
        target(r.name + " build (all threads): Rays / Embree time", r.raysBuildN / r.embreeBuild, 1.5, 1.5, false);
    }
    if (rs && rg && !rs->sets.empty() && !rg->sets.empty() && rs->sets[0].set == "primary" &&
        rg->sets[0].set == "primary") {
        const double growth = (rg->sets[0].rays1 / double(rg->sets[0].rays)) / (rs->sets[0].rays1 / double(rs->sets[0].rays));
        const double growthE =
            (rg->sets[0].embree1 / double(rg->sets[0].rays)) / (rs->sets[0].embree1 / double(rs->sets[0].rays));
        target("primary time per ray, " + rs->name + " -> " + rg->name + ": Rays growth", growth, 2.5, 2.5, false);
        std::printf("  (Embree's growth on the same meshes: x%.2f)\n", growthE);
    }
    if (!o.oneThreadOnly)
        for (const MeshReport& r : reports) {
            if (r.name == small.name) continue;
            for (const SetTimes& s : r.sets)
                if (!isShadowPart(s.set))
                    target(r.name + " " + s.set + ": Rays " + std::to_string(threads) + "T / 1T speed-up",
                           s.rays1 / s.raysN, 1.85, 1.85, true);
        }
    return 0;
}
