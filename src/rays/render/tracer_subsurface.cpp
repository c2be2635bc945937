// POV-Ray's subsurface light transport at a shaded point: the diffuse light of a finish with
// subsurface { translucency C } (when global_settings has a subsurface block) is the light that
// entered the object at points around it, spread by the dipole profile (render/pov_subsurface.h).
//
// The choices POV-Ray's reference leaves open, measured with povray 3.7 (boxes, spheres and slabs
// lit by a parallel light, docs/povray-lighting.md "Subsurface light transport"): diffuse·pigment
// is the total diffuse reflectance from which each channel's albedo is found (kAlbedoA); translucency is each
// channel's mean free path 1/σ′t in millimetres (mm_per_unit of them to a unit); the light goes in
// and out through the Fresnel transmission of the interior's ior, so a wide face lit head-on shows
// (1 − F(0))²·diffuse·pigment; near edges and in thin parts light leaves elsewhere and the surface
// darkens, and thin parts lit from behind glow.
//
// Integration (King et al. 2013): each sample picks an axis (the normal with probability 1/2,
// each tangent with 1/4), a radius r from one of the channels' e^(−σtr·r) and e^(−σ′t·r), and an angle; a
// probe ray along the axis through the point at r from the shaded point, within the sphere of
// radius rMax about it, meets the object's surface at any number of points, each weighed by the
// combined density of all axes and channels (multiple importance sampling, balance heuristic).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "rays/math/sampling.h"
#include "rays/render/pov_lighting.h"
#include "rays/render/pov_subsurface.h"
#include "rays/render/tracer.h"

namespace rays {

namespace {

// The share of light a boundary of relative index eta lets in (or out) at an angle of cosine c:
// 1 − Fresnel reflectance (measured: POV-Ray's wide face lit head-on shows diffuse·pigment times
// 1.04·(1 − F(0))² for indices 1 to 2, and a sphere the same ratio at every angle).
double transmittedShare(double c, double eta) { return eta == 1 ? 1.0 : 1 - fresnelReflectance(std::fabs(c), 1 / eta); }

// The radical inverse of i in the given base: the Halton sequence's coordinate (Halton 1960).
double radicalInverse(unsigned i, unsigned base) {
    double inverse = 0, digit = 1.0 / base;
    for (; i > 0; i /= base, digit /= base) inverse += (i % base) * digit;
    return inverse;
}

// One sample's numbers, the same at every shaded point (the Halton sequence in bases 2, 3, 5 and 7
// from index 1): the axis and rate choices, the exponential radius for rate 1 and the angle.
struct SubsurfaceSample {
    double axis, rate, radius, cosPhi, sinPhi;
};

const std::vector<SubsurfaceSample>& subsurfaceSamples() {
    static const std::vector<SubsurfaceSample> samples = [] {
        std::vector<SubsurfaceSample> v(kMaxSubsurfaceSamples);
        for (int i = 0; i < kMaxSubsurfaceSamples; ++i) {
            const unsigned index = unsigned(i) + 1;
            const double phi = 2 * std::numbers::pi * radicalInverse(index, 7);
            v[size_t(i)] = {radicalInverse(index, 2), radicalInverse(index, 3), -std::log1p(-radicalInverse(index, 5)),
                            std::cos(phi), std::sin(phi)};
        }
        return v;
    }();
    return samples;
}

// The albedo α′ of a channel is the one whose total diffuse reflectance, with this boundary term,
// is diffuse·pigment (measured: POV-Ray's wide face lit head-on shows (1 − F(0))² times 0.0082,
// 0.144, 0.335, 0.519, 0.640, 0.841 and 1.02 for diffuse·pigment 0.006, 0.12, 0.3, 0.48, 0.6, 0.8
// and 1, whatever the ior; albedos found with A = 1.5 and rendered with A = 1 give 0.006, 0.133,
// 0.335, 0.524, 0.642, 0.828 and 0.97: the closest of A = 1, 1.5, 2, 2.6 and 3).
constexpr double kAlbedoA = 1.5;
// The highest albedo taken: without absorption light would spread without end (diffusion length
// 1/σtr at most 58 mean free paths; total diffuse reflectance 0.97).
constexpr double kMaxAlbedo = 1 - 1e-4;
// The shortest mean free path taken (scene units): a translucency of 0 spreads no light to speak of.
constexpr double kMinFreePath = 1e-5;
// Beyond this many diffusion lengths of the widest channel the profile is left out (e^−9 ≈ 1.2e-4).
constexpr double kReachLengths = 9;
constexpr int kMaxProbeHits = 16;  // surface points one probe ray takes (a wavy surface's crossings)

}  // namespace

bool Tracer::povSubsurfaceLit(const PovSurface& s, const PovPoint& pt) const {
    return s.finish.subsurface && scene_.pov.subsurface.enabled && pt.highlights && pt.object >= 0 &&
           maxComponent(s.finish.translucency) > 0;
}

Vec3 Tracer::povSubsurfaceDiffuse(const PovPoint& pt, const PovSurface& s, Vec3 C, Vec3 V, TraceContext& ctx) const {
    const PovSubsurfaceSettings& g = scene_.pov.subsurface;
    const double eta = s.interior.ior > 0 ? s.interior.ior : 1.0;
    // The dipole's boundary term A: 1, as for a boundary that reflects nothing back inside, whatever
    // the ior (measured: POV-Ray's face of translucency 5 mm shows 0.444, 0.439 and 0.430 of
    // (1 − F(0))²·diffuse·pigment for ior 1, 1.3 and 2, where A from the ior, 1 to 8.5, would
    // take the last down by a fifth). The ior sets the Fresnel transmission only.
    constexpr double A = 1;
    Dipole dip[3];
    double widest = 0;
    int channels[3], usable = 0;
    for (int c = 0; c < 3; ++c) {
        const double mfp = std::max(s.finish.translucency[c] / g.mmPerUnit, kMinFreePath);
        if (!(s.finish.diffuse * C[c] > 0)) continue;
        const double albedo = std::min(dipoleAlbedoFor(s.finish.diffuse * C[c], kAlbedoA), kMaxAlbedo);
        dip[c] = dipoleOfAlbedo(albedo, mfp, A);
        widest = std::max(widest, 1 / dip[c].sigmaTr);
        channels[usable++] = c;
    }
    if (usable == 0) return {};
    // The radii are drawn from exponentials of two rates per channel: σtr, the profile's decay far
    // out, and σ′t, its width near the point, which is all there is to see of a channel of high
    // albedo (its profile falls as 1/r³ from r ≈ 1/σ′t out to 1/σtr).
    double rates[6];
    int rateCount = 0;
    for (int k = 0; k < usable; ++k) {
        rates[rateCount++] = dip[channels[k]].sigmaTr;
        rates[rateCount++] = dip[channels[k]].sigmaT;
    }
    const double rMax = kReachLengths * widest;
    const Object& object = scene_.objects[size_t(pt.object)];
    Vec3 axes[3];
    axes[0] = pt.Nfacing;
    orthonormalBasis(axes[0], axes[1], axes[2]);
    constexpr double kAxisChance[3] = {0.5, 0.25, 0.25};

    // The combined density of reaching surface point X (normal n) at offset d from P.
    auto density = [&](Vec3 d, Vec3 n) {
        double p = 0;
        for (int a = 0; a < 3; ++a) {
            const double along = dot(d, axes[a]);
            const double r = std::sqrt(std::max(0.0, dot(d, d) - along * along));
            if (!(r > 0)) return std::numeric_limits<double>::infinity();
            double radial = 0;
            for (int k = 0; k < rateCount; ++k) radial += rates[k] * std::exp(-rates[k] * r);
            p += kAxisChance[a] * std::fabs(dot(n, axes[a])) * radial / (rateCount * 2 * std::numbers::pi * r);
        }
        return p;
    };
    // The light entering the surface at X (outer normal n): each light's, through the boundary.
    // Flat shapes have no outer side that counts (a triangle's normal follows the order of its
    // corners): light enters them from either side; solids take it through their outer side only.
    const bool twoSided = object.type == ShapeType::Triangle || object.type == ShapeType::Mesh ||
                          object.type == ShapeType::Disc || object.type == ShapeType::Polygon;
    auto entering = [&](Vec3 X, Vec3 n) {
        Vec3 E;
        for (size_t li = 0; li < scene_.lights.size(); ++li) {
            const Light& light = scene_.lights[li];
            if (!povLightsSurface(light, s)) continue;
            Vec3 L;
            if (!povDirectionToLight(light, X, L)) continue;
            const bool behind = twoSided && dot(n, L) < 0;
            const Vec3 side = behind ? -n : n;
            const double nl = dot(side, L);
            if (!(nl > 0)) continue;
            const Vec3 reach = povLightReaching(light, li, X, side, false, ctx, true);
            if (reach == Vec3{}) continue;
            E += (nl * transmittedShare(nl, eta)) * reach;
        }
        return E;
    };

    // The same points of the Halton sequence at every shaded point: their error changes smoothly
    // over the surface instead of as grain (POV-Ray's subsurface light is smooth too).
    const std::vector<SubsurfaceSample>& table = subsurfaceSamples();
    Vec3 sum;
    const int n = std::clamp(g.samples, 1, kMaxSubsurfaceSamples);
    for (int i = 0; i < n; ++i) {
        const SubsurfaceSample& smp = table[size_t(i)];
        const int a = smp.axis < 0.5 ? 0 : (smp.axis < 0.75 ? 1 : 2);
        const double r = smp.radius / rates[std::min(rateCount - 1, int(smp.rate * rateCount))];
        if (!(r < rMax)) continue;
        const Vec3 u = axes[(a + 1) % 3], v = axes[(a + 2) % 3];
        const double h = std::sqrt(rMax * rMax - r * r);
        const Vec3 start = pt.P + (r * smp.cosPhi) * u + (r * smp.sinPhi) * v + h * axes[a];
        const Ray probe{start, -axes[a]};
        double from = 0;
        for (int k = 0; k < kMaxProbeHits; ++k) {
            ShapeHit hit;
            if (!intersect(object, probe, from, 2 * h, hit)) break;
            from = hit.t + kMinHitT;
            const Vec3 X = probe.at(hit.t);
            const Vec3 d = X - pt.P;
            const double p = density(d, hit.normal);
            if (!(p > 0) || !std::isfinite(p)) continue;
            const Vec3 E = entering(X, hit.normal);
            if (E == Vec3{}) continue;
            const double dist = length(d);
            Vec3 profile;
            for (int q = 0; q < usable; ++q) profile[channels[q]] = dipoleProfile(dip[channels[q]], dist);
            sum += (1 / p) * profile * E;
        }
    }
    // POV-Ray 3.7 lights a surface with nothing of the object behind it twice as brightly as the
    // face of a solid (measured, head-on: a plane, a triangle, a disc, a polygon and an open mesh
    // show 1.92 to 2.0 times what the face of a box, a sphere, a cylinder or a closed mesh shows,
    // for translucency 0.1 to 5 mm; a plane seen obliquely the same), as if it averaged only
    // those of its probes that meet the object; Rays follows it, looking once straight inwards.
    ShapeHit behind;
    const Ray inwards{pt.P - kSurfaceOffset * pt.Nfacing, -pt.Nfacing};
    const double gain = intersect(object, inwards, 0, std::numeric_limits<double>::infinity(), behind) ? 1.0 : 2.0;
    const double out = transmittedShare(dot(pt.Nfacing, V), eta);
    return (gain * out / n) * sum;
}

}  // namespace rays
