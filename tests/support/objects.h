// Scene objects built in code for geometry and acceleration tests: the shape parameters as a scene
// file would give them, prepared (transform, intersection data) like the parser does.
#pragma once
#include "rays/math/transform.h"
#include "rays/scene/object.h"

namespace rays::test {

inline Object makeObject(ShapeType type, Vec3 p0, Vec3 p1, Vec3 p2, double r0, double r1,
                         const Transform& m = Transform{}) {
    Object o;
    o.type = type;
    o.p0 = p0;
    o.p1 = p1;
    o.p2 = p2;
    o.r0 = r0;
    o.r1 = r1;
    prepareObject(o, m);
    return o;
}

inline Object sphere(Vec3 c, double r, const Transform& m = Transform{}) {
    return makeObject(ShapeType::Sphere, c, {}, {}, r, 0, m);
}

}  // namespace rays::test
