#include "rays/render/pov_lighting.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays {

namespace {

// Highlights of one light (unit N, L, V; nl = N·L), in the light's colour, metallic-tinted.
// Phong: the manual's "mirror direction from the light to the viewer", (R·V)^phong_size; specular:
// (N·H)^(1/roughness). Both measured exactly so (docs/povray-lighting.md, "Highlights").
Vec3 highlights(const PovFinish& f, Vec3 C, Vec3 N, Vec3 L, Vec3 V, double nl, Vec3 lightColor) {
    double amount = 0;
    if (f.phong > 0) {
        const double rv = dot(2.0 * nl * N - L, V);
        if (rv > 0) amount += f.phong * std::pow(rv, f.phongSize);
    }
    if (f.specular > 0) {
        const Vec3 h = L + V;
        const double len = length(h);
        const double nh = len > 0 ? dot(N, h) / len : 0.0;
        if (nh > 0) amount += f.specular * std::pow(nh, 1.0 / f.roughness);
    }
    if (amount == 0) return {};
    return amount * lightColor * povMetallicTint(f.metallic, C, nl);
}

// cosine^brilliance, without pow for the default brilliance 1.
double brilliant(double cosine, double brilliance) { return brilliance == 1 ? cosine : std::pow(cosine, brilliance); }

}  // namespace

PovLightTerms povLightTerms(const PovSurface& s, Vec3 C, Vec3 N, Vec3 L, Vec3 V, Vec3 lightColor) {
    const PovFinish& f = s.finish;
    PovLightTerms out;
    const double nl = dot(N, L);
    const bool front = nl > 0;
    if (!front && !s.doubleIlluminate) {
        // Only the second diffuse value sees light from behind; no highlights (measured).
        if (f.diffuseBack != 0 && nl < 0)
            out.diffuse = f.diffuseBack * brilliant(-nl, f.brilliance) * C * lightColor;
        return out;
    }
    const double cosine = std::fabs(nl);
    if (f.diffuse != 0 && cosine > 0) out.diffuse = f.diffuse * brilliant(cosine, f.brilliance) * C * lightColor;
    out.highlight = highlights(f, C, N, L, V, nl, lightColor);
    return out;
}

Vec3 povAmbient(const PovFinish& f, Vec3 C, Vec3 ambientLight) { return (f.ambient * ambientLight + f.emission) * C; }

double povOpacity(Vec3 C, double filter, double transmit, double version) {
    if (version < 3.7) return 1.0 - (filter * maxComponent(C) + transmit);
    return 1.0 - filter - transmit;
}

double povMetallicCurve(double cosAngle) {
    const double x = std::acos(std::clamp(cosAngle, -1.0, 1.0)) / (std::numbers::pi / 2);
    const double d = x - 1.12;
    return std::clamp(0.014567225 / (d * d) - 0.011612903, 0.0, 1.0);
}

Vec3 povMetallicTint(double amount, Vec3 C, double cosAngle) {
    if (amount == 0) return Vec3(1.0);
    return Vec3(1.0) + amount * (1.0 - povMetallicCurve(cosAngle)) * (C - Vec3(1.0));
}

double fresnelReflectance(double cosIncidence, double eta) {
    const double ci = std::clamp(cosIncidence, 0.0, 1.0);
    const double sin2t = eta * eta * (1.0 - ci * ci);
    if (sin2t >= 1.0) return 1.0;
    const double ct = std::sqrt(1.0 - sin2t);
    const double rs = (eta * ci - ct) / (eta * ci + ct);
    const double rp = (ci - eta * ct) / (ci + eta * ct);
    return 0.5 * (rs * rs + rp * rp);
}

Vec3 povReflectivity(const PovSurface& s, Vec3 C, double cosView, double eta) {
    const PovFinish& f = s.finish;
    Vec3 r = f.reflectionMax;
    if (f.reflectionFresnel) {
        r = f.reflectionMin + fresnelReflectance(cosView, eta) * (f.reflectionMax - f.reflectionMin);
    } else if (!(f.reflectionMin == f.reflectionMax)) {
        const double k = std::pow(std::max(0.0, 1.0 - cosView), f.reflectionFalloff);
        r = f.reflectionMin + k * (f.reflectionMax - f.reflectionMin);
    }
    if (f.reflectionMetallic != 0) r *= povMetallicTint(f.reflectionMetallic, C, cosView);
    return r;
}

Vec3 povReflectionExponent(Vec3 reflected, double exponent) {
    if (exponent == 1) return reflected;
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = reflected[i] > 0 ? std::pow(reflected[i], 1.0 / exponent) : 0.0;
    return out;
}

Vec3 povFade(const PovInterior& in, double distance) {
    if (!povFades(in)) return Vec3(1.0);
    const double q = distance / in.fadeDistance;
    if (in.fadePower >= 1000) {
        Vec3 out;
        for (int i = 0; i < 3; ++i) {
            const double k = 1.0 - in.fadeColor[i];
            out[i] = k == 0 ? 1.0 : std::exp(-k * q);
        }
        return out;
    }
    const double a = std::isinf(q) ? 0.0 : 1.0 / (1.0 + std::pow(q, in.fadePower));
    return Vec3(a) + (1.0 - a) * in.fadeColor;
}

}  // namespace rays
