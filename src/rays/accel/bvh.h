// Acceleration for a scene's objects: untransformed triangles go into a wide SIMD TriangleBvh
// (triangle_bvh.h); the other bounded objects into a binary BVH (binned SAH, Wald 2007; ordered
// traversal with an any-hit variant); unbounded objects (planes) are tested separately.
#pragma once
#include <cstdint>
#include <vector>

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

/// Build-time node (double bounds).
struct BvhNode {
    Bounds bounds;
    uint32_t first = 0;  ///< leaf: first index into the primitive list; inner: index of the left child
    uint32_t count = 0;  ///< leaf: number of primitives; inner: 0 (right child = left + 1)
};

/// Traversal node: 32 bytes, two per cache line; float bounds rounded outward and padded so the
/// float slab test never misses what the double bounds contain.
struct FlatNode {
    float lo[3];
    uint32_t first;
    float hi[3];
    uint32_t count;
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

    size_t nodeCount() const { return nodes_.size(); }
    size_t triangleCount() const { return triObject_.size(); }
    int depth() const;

private:
    void build(std::vector<Bounds>& primBounds, std::vector<Vec3>& centroids, uint32_t begin,
               uint32_t end);
    void medianPartition(std::vector<Bounds>& primBounds, std::vector<Vec3>& centroids, uint32_t begin,
                         uint32_t mid, uint32_t end, int axis);

    std::vector<BvhNode> nodes_;       ///< build result
    std::vector<FlatNode> flat_;       ///< what traversal reads
    std::vector<uint32_t> prims_;      ///< object indices, leaves reference ranges of this
    std::vector<uint32_t> unbounded_;  ///< planes: always tested
    TriangleBvh triangles_;            ///< untransformed triangle objects
    std::vector<uint32_t> triObject_;  ///< triangle index in triangles_ → object index
};

}  // namespace rays
