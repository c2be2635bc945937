#include "rays/render/shading.h"
#include "rays/render/settings.h"

#include <cmath>
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
        case ShadingModel::Flat: return "Flat";
        case ShadingModel::Normals: return "Normals";
    }
    return "?";
}

}  // namespace rays
