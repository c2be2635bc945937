#include "rays/math/transform.h"

#include <cmath>
#include <numbers>

namespace rays {

Transform Transform::translate(Vec3 t) {
    Transform r;
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
}

Transform Transform::scale(Vec3 s) {
    Transform r;
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
}

Transform Transform::rotateAxis(int axis, double deg) {
    const double a = deg * std::numbers::pi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // the plane rotated: i -> j
    Transform r;
    r.m[i][i] = c;
    r.m[i][j] = -s;
    r.m[j][i] = s;
    r.m[j][j] = c;
    return r;
}

Transform Transform::rotateCourse(Vec3 deg) {
    return rotateAxis(0, deg.x) * rotateAxis(1, deg.y) * rotateAxis(2, deg.z);
}

Transform Transform::rotatePovray(Vec3 deg) {
    return rotateAxis(2, deg.z) * rotateAxis(1, deg.y) * rotateAxis(0, deg.x);
}

Transform Transform::fromColumns(Vec3 cx, Vec3 cy, Vec3 cz, Vec3 origin) {
    Transform r;
    for (int row = 0; row < 3; ++row) {
        r.m[row][0] = cx[row];
        r.m[row][1] = cy[row];
        r.m[row][2] = cz[row];
        r.m[row][3] = origin[row];
    }
    return r;
}

double Transform::determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool Transform::isUsable() const {
    auto finite = [](const Transform& t) {
        for (const auto& row : t.m)
            for (double v : row)
                if (!std::isfinite(v)) return false;
        return true;
    };
    const double det = determinant();
    if (!finite(*this) || !std::isfinite(det) || det == 0) return false;
    const Transform inv = inverse();
    const double invDet = inv.determinant();
    return finite(inv) && std::isfinite(invDet) && invDet != 0;
}

Transform Transform::inverse() const {
    const double inv = 1.0 / determinant();
    Transform r;
    r.m[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * inv;
    r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * inv;
    r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * inv;
    r.m[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * inv;
    r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * inv;
    r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * inv;
    r.m[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * inv;
    r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * inv;
    r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * inv;
    const Vec3 t{m[0][3], m[1][3], m[2][3]};
    const Vec3 rt = r.vector(t);
    r.m[0][3] = -rt.x;
    r.m[1][3] = -rt.y;
    r.m[2][3] = -rt.z;
    return r;
}

bool Transform::isIdentity() const {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j)
            if (m[i][j] != (i == j ? 1.0 : 0.0)) return false;
    return true;
}

Transform operator*(const Transform& a, const Transform& b) {
    Transform r;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) {
            double s = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
            if (j == 3) s += a.m[i][3];
            r.m[i][j] = s;
        }
    }
    return r;
}

}  // namespace rays
