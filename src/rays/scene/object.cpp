#include "rays/scene/object.h"
#include "rays/scene/object_transform.h"

#include <cmath>
#include <limits>

#include "rays/geometry/sphere_hit.h"
#include "rays/scene/csg.h"
#include "rays/scene/mesh.h"
#include "rays/scene/text_shape.h"
#include "rays/scene/shapes/blob.h"
#include "rays/scene/shapes/isosurface.h"
#include "rays/scene/shapes/julia_fractal.h"
#include "rays/scene/shapes/disc.h"
#include "rays/scene/shapes/height_field.h"
#include "rays/scene/shapes/lathe.h"
#include "rays/scene/shapes/ovus.h"
#include "rays/scene/shapes/polygon.h"
#include "rays/scene/shapes/poly.h"
#include "rays/scene/shapes/prism.h"
#include "rays/scene/shapes/sor.h"
#include "rays/scene/shapes/sphere_sweep.h"
#include "rays/scene/shapes/superellipsoid.h"
#include "rays/scene/shapes/torus.h"

namespace rays {

std::string_view shapeName(ShapeType t) {
    switch (t) {
        case ShapeType::Sphere: return "Sphere";
        case ShapeType::Plane: return "Plane";
        case ShapeType::Triangle: return "Triangle";
        case ShapeType::Box: return "Box";
        case ShapeType::Cone: return "Cone";
        case ShapeType::Mesh: return "Mesh";
        case ShapeType::Csg: return "CSG";
        case ShapeType::Text: return "Text";
        case ShapeType::Torus: return "Torus";
        case ShapeType::Disc: return "Disc";
        case ShapeType::Polygon: return "Polygon";
        case ShapeType::Poly: return "Poly";
        case ShapeType::Superellipsoid: return "Superellipsoid";
        case ShapeType::Prism: return "Prism";
        case ShapeType::Blob: return "Blob";
        case ShapeType::Isosurface: return "Isosurface";
        case ShapeType::Lathe: return "Lathe";
        case ShapeType::HeightField: return "HeightField";
        case ShapeType::JuliaFractal: return "JuliaFractal";
        case ShapeType::Ovus: return "Ovus";
        case ShapeType::Sor: return "Sor";
        case ShapeType::SphereSweep: return "SphereSweep";
    }
    return "Object";
}

namespace {

// Sphere (p1, r1): the object-space sphere, or the world-space one for similarity transforms.
bool hitSphere(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    if (!sphereHitT(o.p1, o.r1, r, tMin, tMax, h.t)) return false;
    h.normal = sphereNormal(o.p1, o.r1, r, h.t);
    return true;
}

// Uniform scale factor s when the linear part of m is s times an orthogonal matrix, else 0.
double similarityScale(const Transform& m) {
    Vec3 col[3];
    for (int j = 0; j < 3; ++j) col[j] = Vec3{m.m[0][j], m.m[1][j], m.m[2][j]};
    const double s2 = dot(col[0], col[0]);
    const double tol = 1e-12 * s2;
    if (std::fabs(dot(col[1], col[1]) - s2) > tol || std::fabs(dot(col[2], col[2]) - s2) > tol) return 0;
    if (std::fabs(dot(col[0], col[1])) > tol || std::fabs(dot(col[0], col[2])) > tol ||
        std::fabs(dot(col[1], col[2])) > tol)
        return 0;
    return std::sqrt(s2);
}

bool hitPlane(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const double denom = dot(o.p0, r.dir);
    if (denom == 0) return false;
    const double t = (o.r0 - dot(o.p0, r.origin)) / denom;
    if (!(t > tMin && t < tMax)) return false;
    h.t = t;
    h.normal = o.p0;
    return true;
}

// Möller–Trumbore (1997).
}  // namespace

bool triangleHitT(const Object& o, const Ray& r, double tMin, double tMax, double& t, double& u, double& v) {
    const Vec3 e1 = o.p1 - o.p0, e2 = o.p2 - o.p0;
    const Vec3 pv = cross(r.dir, e2);
    const double det = dot(e1, pv);
    if (det == 0) return false;
    const double inv = 1.0 / det;
    const Vec3 tv = r.origin - o.p0;
    u = dot(tv, pv) * inv;
    if (u < 0 || u > 1) return false;
    const Vec3 qv = cross(tv, e1);
    v = dot(r.dir, qv) * inv;
    if (v < 0 || u + v > 1) return false;
    t = dot(e2, qv) * inv;
    return t > tMin && t < tMax;
}

void triangleNormals(const Object& o, double u, double v, Vec3& geomNormal, Vec3& normal) {
    geomNormal = normalize(cross(o.p1 - o.p0, o.p2 - o.p0));
    if (o.smooth) {
        const Vec3 n = normalize((1 - u - v) * o.n0 + u * o.n1 + v * o.n2);
        if (!(o.n0 == o.n1 && o.n1 == o.n2)) geomNormal = triangleSides(geomNormal, n);
        normal = dot(n, geomNormal) < 0 ? -n : n;
    } else {
        normal = geomNormal;
    }
}

namespace {

bool hitTriangle(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    double t, u, v;
    if (!triangleHitT(o, r, tMin, tMax, t, u, v)) return false;
    h.t = t;
    triangleNormals(o, u, v, h.geomNormal, h.normal);
    return true;
}

// Slab test (Kay & Kajiya 1986), remembering which face was crossed. The faces are picked by
// the sign of the direction rather than by comparing their distances, and the miss is decided
// after the three slabs (tNear only grows, tFar only shrinks): the same answer with selects
// instead of branches that random directions would mispredict.
bool hitBox(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    double tNear = -kInfinity, tFar = kInfinity;
    int nearAxis = 0, farAxis = 0;
    double nearSign = 0, farSign = 0;
    for (int a = 0; a < 3; ++a) {
        const double d = r.dir[a];
        if (d == 0) {
            if (r.origin[a] < o.p0[a] || r.origin[a] > o.p1[a]) return false;
            continue;
        }
        const bool up = d > 0;
        const double inv = 1 / d;  // one division per axis, not two
        const double t0 = ((up ? o.p0[a] : o.p1[a]) - r.origin[a]) * inv;  // entering face
        const double t1 = ((up ? o.p1[a] : o.p0[a]) - r.origin[a]) * inv;  // leaving face
        const double s0 = up ? -1 : 1;  // outward normal sign of the entering face
        if (t0 > tNear) { tNear = t0; nearAxis = a; nearSign = s0; }
        if (t1 < tFar) { tFar = t1; farAxis = a; farSign = -s0; }
    }
    if (tNear > tFar) return false;
    Vec3 n;
    if (tNear > tMin && tNear < tMax) {
        h.t = tNear;
        n[nearAxis] = nearSign;
    } else if (tFar > tMin && tFar < tMax) {
        h.t = tFar;
        n[farAxis] = farSign;
    } else {
        return false;
    }
    h.normal = n;
    return true;
}

// Cone in its canonical frame: axis z ∈ [0, h], radius r0 + k·z with k = (r1 − r0)/h; closed by caps.
bool hitCone(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const double height = o.p2.x, k = o.p2.y;
    double best = tMax;
    Vec3 bestN;
    bool found = false;
    auto consider = [&](double t, Vec3 n) {
        if (t > tMin && t < best) {
            best = t;
            bestN = n;
            found = true;
        }
    };
    // Side: x² + y² = (r0 + k z)².
    const Vec3 O = r.origin, D = r.dir;
    const double rz = o.r0 + k * O.z;
    const double A = D.x * D.x + D.y * D.y - k * k * D.z * D.z;
    const double B = 2 * (O.x * D.x + O.y * D.y - rz * k * D.z);
    const double C = O.x * O.x + O.y * O.y - rz * rz;
    auto side = [&](double t) {
        const Vec3 p = r.at(t);
        if (p.z < 0 || p.z > height) return;
        const double rad = o.r0 + k * p.z;
        if (rad < 0) return;
        consider(t, Vec3{p.x, p.y, -rad * k});
    };
    if (std::fabs(A) > 1e-14) {
        const double disc = B * B - 4 * A * C;
        if (disc >= 0) {
            const double sq = std::sqrt(disc);
            side((-B - sq) / (2 * A));
            side((-B + sq) / (2 * A));
        }
    } else if (B != 0) {
        side(-C / B);
    }
    // Caps.
    if (D.z != 0 && !o.open) {
        const double capR[2] = {o.r0, o.r1};
        const double capZ[2] = {0, height};
        for (int i = 0; i < 2; ++i) {
            const double t = (capZ[i] - O.z) / D.z;
            const Vec3 p = r.at(t);
            if (p.x * p.x + p.y * p.y <= capR[i] * capR[i]) consider(t, Vec3{0, 0, i == 0 ? -1.0 : 1.0});
        }
    }
    if (!found) return false;
    h.t = best;
    h.normal = bestN;  // canonical frame; intersect() maps it to world space
    return true;
}

bool hitLocal(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    bool found = false;
    h.hasUV = false;  // h may be reused across objects
    h.part = nullptr;
    h.blend.face = CornerBlend::kNone;
    h.cutawayBlend = false;
    switch (o.type) {
        case ShapeType::Sphere: found = hitSphere(o, r, tMin, tMax, h); break;
        case ShapeType::Plane: found = hitPlane(o, r, tMin, tMax, h); break;
        case ShapeType::Triangle: return hitTriangle(o, r, tMin, tMax, h);
        case ShapeType::Mesh: {
            MeshHit mh;
            if (!intersectMesh(*o.mesh, r, tMin, tMax, mh)) return false;
            if (o.data && mh.triangle < o.data->faceParts.size()) {  // the face's own texture
                const int32_t part = o.data->faceParts[mh.triangle];
                h.part = part >= 0 ? &o.data->parts[size_t(part)] : nullptr;
                if (3 * size_t(mh.triangle) < o.data->cornerParts.size() && o.data->cornerParts[3 * size_t(mh.triangle)] >= 0)
                    h.blend = CornerBlend{mh.triangle, float(mh.b1), float(mh.b2)};  // or one per corner
            }
            h.t = mh.t;
            h.normal = mh.normal;
            h.geomNormal = mh.geomNormal;
            h.hasUV = o.mesh->hasUVs();
            h.u = mh.u;
            h.v = mh.v;
            h.dpdu = mh.dpdu;
            return true;
        }
        case ShapeType::Box: found = hitBox(o, r, tMin, tMax, h); break;
        case ShapeType::Cone: found = hitCone(o, r, tMin, tMax, h); break;
        case ShapeType::Text: found = intersectText(*o.text, r, tMin, tMax, h.t, h.normal); break;
        case ShapeType::Torus: found = hitTorus(o, r, tMin, tMax, h); break;
        case ShapeType::Disc: found = hitDisc(o, r, tMin, tMax, h); break;
        case ShapeType::Polygon: found = hitPolygon(o, r, tMin, tMax, h); break;
        case ShapeType::Poly: found = hitPolySurface(o, r, tMin, tMax, h); break;
        case ShapeType::Superellipsoid: found = hitSuperellipsoid(o, r, tMin, tMax, h); break;
        case ShapeType::Prism: found = hitPrism(o, r, tMin, tMax, h); break;
        case ShapeType::Blob: found = hitBlob(o, r, tMin, tMax, h); break;
        case ShapeType::Isosurface: found = hitIsosurface(o, r, tMin, tMax, h); break;
        case ShapeType::Lathe: found = hitLathe(o, r, tMin, tMax, h); break;
        case ShapeType::Sor: found = hitSor(o, r, tMin, tMax, h); break;
        case ShapeType::SphereSweep: found = hitSphereSweep(o, r, tMin, tMax, h); break;
        case ShapeType::JuliaFractal: found = hitJuliaFractal(o, r, tMin, tMax, h); break;
        case ShapeType::Ovus: found = hitOvus(o, r, tMin, tMax, h); break;
        case ShapeType::HeightField: return hitHeightField(o, r, tMin, tMax, h);  // sets both normals
        case ShapeType::Csg: return intersectCsg(*o.csg, r, tMin, tMax, &h);  // world space (not localSpace)
    }
    if (found) h.geomNormal = h.normal;
    return found;
}

Bounds localBounds(const Object& o) {
    Bounds b;
    switch (o.type) {
        case ShapeType::Sphere:
            b.extend(o.p1 - Vec3(o.r1));
            b.extend(o.p1 + Vec3(o.r1));
            break;
        case ShapeType::Plane: break;
        case ShapeType::Triangle:
            b.extend(o.p0);
            b.extend(o.p1);
            b.extend(o.p2);
            break;
        case ShapeType::Box:
            b.extend(o.p0);
            b.extend(o.p1);
            break;
        case ShapeType::Mesh:
            b = o.mesh->bounds;
            break;
        case ShapeType::Csg:
            b = o.csg->bounds;
            break;
        case ShapeType::Text: b = o.text->bounds; break;
        case ShapeType::Torus: b = torusBounds(o); break;
        case ShapeType::Disc: b = discBounds(o); break;
        case ShapeType::Polygon: case ShapeType::Poly: case ShapeType::Prism: case ShapeType::Blob:
        case ShapeType::Lathe: case ShapeType::Sor: case ShapeType::SphereSweep: case ShapeType::Isosurface: case ShapeType::HeightField:
        case ShapeType::JuliaFractal: case ShapeType::Ovus:
            b = o.data->bounds;
            break;
        case ShapeType::Superellipsoid: b = Bounds{Vec3(-1), Vec3(1)}; break;
        case ShapeType::Cone: {
            const double r = std::max(o.r0, o.r1);
            b.extend(o.p0 - Vec3(r));
            b.extend(o.p0 + Vec3(r));
            b.extend(o.p1 - Vec3(r));
            b.extend(o.p1 + Vec3(r));
            break;
        }
    }
    return b;
}

}  // namespace

namespace {
// A cone's canonical frame in object space: x, y, z to u, v, w (w along the axis) at the base.
Transform coneFrame(const Object& o) {
    const Vec3 w = normalize(o.p1 - o.p0);
    const Vec3 helper = std::fabs(w.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = normalize(cross(helper, w));
    const Vec3 v = cross(w, u);
    return Transform::fromColumns(u, v, w, o.p0);
}
}  // namespace

void prepareObject(Object& o, const Transform& objectToWorld) {
    o.transformed = !objectToWorld.isIdentity();
    o.toObject = o.transformed ? objectToWorld.inverse() : Transform{};
    o.localSpace = o.transformed || o.type == ShapeType::Cone;
    if (o.type == ShapeType::Sphere) {
        o.p1 = o.p0;
        o.r1 = o.r0;
        const double s = o.transformed ? similarityScale(objectToWorld) : 0.0;
        if (s > 0) {  // a sphere stays a sphere: intersect it in world space
            o.p1 = objectToWorld.point(o.p0);
            o.r1 = s * o.r0;
            o.localSpace = false;
        }
        return;
    }
    if (o.type != ShapeType::Cone) return;
    const double height = length(o.p1 - o.p0);
    // Canonical → object maps x, y, z to u, v, w at the base; its (rigid) inverse follows M⁻¹.
    o.toObject = coneFrame(o).inverse() * o.toObject;
    o.p2 = Vec3{height, (o.r1 - o.r0) / height, 0};
}

Transform objectToWorld(const Object& o) {
    if (!o.transformed) return Transform{};
    if (o.type != ShapeType::Cone) return o.toObject.inverse();
    return (coneFrame(o) * o.toObject).inverse();  // toObject = frame⁻¹ · M⁻¹
}

namespace {

// The box of o in the space its rays are intersected in: cones' toObject includes the canonical
// frame (axis along z), so their box is taken in that frame.
Bounds intersectionSpaceBounds(const Object& o) {
    if (o.type != ShapeType::Cone) return localBounds(o);
    const double r = std::max(o.r0, o.r1);
    return Bounds{{-r, -r, 0}, {r, r, o.p2.x}};
}

// An upper bound of the largest stretch |M·v|/|v| of the linear part M of t: the square root of
// the largest row sum of |MᵀM| (Gershgorin's circle theorem bounds MᵀM's largest eigenvalue by
// it). Exact for rotations, uniform scales and scales along the axes.
double largestStretch(const Transform& t) {
    double worst = 0;
    for (int i = 0; i < 3; ++i) {
        double row = 0;
        for (int j = 0; j < 3; ++j) {
            double g = 0;
            for (int k = 0; k < 3; ++k) g += t.m[k][i] * t.m[k][j];
            row += std::fabs(g);
        }
        worst = std::max(worst, row);
    }
    return std::sqrt(worst);
}

}  // namespace

bool worldBoundingSphere(const Object& o, Vec3& centre, double& radius) {
    if (!o.localSpace && o.type == ShapeType::Sphere) {
        centre = o.p1;
        radius = o.r1;
        return true;
    }
    const Bounds lb = o.transformed ? intersectionSpaceBounds(o) : localBounds(o);  // as worldBounds
    if (lb.empty()) return false;
    const Vec3 c = 0.5 * (lb.lo + lb.hi);
    double shapeRadius = std::numeric_limits<double>::infinity();  // a sphere tighter than the box's
    if (o.type == ShapeType::Torus) shapeRadius = std::fabs(o.r0) + o.r1;  // centred at the origin
    if (o.type == ShapeType::Sphere) shapeRadius = o.r1;
    const Transform toWorld = o.transformed ? o.toObject.inverse() : Transform::identity();
    centre = toWorld.point(c);
    double corner2 = 0;  // the transformed box lies within its corners' farthest distance
    for (int i = 0; i < 8; ++i) {
        const Vec3 k{(i & 1) ? lb.hi.x : lb.lo.x, (i & 2) ? lb.hi.y : lb.lo.y, (i & 4) ? lb.hi.z : lb.lo.z};
        const Vec3 v = toWorld.point(k) - centre;
        corner2 = std::max(corner2, dot(v, v));
    }
    radius = std::min(std::sqrt(corner2), largestStretch(toWorld) * shapeRadius);
    radius *= 1 + 1e-9;  // the rounding of the numbers above
    return std::isfinite(radius) && std::isfinite(centre.x) && std::isfinite(centre.y) && std::isfinite(centre.z);
}

Bounds worldBounds(const Object& o) {
    if (!o.localSpace && o.type == ShapeType::Sphere) return Bounds{o.p1 - Vec3(o.r1), o.p1 + Vec3(o.r1)};
    if (!o.transformed) return localBounds(o);
    const Transform toWorld = o.toObject.inverse();
    if (o.type == ShapeType::Sphere) {
        // Exact box of an ellipsoid: half-extent along world axis i is r·|row i of M|.
        const Vec3 c = toWorld.point(o.p1);
        Vec3 half;
        for (int i = 0; i < 3; ++i)
            half[i] = o.r1 * std::sqrt(toWorld.m[i][0] * toWorld.m[i][0] + toWorld.m[i][1] * toWorld.m[i][1] +
                                       toWorld.m[i][2] * toWorld.m[i][2]);
        return Bounds{c - half, c + half};
    }
    const Bounds lb = intersectionSpaceBounds(o);
    if (lb.empty()) return lb;
    Bounds wb;
    for (int i = 0; i < 8; ++i) {
        const Vec3 c{(i & 1) ? lb.hi.x : lb.lo.x, (i & 2) ? lb.hi.y : lb.lo.y, (i & 4) ? lb.hi.z : lb.lo.z};
        wb.extend(toWorld.point(c));
    }
    return wb;
}

bool intersect(const Object& o, const Ray& worldRay, double tMin, double tMax, ShapeHit& hit) {
    if (!usesLocalSpace(o)) return hitLocal(o, worldRay, tMin, tMax, hit);
    const Ray local{o.toObject.point(worldRay.origin), o.toObject.vector(worldRay.dir)};
    if (!hitLocal(o, local, tMin, tMax, hit)) return false;
    hit.normal = normalize(o.toObject.transposedVector(hit.normal));
    hit.geomNormal = (o.smooth || o.type == ShapeType::Mesh) ? normalize(o.toObject.transposedVector(hit.geomNormal))
                                                             : hit.normal;
    return true;
}

bool occludes(const Object& o, const Ray& worldRay, double tMin, double tMax) {
    if (o.type == ShapeType::Csg) return intersectCsg(*o.csg, worldRay, tMin, tMax, nullptr);
    if (o.type == ShapeType::Mesh) {
        if (!usesLocalSpace(o)) return occludesMesh(*o.mesh, worldRay, tMin, tMax);
        return occludesMesh(*o.mesh, Ray{o.toObject.point(worldRay.origin), o.toObject.vector(worldRay.dir)}, tMin, tMax);
    }
    if (!usesLocalSpace(o)) {  // the common shapes without the normals a hit would compute
        double t, u, v;
        if (o.type == ShapeType::Sphere) return sphereHitT(o.p1, o.r1, worldRay, tMin, tMax, t);
        if (o.type == ShapeType::Triangle) return triangleHitT(o, worldRay, tMin, tMax, t, u, v);
    }
    ShapeHit h;
    if (!usesLocalSpace(o)) return hitLocal(o, worldRay, tMin, tMax, h);
    const Ray local{o.toObject.point(worldRay.origin), o.toObject.vector(worldRay.dir)};
    return hitLocal(o, local, tMin, tMax, h);
}

}  // namespace rays
