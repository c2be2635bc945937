#include "rays/accel/bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rays/accel/object_bvh_traverse.h"
#include "rays/geometry/sphere_hit.h"

namespace rays {
namespace {

constexpr float kFloatInf = std::numeric_limits<float>::infinity();

// Float versions of the ray interval, widened so float rounding never cuts a real hit.
inline float lowerT(double t) { return float(t) - 1e-6f * std::fabs(float(t)); }
inline float upperT(double t) { return std::isinf(t) ? kFloatInf : float(t) * (1 + 1e-6f) + 1e-30f; }

TriRay floatRay(const Ray& r) {
    return {{float(r.origin.x), float(r.origin.y), float(r.origin.z)}, {float(r.dir.x), float(r.dir.y), float(r.dir.z)}};
}

Vec3 centreOf(const ObjectBvh::ExactSphere& s) { return {s.centre[0], s.centre[1], s.centre[2]}; }

// best ← the object hit sh of object id.
void take(Hit& best, uint32_t id, const ShapeHit& sh) {
    best.t = sh.t;
    best.object = int(id);
    best.normal = sh.normal;
    best.geomNormal = sh.geomNormal;
    best.hasUV = sh.hasUV;
    best.u = sh.u;
    best.v = sh.v;
    best.dpdu = sh.dpdu;
}

// The object BVH's entry for o: its world box and, for spheres intersected in world space, the
// sphere itself as the bounding sphere of the leaf reject test.
ObjectBvh::Prim objectPrim(const Object& o, const Bounds& b, uint32_t id) {
    ObjectBvh::Prim p;
    for (int a = 0; a < 3; ++a) {
        p.lo[a] = b.lo[a];
        p.hi[a] = b.hi[a];
    }
    p.id = id;
    if (o.type == ShapeType::Sphere && !o.localSpace) {
        for (int a = 0; a < 3; ++a) p.center[a] = o.p1[a];
        p.sphereRadius = o.r1;
        p.isSphere = true;
    }
    return p;
}

bool finiteBounds(const Bounds& b) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a])) return false;
    return true;
}

}  // namespace

// Below this many untransformed triangles, a separate triangle BVH (a second traversal per ray,
// with its own setup) costs more than testing them as objects.
constexpr size_t kTriangleBvhMin = 64;

Bvh::Bvh(const std::vector<Object>& objects) {
    std::vector<ObjectBvh::Prim> prims;
    std::vector<float> positions;
    std::vector<uint32_t> indices;
    size_t plainTriangles = 0;
    for (const Object& o : objects) plainTriangles += o.type == ShapeType::Triangle && !o.localSpace;
    const bool triangleBvh = plainTriangles >= kTriangleBvhMin;
    for (uint32_t i = 0; i < objects.size(); ++i) {
        const Object& o = objects[i];
        if (triangleBvh && o.type == ShapeType::Triangle && !o.localSpace) {
            for (Vec3 p : {o.p0, o.p1, o.p2}) {
                indices.push_back(uint32_t(positions.size() / 3));
                positions.insert(positions.end(), {float(p.x), float(p.y), float(p.z)});
            }
            triObject_.push_back(i);
            continue;
        }
        const Bounds b = worldBounds(o);
        if (b.empty() || !finiteBounds(b)) {  // planes, and anything without a usable box
            unbounded_.push_back(i);
            continue;
        }
        prims.push_back(objectPrim(o, b, i));
    }
    if (!triObject_.empty())
        triangles_.build(positions.data(), positions.size() / 3, indices.data(), triObject_.size());
    objects_.build(prims);
}

Hit Bvh::closest(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const {
    Hit best;
    best.t = tMax;
    ShapeHit sh;
    for (uint32_t id : unbounded_)
        if (intersect(objects[id], ray, tMin, best.t, sh)) take(best, id, sh);
    const TriRay fr = floatRay(ray);
    if (!triangles_.empty()) {
        TriHit th;
        if (triangles_.intersect(fr, float(tMin), upperT(best.t), th)) {
            // Refine in double precision on the triangle found (exact t and normal for the
            // course's printouts); fall back to the float hit at a grazing edge.
            const uint32_t id = triObject_[th.prim];
            if (intersect(objects[id], ray, tMin, kInfinity, sh) && sh.t < best.t) {
                take(best, id, sh);
            } else if (double(th.t) < best.t && double(th.t) > tMin) {
                const Object& o = objects[id];
                best.t = th.t;
                best.object = int(id);
                best.hasUV = false;
                best.geomNormal = normalize(cross(o.p1 - o.p0, o.p2 - o.p0));
                best.normal = o.smooth ? normalize((1 - th.u - th.v) * o.n0 + th.u * o.n1 + th.v * o.n2) : best.geomNormal;
                if (dot(best.normal, best.geomNormal) < 0) best.normal = -best.normal;
            }
        }
    }
    // Sphere and world-space triangle hits get their normals once, for the object that is nearest
    // in the end (the same tests and formulas as intersect()).
    const ObjectBvh::ExactSphere* bestSphere = nullptr;
    const Object* bestTriangle = nullptr;
    double triangleU = 0, triangleV = 0;
    auto found = [&](uint32_t id, double t, float& tBest) {
        best.t = t;
        best.object = int(id);
        best.hasUV = false;
        tBest = upperT(t);
    };
    auto exact = [&](uint32_t id, const ObjectBvh::ExactSphere& sphere, float& tBest) {
        double t;
        if (sphere.radius >= 0) {  // on the slot's compact copy of the sphere
            if (!sphereHitT(centreOf(sphere), sphere.radius, ray, tMin, best.t, t)) return false;
            found(id, t, tBest);
            bestSphere = &sphere;
            bestTriangle = nullptr;
            return false;
        }
        const Object& o = objects[id];
        if (o.type == ShapeType::Triangle && !usesLocalSpace(o)) {
            double u, v;
            if (!triangleHitT(o, ray, tMin, best.t, t, u, v)) return false;
            found(id, t, tBest);
            bestSphere = nullptr;
            bestTriangle = &o;
            triangleU = u;
            triangleV = v;
            return false;
        }
        if (!intersect(o, ray, tMin, best.t, sh)) return false;
        take(best, id, sh);
        bestSphere = nullptr;
        bestTriangle = nullptr;
        tBest = upperT(best.t);
        return false;
    };
    objects_.traverse<false>(fr.org, fr.dir, lowerT(tMin), upperT(best.t), exact);
    if (bestSphere) {
        best.normal = sphereNormal(centreOf(*bestSphere), bestSphere->radius, ray, best.t);
        best.geomNormal = best.normal;
    } else if (bestTriangle) {
        triangleNormals(*bestTriangle, triangleU, triangleV, best.geomNormal, best.normal);
    }
    return best;
}

int Bvh::anyBlocker(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const {
    for (uint32_t id : unbounded_)
        if (occludes(objects[id], ray, tMin, tMax)) return int(id);
    const TriRay fr = floatRay(ray);
    if (!triangles_.empty()) {
        // Float origins are rounded by up to half an ulp of their largest coordinate: widen the
        // interval's end by that much so that a blocker right at tMax is still found.
        const double slack = 1e-6 * (std::max({std::fabs(ray.origin.x), std::fabs(ray.origin.y), std::fabs(ray.origin.z)}) + 1.0);
        if (triangles_.occluded(fr, float(tMin), upperT(tMax + slack))) return kSomeTriangle;
    }
    int blocker = kNoBlocker;
    auto exact = [&](uint32_t id, const ObjectBvh::ExactSphere& sphere, float&) {
        double t;
        if (sphere.radius >= 0
                ? !sphereHitT(centreOf(sphere), sphere.radius, ray, tMin, tMax, t)
                : !occludes(objects[id], ray, tMin, tMax))
            return false;
        blocker = int(id);
        return true;
    };
    objects_.traverse<true>(fr.org, fr.dir, lowerT(tMin), upperT(tMax), exact);
    return blocker;
}

int Bvh::depth() const { return std::max(objects_.depth(), triangles_.stats().depth); }

}  // namespace rays
