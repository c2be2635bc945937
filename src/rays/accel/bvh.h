// Acceleration for a scene's objects: untransformed triangles (64 or more) go into a wide SIMD TriangleBvh
// (triangle_bvh.h); the other bounded objects into an 8-wide ObjectBvh (object_bvh.h) whose leaves
// reject with a 4-wide bounding-sphere test before the exact double-precision object tests;
// unbounded objects (planes) are tested separately.
#pragma once
#include <cstdint>
#include <vector>

#include "rays/accel/object_bvh.h"
#include "rays/accel/origin_buffer.h"
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
    const Object* part = nullptr;  ///< CSG objects: the leaf hit (material, texture space)
    CornerBlend blend;             ///< a mesh face textured per vertex: its corners' textures and weights
    bool cutawayBlend = false;     ///< ShapeHit::cutawayBlend
    bool valid() const { return object >= 0; }
};

/// The object whose material and texture space shade hit h: the CSG leaf hit, or the object.
inline const Object& shadedObject(const std::vector<Object>& objects, const Hit& h) {
    return h.part ? *h.part : objects[size_t(h.object)];
}

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

    /// occludes(objects[id], ...) on the BVH's compact copy of the object when it has one (world
    /// spheres): the same test without loading the object.
    bool occludesObject(const std::vector<Object>& objects, uint32_t id, const Ray& ray, double tMin, double tMax) const;

    /// Bounds of the objects in the object BVH, for an OriginBuffer over them (its entry ids are
    /// positions in this list).
    std::vector<OriginBuffer::Bound> originBounds(const std::vector<Object>& objects) const;
    size_t boundedCount() const { return bounded_.size(); }
    /// closest() for a ray that starts at the origin of an OriginBuffer built over originBounds()
    /// with no dilation; cells: the buffer's cells of ray.dir. The object BVH's objects come from
    /// the cells' lists. Same result.
    Hit closestFrom(const OriginBuffer::Cells& cells, const std::vector<Object>& objects, const Ray& ray, double tMin,
                    double tMax) const;
    /// anyBlocker() for a ray that runs, from tMin to tMax, within the dilation of an OriginBuffer
    /// built over originBounds() of the segment from its origin to origin + toPoint (a shadow
    /// ray from a point near a surface towards a point light at the origin); cells: the buffer's
    /// cells of toPoint, reach: |toPoint|. Same result.
    int anyBlockerFrom(const OriginBuffer::Cells& cells, const std::vector<Object>& objects, const Ray& ray,
                       double tMin, double tMax, double reach) const;

    /// 8-wide nodes of the object BVH and of the triangle BVH.
    size_t nodeCount() const { return objects_.nodeCount() + triangles_.stats().nodes; }
    size_t triangleCount() const { return triObject_.size(); }
    /// Deeper of the two trees, in wide levels.
    int depth() const;

private:
    /// An object of the object BVH: its index and, for world-space spheres, the sphere; for
    /// world-space triangles the index of their plane in planes_ (else -1).
    struct Bounded {
        ObjectBvh::ExactSphere sphere;
        uint32_t id;
        int32_t plane;
        Bounds box;  ///< world box, widened for rounding (the few-objects walk's reject test)
    };
    /// Whether the ray may meet box b with t in [tMin, tMax]; invDir = 1 / ray.dir.
    static bool meetsBox(const Bounds& b, const Ray& ray, Vec3 invDir, double tMin, double tMax);
    /// dot(normal, x) = offset for every point x of a flat object (normal unit length), up to rounding.
    struct Plane {
        Vec3 normal;
        double offset;
    };
    /// False when the ray a + t·d, t in [0, tEnd], stays on one side of the plane (beyond the
    /// rounding of its offset): no flat object in the plane can meet it.
    static bool reachesPlane(const Plane& p, Vec3 a, Vec3 d, double tEnd);
    /// reachesPlane of the last plane asked within one walk of a ray, remembered: coplanar objects
    /// (a floor made of triangles) share the answer. A walk's end only comes nearer, so a plane
    /// the ray did not reach stays unreached, and one it reached is at worst tested for nothing.
    struct PlaneMemo {
        int32_t plane = -1;
        bool result = true;
        bool reaches(const Bvh& bvh, int32_t p, const Ray& ray, double tEnd) {
            if (p != plane) {
                plane = p;
                result = reachesPlane(bvh.planes_[size_t(p)], ray.origin, ray.dir, tEnd);
            }
            return result;
        }
    };
    /// Index in planes_ of the plane of a world-space triangle o with normal n (non-zero), shared
    /// with the earlier triangles of exactly that plane.
    int32_t planeIndex(Vec3 n, const Object& o) { return planeIndexIn(planes_, n, o); }
    /// The same in any plane list.
    static int32_t planeIndexIn(std::vector<Plane>& planes, Vec3 n, const Object& o);
    /// Adds o's plane to trianglePlanes_ and returns its index; -1 when o's vertices are not on
    /// it within rounding (then the plane walk is not safe), -2 for a triangle that cannot be hit.
    int32_t addTrianglePlane(const Object& o);
    /// Nearest triangle hit by walking the planes the ray crosses, nearest first, and testing
    /// only their triangles (the triangles lie in few planes); updates best when nearer.
    void closestOnPlanes(const std::vector<Object>& objects, const Ray& ray, double tMin, Hit& best) const;
    /// A triangle on a plane the ray crosses before tMax that blocks it, or kNoBlocker.
    int blockerOnPlanes(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const;
    /// Nearest hit among the planes and the triangle BVH (the part of closest() that does not
    /// depend on how the other objects are found).
    Hit closestUnbounded(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const;
    /// A blocker among the planes and the triangle BVH, or kNoBlocker.
    int blockerUnbounded(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const;
    /// Calls visit(bounded object) for the entries of the fine, then the coarse list of cells, in
    /// order, while their minDist is at most reach (read again after each call, which may lower
    /// it), until visit returns true. Defined in bvh.cpp.
    template <class Visit>
    void walkCells(const OriginBuffer::Cells& cells, const double& reach, Visit&& visit) const;

    ObjectBvh objects_;                ///< bounded objects other than untransformed triangles
    std::vector<uint32_t> unbounded_;  ///< planes: always tested
    TriangleBvh triangles_;            ///< untransformed triangle objects
    std::vector<uint32_t> triObject_;  ///< triangle index in triangles_ → object index
    std::vector<Vec3> triNormal_;      ///< triangle index in triangles_ → its unit geometric normal
    /// The planes of triangles_' triangles when they are few (a room, a box of triangles: then
    /// rays test the triangles of the planes they cross instead of walking triangles_); empty
    /// when there are more.
    std::vector<Plane> trianglePlanes_;
    std::vector<uint32_t> planeFirst_;  ///< plane k's triangles: planeTri_[planeFirst_[k] .. planeFirst_[k+1])
    /// A triangle of a plane, with its barycentric coordinates as affine functions of a point of
    /// the plane: a quick filter before the exact test.
    struct PlaneTri {
        Vec3 au;
        double cu;
        Vec3 av;
        double cv;
        uint32_t tri;  ///< index in triangles_ (into triObject_)
    };
    std::vector<PlaneTri> planeTri_;  ///< by plane
    std::vector<Bounded> bounded_;     ///< the objects in objects_, in scene order
    std::vector<Plane> planes_;        ///< of the world-space triangles among them
    std::vector<int32_t> boundedOf_;   ///< object index → index in bounded_, or -1
};

}  // namespace rays
