#include "rays/sdl/pure_builtins.h"

#include <array>
#include <cmath>

namespace rays::sdl {

namespace {

constexpr double kPi = 3.1415926535897932384626;

double degrees(double a) { return a * 180 / kPi; }
double radians(double a) { return a * kPi / 180; }

using V3 = std::array<double, 3>;

V3 vec3Of(const Num& v) {
    if (v.type == VType::Float) return {v.c[0], v.c[0], v.c[0]};
    return {v.c[0], v.dim > 1 ? v.c[1] : 0.0, v.dim > 2 ? v.c[2] : 0.0};
}

Num fromVec3(const V3& p) {
    Num r;
    r.type = VType::Vector;
    r.dim = 3;
    r.c = {p[0], p[1], p[2], 0, 0};
    return r;
}

// Rotation of p about the x, then y, then z axis by the angles in degrees (standard rotation
// matrices; measured with POV-Ray 3.7: vrotate(x, 90*y) = <0,0,-1>).
V3 rotateXYZ(V3 p, const V3& deg) {
    for (int axis = 0; axis < 3; ++axis) {
        const double a = deg[size_t(axis)] * kPi / 180, c = std::cos(a), s = std::sin(a);
        const int i = (axis + 1) % 3, j = (axis + 2) % 3;
        const double pi = p[size_t(i)], pj = p[size_t(j)];
        p[size_t(i)] = c * pi - s * pj;
        p[size_t(j)] = s * pi + c * pj;
    }
    return p;
}

// Rodrigues' rotation of p about the axis k by deg degrees, in the sense of rotateXYZ.
V3 rotateAxis(const V3& p, V3 k, double deg) {
    const double len = std::sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
    for (double& c : k) c /= len;
    const double a = deg * kPi / 180, c = std::cos(a), s = std::sin(a);
    const double d = k[0] * p[0] + k[1] * p[1] + k[2] * p[2];
    const V3 x{k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2], k[0] * p[1] - k[1] * p[0]};
    return {p[0] * c + x[0] * s + k[0] * d * (1 - c), p[1] * c + x[1] * s + k[1] * d * (1 - c),
            p[2] * c + x[2] * s + k[2] * d * (1 - c)};
}

}  // namespace

double (*mathFunction1(Kw k))(double) {
    switch (k) {
        case Kw::abs: return static_cast<double (*)(double)>(std::fabs);
        case Kw::acos: return static_cast<double (*)(double)>(std::acos);
        case Kw::acosh: return static_cast<double (*)(double)>(std::acosh);
        case Kw::asin: return static_cast<double (*)(double)>(std::asin);
        case Kw::asinh: return static_cast<double (*)(double)>(std::asinh);
        case Kw::atan: return static_cast<double (*)(double)>(std::atan);
        case Kw::atanh: return static_cast<double (*)(double)>(std::atanh);
        case Kw::ceil: return static_cast<double (*)(double)>(std::ceil);
        case Kw::cos: return static_cast<double (*)(double)>(std::cos);
        case Kw::cosh: return static_cast<double (*)(double)>(std::cosh);
        case Kw::exp: return static_cast<double (*)(double)>(std::exp);
        case Kw::floor: return static_cast<double (*)(double)>(std::floor);
        case Kw::int_: return static_cast<double (*)(double)>(std::trunc);
        case Kw::ln: return static_cast<double (*)(double)>(std::log);
        case Kw::log: return static_cast<double (*)(double)>(std::log10);
        case Kw::sin: return static_cast<double (*)(double)>(std::sin);
        case Kw::sinh: return static_cast<double (*)(double)>(std::sinh);
        case Kw::sqrt: return static_cast<double (*)(double)>(std::sqrt);
        case Kw::tan: return static_cast<double (*)(double)>(std::tan);
        case Kw::tanh: return static_cast<double (*)(double)>(std::tanh);
        case Kw::degrees: return degrees;
        case Kw::radians: return radians;
        default: return nullptr;
    }
}

bool mathFunction2(Kw k, double a, double b, double& out) {
    switch (k) {
        case Kw::atan2: out = std::atan2(a, b); return true;
        case Kw::pow: out = std::pow(a, b); return true;
        case Kw::mod: out = std::fmod(a, b); return true;
        case Kw::div: out = std::trunc(a / b); return true;
        default: return false;
    }
}

bool vectorFunction(Kw k, const Num* a, int n, Num& out) {
    for (int i = 0; i < n; ++i)
        if (!a[i].isNumeric()) return false;
    switch (k) {
        case Kw::vdot: {
            if (n != 2) return false;
            const V3 p = vec3Of(a[0]), q = vec3Of(a[1]);
            out = Num::number(p[0] * q[0] + p[1] * q[1] + p[2] * q[2]);
            return true;
        }
        case Kw::vlength: {
            if (n != 1) return false;
            const V3 p = vec3Of(a[0]);
            out = Num::number(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
            return true;
        }
        case Kw::vcross: {
            if (n != 2) return false;
            const V3 p = vec3Of(a[0]), q = vec3Of(a[1]);
            out = fromVec3({p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]});
            return true;
        }
        case Kw::vnormalize: {
            if (n != 1) return false;
            const V3 p = vec3Of(a[0]);
            const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            if (l == 0) return false;
            out = fromVec3({p[0] / l, p[1] / l, p[2] / l});
            return true;
        }
        case Kw::vrotate:
            if (n != 2) return false;
            out = fromVec3(rotateXYZ(vec3Of(a[0]), vec3Of(a[1])));
            return true;
        case Kw::vaxis_rotate: {
            if (n != 3 || a[2].type != VType::Float) return false;
            const V3 axis = vec3Of(a[1]);
            if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0) return false;
            out = fromVec3(rotateAxis(vec3Of(a[0]), axis, a[2].c[0]));
            return true;
        }
        default:
            return false;
    }
}

}  // namespace rays::sdl
