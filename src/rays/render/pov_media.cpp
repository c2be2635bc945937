#include "rays/render/pov_media.h"

#include <algorithm>
#include <cmath>

namespace rays {

namespace {

// Scales of the phase functions (measured: a thin slab lit from a known angle, povray 3.7).
constexpr double kMieHazyScale = 0.5766;
constexpr double kMieMurkyScale = 0.4954;
constexpr double kRayleighScale = 0.7994;

double phasePow8(double x) {
    const double x2 = x * x, x4 = x2 * x2;
    return x4 * x4;
}

}  // namespace

double povMediaPhase(const PovMedia& m, double c) {
    c = std::clamp(c, -1.0, 1.0);
    switch (m.type) {
        case PovMedia::Scattering::None: return 0.0;
        case PovMedia::Scattering::Isotropic: return 1.0;
        case PovMedia::Scattering::MieHazy: return kMieHazyScale * (1 + 9 * phasePow8(0.5 * (1 + c)));
        case PovMedia::Scattering::MieMurky: {
            const double x8 = phasePow8(0.5 * (1 + c));
            const double x32 = (x8 * x8) * (x8 * x8);
            return kMieMurkyScale * (1 + 50 * x32);
        }
        case PovMedia::Scattering::Rayleigh: return kRayleighScale * (1 + c * c);
        case PovMedia::Scattering::HenyeyGreenstein: {
            const double g = m.eccentricity;
            const double d = 1 + g * g - 2 * g * c;
            return d > 0 ? (1 - g * g) / (d * std::sqrt(d)) : 0.0;
        }
    }
    return 0.0;
}

Vec3 povMediaDensity(const Scene& scene, const PovMedia& m, Vec3 P) {
    Vec3 d(1.0);
    for (int i = 0; i < m.densityCount; ++i) {
        d *= scene.pigments.atRoot(m.densityFirst + i, P).rgb;
        if (d == Vec3{}) break;
    }
    return d;
}

namespace {

// Roots of a·t² + b·t + c strictly inside (t0, t1), appended to out.
int quadraticRootsIn(double a, double b, double c, double t0, double t1, double* out, int room) {
    double r[2];
    int n = 0;
    if (std::fabs(a) < 1e-12) {
        if (b != 0) r[n++] = -c / b;
    } else {
        const double disc = b * b - 4 * a * c;
        if (disc < 0) return 0;
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        if (q != 0) r[n++] = c / q;
        r[n++] = q / a;
    }
    int added = 0;
    for (int i = 0; i < n && added < room; ++i)
        if (r[i] > t0 && r[i] < t1) out[added++] = r[i];
    return added;
}

}  // namespace

int povLightBeamEdges(const Light& light, const Ray& ray, double t0, double t1, double* out, int room) {
    if (light.spot == Light::Spot::None || room <= 0) return 0;
    const Vec3 a = light.direction, V = ray.origin - light.position, D = ray.dir;
    const double da = dot(D, a), va = dot(V, a);
    int n = 0;
    const double edges[2] = {light.spotRadius, light.spotFalloff};
    for (double e : edges) {
        if (light.spot == Light::Spot::Cone) {
            // (X·a)² = cos²·|X|², X = V + t·D: the double cone of half angle acos(e) about a.
            const double c2 = e * e;
            n += quadraticRootsIn(da * da - c2 * dot(D, D), 2 * (da * va - c2 * dot(D, V)), va * va - c2 * dot(V, V),
                                  t0, t1, out + n, room - n);
        } else {
            // |X − (X·a)a|² = e²: the cylinder of radius e about the axis.
            const Vec3 W = D - da * a, U = V - va * a;
            n += quadraticRootsIn(dot(W, W), 2 * dot(W, U), dot(U, U) - e * e, t0, t1, out + n, room - n);
        }
    }
    return n;
}

int povMediaSteps(int samples) { return std::max(samples, 3) / 2 + 1; }

int povMediaSteps(const PovMedia& m) { return m.method == 3 ? povMediaSteps(m.samples) : std::max(1, m.samples); }

void PovMediaSet::add(const PovMedia* first, int count) {
    if (count <= 0 || spanCount == kMaxSpans) return;
    if (spanCount == 0) midpoints = first[0].method != 3;
    spans[spanCount++] = Span{first, count};
    for (int i = 0; i < count; ++i) {
        const PovMedia& m = first[i];
        scatters = scatters || m.scatters();
        steps = std::max(steps, povMediaSteps(m));
        intervals = std::max(intervals, m.intervals);
        aaLevel = std::max(aaLevel, m.aaLevel);
        aaThreshold = std::min(aaThreshold, m.aaThreshold);
        jitter = std::max(jitter, m.jitter);
    }
}

Vec3 povMediaTransmittance(const Scene& scene, const PovMediaSet& set, const Ray& ray, double t0, double t1) {
    if (!(t1 > t0)) return Vec3(1.0);
    Vec3 depth;
    bool varies = false;
    for (int s = 0; s < set.spanCount; ++s)
        for (int i = 0; i < set.spans[s].count; ++i) {
            const PovMedia& m = set.spans[s].first[i];
            if (m.densityCount == 0) depth += m.extinctionColor() * (t1 - t0);  // constant: exact
            else varies = varies || !(m.extinctionColor() == Vec3{});
        }
    if (varies) {
        const int steps = set.intervals * set.steps;
        const double h = (t1 - t0) / steps;
        for (int k = 0; k < steps; ++k) {
            const Vec3 P = ray.at(t0 + (k + 0.5) * h);
            for (int s = 0; s < set.spanCount; ++s)
                for (int i = 0; i < set.spans[s].count; ++i) {
                    const PovMedia& m = set.spans[s].first[i];
                    if (m.densityCount == 0) continue;
                    const Vec3 sigma = m.extinctionColor();
                    if (sigma == Vec3{}) continue;
                    depth += sigma * povMediaDensity(scene, m, P) * h;
                }
        }
    }
    Vec3 out;
    for (int c = 0; c < 3; ++c) out[c] = depth[c] > 0 ? std::exp(-depth[c]) : 1.0;
    return out;
}

}  // namespace rays
