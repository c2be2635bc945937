#include "rays/render/pov_lighting.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rays/render/absorption.h"

namespace rays {

namespace {

// x^n for x in (0, 1] and n > 0, without pow where it is 0 anyway: x^n ≤ e^(−n(1 − x)) (as
// ln x ≤ x − 1), and beyond n(1 − x) = 746 that is below half the smallest double. Highlights of
// tiny roughness (exponents of 10⁵) are 0 but in a sliver about the mirror direction.
double highlightPower(double x, double n) { return n * (1 - x) > 746 ? 0.0 : std::pow(x, n); }

// Highlights of one light (unit N, L, V; nl = N·L), in the light's colour, metallic-tinted.
// Phong: the manual's "mirror direction from the light to the viewer", (R·V)^phong_size; specular:
// (N·H)^(1/roughness). Both measured exactly so (docs/povray-lighting.md, "Highlights").
Vec3 highlights(const PovFinish& f, Vec3 C, Vec3 N, Vec3 L, Vec3 V, double nl, Vec3 lightColor) {
    double amount = 0;
    if (f.phong > 0) {
        const double rv = dot(2.0 * nl * N - L, V);
        if (rv > 0) amount += f.phong * highlightPower(rv, f.phongSize);
    }
    if (f.specular > 0) {
        const Vec3 h = L + V;
        const double len = length(h);
        const double nh = len > 0 ? dot(N, h) / len : 0.0;
        if (nh > 0) amount += f.specular * highlightPower(nh, 1.0 / f.roughness);
    }
    if (amount == 0) return {};
    return amount * lightColor * povMetallicTint(f.metallic, C, nl);
}

// 3s² − 2s³ for s in [0, 1]: the spotlight's curve between its cones.
double smooth(double s) { return s * s * (3 - 2 * s); }

// Integral of a ground fog's density from its offset up to height h (negative below the offset,
// where the density is 1): alt·atan((h − offset)/alt) above it.
double groundFogIntegral(const PovFog& f, double h) {
    const double u = h - f.offset;
    if (u <= 0) return u;
    if (f.alt <= 0) return 0;  // no fog above the offset
    return f.alt * std::atan(u / f.alt);
}

// Optical length of a ray segment in ground fog: the density integrated along the segment.
double groundFogDepth(const PovFog& f, const Ray& ray, double t) {
    const double h0 = dot(ray.origin, f.up), du = dot(ray.dir, f.up);
    if (std::fabs(du) < 1e-12 || (std::isfinite(t) && std::fabs(du * t) < 1e-9)) {
        const double u = h0 - f.offset;
        const double density = u <= 0 ? 1.0 : f.alt <= 0 ? 0.0 : 1.0 / (1.0 + (u / f.alt) * (u / f.alt));
        return density == 0 ? 0.0 : t * density;
    }
    const double h1 = std::isfinite(t) ? h0 + du * t : (du > 0 ? kInfinity : -kInfinity);
    double top = -kInfinity;  // a ray going down for ever stays in the fog below the offset
    if (std::isfinite(h1)) top = groundFogIntegral(f, h1);
    else if (h1 > 0) top = f.alt > 0 ? f.alt * std::numbers::pi / 2 : 0.0;
    return (top - groundFogIntegral(f, h0)) / du;
}

// What a fog's turbulence leaves of the segment's optical depth (POV-Ray 3.7 reference, "Fog": the
// turbulence is read at one point, turb_depth of the way from the ray's start to the hit, and only
// the distance-based attenuation changes, not the fog's density). The rule as measured with
// POV-Ray 3.7 on constant and ground fogs, pixel by pixel: the depth is multiplied by
// 1 − c·exp(−t/distance), c = min(1, turb_depth·T), T the turbulence of marble (POV-Ray's scalar
// turbulence, pattern/noise.h) at amount ⊙ P with the fog's octaves, omega and lambda; the same c
// for both fog types, the exponential always the constant fog's. Measured over an 80×60 view of a
// wall: POV-Ray's c from 0.33 to 0.71 between its 10th and 90th percentiles at turb_depth 0.5,
// which is that turbulence's spread (mean 1.0, 0.64 to 1.38). Rays' noise is not POV-Ray's, so
// the pattern is alike, not the same.
double fogTurbulenceFactor(const PovFog& f, const Ray& ray, double t) {
    if (!f.turbulence.on() || !std::isfinite(t)) return 1.0;  // nothing hit: exp(−t/distance) is 0
    const Vec3 P = ray.origin + (f.turbDepth * t) * ray.dir;
    const Vec3 a = f.turbulence.amount;
    const pattern::Turbulence& tu = f.turbulence;
    const double T = pattern::turbulenceScalar({P.x * a.x, P.y * a.y, P.z * a.z}, tu.octaves, tu.omega, tu.lambda);
    const double c = std::clamp(f.turbDepth * T, 0.0, 1.0);
    return 1.0 - c * std::exp(-t / f.distance);
}

// The thickness' variation Y under irid's turbulence (measured: mean 1, from −0.8 to 2.8, 10th to
// 90th percentile 0.18 to 1.72 over a plane): Rays' turbulence sum (POV-Ray's octaves, omega and
// lambda are fixed and not documented; the defaults here) about its mean, widened 5 times to
// POV-Ray's spread (the noise is not POV-Ray's: alike, not the same; 5 times for the noise as it
// spread before it was widened to bozo's measured spread, which is 0.96/0.78 times wider).
constexpr double kIridSpread = 5.0 * 0.78 / 0.96;

double iridThicknessVariation(Vec3 P) {
    const pattern::Turbulence t;  // octaves 6, omega 0.5, lambda 2
    double mean = 0, amp = 1;
    for (int i = 0; i < t.octaves; ++i, amp *= t.omega) mean += 0.5 * amp;
    return 1 + kIridSpread * (pattern::turbulenceSum(P, t) - mean) / mean;
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

Vec3 povMirrorDirection(Vec3 d, Vec3 N, Vec3 Nfacing) {
    if (dot(d, N) >= 0) return normalize(reflect(d, Nfacing));
    Vec3 r = normalize(reflect(d, N));
    if (const double into = dot(r, Nfacing); into < 0) r -= (2 * into) * Nfacing;
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
    if (in.fadePower >= 1000) return beerAbsorption(Vec3(1.0) - in.fadeColor, q);
    const double a = std::isinf(q) ? 0.0 : 1.0 / (1.0 + std::pow(q, in.fadePower));
    return Vec3(a) + (1.0 - a) * in.fadeColor;
}

double povSpotFactor(const Light& light, Vec3 toPoint) {
    if (light.spot == Light::Spot::None) return 1.0;
    const double along = dot(toPoint, light.direction);
    if (light.spot == Light::Spot::Cylinder) {
        const double r = length(toPoint - along * light.direction);
        if (r >= light.spotFalloff) return 0.0;
        const double k =
            r <= light.spotRadius ? 1.0 : smooth((light.spotFalloff - r) / (light.spotFalloff - light.spotRadius));
        return light.tightness == 0 ? k : k * std::pow(1.0 - r / light.spotFalloff, light.tightness);
    }
    const double len = length(toPoint);
    if (len == 0) return 1.0;
    const double c = along / len;
    if (c <= 0) return 0.0;
    double k = 1.0;
    if (c < light.spotRadius) {
        if (c <= light.spotFalloff) return 0.0;
        k = smooth((c - light.spotFalloff) / (light.spotRadius - light.spotFalloff));
    }
    return light.tightness == 0 ? k : k * std::pow(c, light.tightness);
}

double povLightFade(const Light& light, double distance) {
    if (light.fadeDistance <= 0) return 1.0;
    return 2.0 / (1.0 + std::pow(distance / light.fadeDistance, light.fadePower));
}

Vec3 povIridTint(const PovFinish& f, Vec3 wavelength, Vec3 N, Vec3 L, Vec3 V, Vec3 P) {
    if (f.irid == 0) return Vec3(1.0);
    double t = f.iridThickness;
    if (f.iridTurbulence != 0) t *= 1 + f.iridTurbulence * iridThicknessVariation(P);
    const double path = 2 * std::numbers::pi * t * (dot(N, L) + dot(N, V));
    Vec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = 1 + f.irid * (wavelength[i] != 0 ? std::cos(path / wavelength[i]) : 1.0);
    return out;
}

namespace {

// The share of what lies behind a fog's segment that it lets through (before its filter's tint).
double fogKeeps(const PovFog& f, const Ray& ray, double t) {
    const double depth = (f.ground ? groundFogDepth(f, ray, t) : t) * fogTurbulenceFactor(f, ray, t);
    return std::max(std::exp(-depth / f.distance), f.transmit);
}

}  // namespace

Vec3 povFogLightTransmittance(const std::vector<PovFog>& fogs, const Ray& ray, double t) {
    Vec3 keep(1.0);
    for (const PovFog& f : fogs) {
        keep *= fogKeeps(f, ray, t) * (Vec3(1.0 - f.filter) + f.filter * f.color);
    }
    return keep;
}

Vec3 povFog(const std::vector<PovFog>& fogs, Vec3 behind, const Ray& ray, double t) {
    Vec3 keep(1.0), add;
    for (const PovFog& f : fogs) {
        const double a = fogKeeps(f, ray, t);
        keep *= a * (Vec3(1.0 - f.filter) + f.filter * f.color);
        add += (1.0 - a) * f.color;
    }
    return keep * behind + add;
}

}  // namespace rays
