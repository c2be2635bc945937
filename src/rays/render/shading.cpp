#include "rays/render/shading.h"
#include "rays/render/settings.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <numbers>

namespace rays {


LightTerms blinnPhong(const Material& m, Vec3 N, Vec3 L, Vec3 V, Vec3 lightColor) {
    LightTerms out;
    const double nl = dot(N, L);
    out.diffuse = lightColor * m.color * (m.diffuse * std::max(0.0, nl));
    if (m.specular != 0) {
        const Vec3 H = normalize(L + V);
        const double nh = std::max(0.0, dot(N, H));
        const double exponent = 2.0 / (m.roughness * m.roughness) - 2.0;
        out.specular = lightColor * m.color * (m.specular * std::pow(nh, exponent));
    }
    return out;
}

double schlickFresnel(double ior, double cosTheta) {
    const double r = (ior - 1.0) / (ior + 1.0);
    const double f0 = r * r;
    return f0 + (1.0 - f0) * std::pow(1.0 - std::fabs(cosTheta), 5.0);
}

namespace {

// Smith masking for GGX, one direction (Walter et al. 2007).
double smithG1(double nx, double alpha2) {
    return 2.0 * nx / (nx + std::sqrt(alpha2 + (1.0 - alpha2) * nx * nx));
}

}  // namespace

LightTerms cookTorrance(const Material& m, Vec3 N, Vec3 L, Vec3 V, Vec3 lightColor) {
    LightTerms out;
    const double nl = dot(N, L);
    if (nl <= 0) return out;
    out.diffuse = lightColor * m.color * (m.diffuse * nl * (1.0 - m.metallic));
    if (m.specular == 0) return out;
    const Vec3 H = normalize(L + V);
    const double nh = std::max(0.0, dot(N, H));
    const double nv = std::fabs(dot(N, V));
    const double alpha = m.roughness * m.roughness;
    const double a2 = alpha * alpha;
    const double denom = nh * nh * (a2 - 1.0) + 1.0;
    const double D = a2 / (std::numbers::pi * denom * denom);
    const double G = smithG1(nl, a2) * smithG1(nv, a2);
    const double r = (m.ior - 1.0) / (m.ior + 1.0);
    const double f0 = r * r * (1.0 - m.metallic) + m.metallic;
    const double vh = std::max(0.0, dot(V, H));
    const double F = f0 + (1.0 - f0) * std::pow(1.0 - vh, 5.0);
    out.specular = lightColor * m.color * (m.specular * D * G * F / (4.0 * std::max(1.0 / 16.0, nv)));
    return out;
}

const char* shadingName(ShadingModel m) {
    switch (m) {
        case ShadingModel::BlinnPhong: return "Blinn-Phong";
        case ShadingModel::CookTorrance: return "Cook-Torrance";
        case ShadingModel::OrenNayar: return "Oren-Nayar";
        case ShadingModel::Lambert: return "Lambert";
        case ShadingModel::Flat: return "Flat";
        case ShadingModel::Normals: return "Normals";
    }
    return "?";
}

bool parseShadingName(const char* name, ShadingModel& out) {
    std::string n(name);
    for (char& c : n)
        if (c == '_') c = '-';
    static const std::pair<const char*, ShadingModel> kNames[] = {
        {"blinn-phong", ShadingModel::BlinnPhong}, {"cook-torrance", ShadingModel::CookTorrance},
        {"oren-nayar", ShadingModel::OrenNayar},   {"lambert", ShadingModel::Lambert},
        {"flat", ShadingModel::Flat},              {"normals", ShadingModel::Normals}};
    for (const auto& [k, v] : kNames)
        if (n == k) {
            out = v;
            return true;
        }
    return false;
}

LightTerms lambert(const Material& m, Vec3 N, Vec3 L, Vec3 lightColor) {
    LightTerms out;
    const double nl = dot(N, L);
    if (nl > 0) out.diffuse = lightColor * m.color * (m.diffuse * nl);
    return out;
}

// Oren & Nayar 1994, qualitative model: A = 1 − σ²/(2(σ²+0.33)), B = 0.45σ²/(σ²+0.09),
// f = A + B·max(0, cos(φi − φr))·sin α·tan β with α = max(θi, θr), β = min(θi, θr).
LightTerms orenNayar(const Material& m, Vec3 N, Vec3 L, Vec3 V, Vec3 lightColor) {
    LightTerms out;
    const double nl = dot(N, L);
    if (nl <= 0) return out;
    const double sigma = m.sigma * std::numbers::pi / 180.0;
    const double s2 = sigma * sigma;
    const double A = 1.0 - 0.5 * s2 / (s2 + 0.33);
    const double B = 0.45 * s2 / (s2 + 0.09);
    const double nv = std::clamp(dot(N, V), 0.0, 1.0);
    const double thetaI = std::acos(std::min(1.0, nl)), thetaR = std::acos(nv);
    // cos(φi − φr): angle between L and V projected onto the tangent plane.
    const Vec3 lp = L - nl * N, vp = V - nv * N;
    const double ll = length(lp), lv = length(vp);
    const double cosPhi = (ll > 1e-12 && lv > 1e-12) ? dot(lp, vp) / (ll * lv) : 0.0;
    const double alpha = std::max(thetaI, thetaR), beta = std::min(thetaI, thetaR);
    const double f = A + B * std::max(0.0, cosPhi) * std::sin(alpha) * std::tan(beta);
    out.diffuse = lightColor * m.color * (m.diffuse * nl * f);
    return out;
}

}  // namespace rays
