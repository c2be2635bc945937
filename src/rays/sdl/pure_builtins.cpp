#include "rays/sdl/pure_builtins.h"

#include <cmath>
#include <numbers>

#include "rays/math/transform.h"

namespace rays::sdl {

namespace {

double degrees(double a) { return a * 180 / std::numbers::pi; }
double radians(double a) { return a * std::numbers::pi / 180; }

Vec3 vec3Of(const Num& v) {
    if (v.type == VType::Float) return Vec3(v.c[0]);
    return {v.c[0], v.dim > 1 ? v.c[1] : 0.0, v.dim > 2 ? v.c[2] : 0.0};
}

Num fromVec3(Vec3 p) {
    Num r;
    r.type = VType::Vector;
    r.dim = 3;
    r.c = {p.x, p.y, p.z, 0, 0};
    return r;
}

// Rodrigues' rotation of p about the axis k by deg degrees, in the sense of Transform::rotateAxis.
Vec3 rotateAbout(Vec3 p, Vec3 k, double deg) {
    k = normalize(k);
    const double a = deg * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
    return p * c + cross(k, p) * s + k * (dot(k, p) * (1 - c));
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
        case Kw::vdot:
            if (n != 2) return false;
            out = Num::number(dot(vec3Of(a[0]), vec3Of(a[1])));
            return true;
        case Kw::vlength:
            if (n != 1) return false;
            out = Num::number(length(vec3Of(a[0])));
            return true;
        case Kw::vcross:
            if (n != 2) return false;
            out = fromVec3(cross(vec3Of(a[0]), vec3Of(a[1])));
            return true;
        case Kw::vnormalize: {
            if (n != 1) return false;
            const Vec3 p = vec3Of(a[0]);
            if (length(p) == 0) return false;
            out = fromVec3(p / length(p));
            return true;
        }
        case Kw::vrotate:  // about x, then y, then z (measured with POV-Ray 3.7: vrotate(x, 90*y) = <0,0,-1>)
            if (n != 2) return false;
            out = fromVec3(Transform::rotatePovray(vec3Of(a[1])).vector(vec3Of(a[0])));
            return true;
        case Kw::vaxis_rotate: {
            if (n != 3 || a[2].type != VType::Float) return false;
            const Vec3 axis = vec3Of(a[1]);
            if (axis == Vec3{}) return false;
            out = fromVec3(rotateAbout(vec3Of(a[0]), axis, a[2].c[0]));
            return true;
        }
        default:
            return false;
    }
}

}  // namespace rays::sdl
