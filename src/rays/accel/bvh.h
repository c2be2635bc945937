// Acceleration for a scene's objects: untransformed triangles (64 or more) go into a wide SIMD TriangleBvh
// (triangle_bvh.h); the other bounded objects into an 8-wide ObjectBvh (object_bvh.h) whose leaves
// reject with a 4-wide bounding-sphere test before the exact double-precision object tests;
// unbounded objects (planes) are tested separately.
#pragma once
#include <cstdint>
#include <vector>

#include "rays/accel/object_bvh.h"
#include "rays/accel/triangle_bvh.h"
#include "rays/geometry/ray.h"
#include "rays/scene/object.h"

namespace rays {

/// Closest-hit result: object index (−1 when nothing was hit), t and outward world normal.
struct Hit {
    int object = -1;
    double t = kInfinity;
    Vec3 normal;      ///< shading normal (outward)
    Vec3 geomNormal;  ///< geometric normal (outward; decides entering versus leaving)
    bool hasUV = false;   ///< meshes with texture coordinates:
    double u = 0, v = 0;  ///< the uv at the hit
    Vec3 dpdu;            ///< and the object-space tangent dP/du
    bool valid() const { return object >= 0; }
};

class Bvh {
public:
    Bvh() = default;
    /// Builds over objects; planes and other unbounded objects go to a separate list.
    explicit Bvh(const std::vector<Object>& objects);

    /// Nearest hit with t in (tMin, tMax) over all objects.
    Hit closest(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const;
    /// True when any object is hit with t in (tMin, tMax); stops at the first blocker.
    bool any(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const {
        return anyBlocker(objects, ray, tMin, tMax) != kNoBlocker;
    }
    static constexpr int kNoBlocker = -1;     ///< anyBlocker: nothing in the way
    static constexpr int kSomeTriangle = -2;  ///< anyBlocker: blocked by a triangle (which one is not known)
    /// Index of some object hit with t in (tMin, tMax), kSomeTriangle, or kNoBlocker; stops at the
    /// first blocker.
    int anyBlocker(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const;

    /// 8-wide nodes of the object BVH and of the triangle BVH.
    size_t nodeCount() const { return objects_.nodeCount() + triangles_.stats().nodes; }
    size_t triangleCount() const { return triObject_.size(); }
    /// Deeper of the two trees, in wide levels.
    int depth() const;

private:
    ObjectBvh objects_;                ///< bounded objects other than untransformed triangles
    std::vector<uint32_t> unbounded_;  ///< planes: always tested
    TriangleBvh triangles_;            ///< untransformed triangle objects
    std::vector<uint32_t> triObject_;  ///< triangle index in triangles_ → object index
};

}  // namespace rays
