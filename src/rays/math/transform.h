// Affine 3-D transforms stored as a 3x4 row-major matrix (the last row is implicitly 0 0 0 1).
#pragma once
#include "rays/math/vec3.h"

namespace rays {

struct Transform {
    double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

    static Transform identity() { return {}; }
    static Transform translate(Vec3 t);
    static Transform scale(Vec3 s);
    /// Rotation about x, y or z (axis 0, 1, 2) by deg degrees, right-handed.
    static Transform rotateAxis(int axis, double deg);
    /// Course order: R = Rx(a)·Ry(b)·Rz(c) acting on column vectors (z applied first).
    static Transform rotateCourse(Vec3 deg);
    /// POV-Ray order: R = Rz·Ry·Rx (x applied first).
    static Transform rotatePovray(Vec3 deg);
    /// Maps canonical x, y, z axes and origin to the given columns.
    static Transform fromColumns(Vec3 cx, Vec3 cy, Vec3 cz, Vec3 origin);

    Vec3 point(Vec3 p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
    }
    Vec3 vector(Vec3 v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    /// Applies the transpose of the linear part: with *this = M⁻¹ this maps object normals to world.
    Vec3 transposedVector(Vec3 v) const {
        return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z,
                m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
                m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
    }
    double determinant() const;
    /// Inverse; the caller guarantees determinant() != 0.
    Transform inverse() const;
    bool isIdentity() const;
    /// True when every entry, the determinant and the inverse are finite and the determinant is not
    /// 0: a transform an object can be drawn with (false after `scale 1e300 scale 1e300` overflows,
    /// or `scale 1e-200 scale 1e-200` underflows to 0).
    bool isUsable() const;
};

/// Composition: (a * b).point(p) == a.point(b.point(p)).
Transform operator*(const Transform& a, const Transform& b);

}  // namespace rays
