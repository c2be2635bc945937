// Noise for the noise-based patterns and POV-Ray's classic turbulence (POV-Ray 3.7 reference,
// "Turbulence", "Octaves", "Omega", "Lambda"). The solid noise is rays/fn's (Perlin's improved
// noise, not POV-Ray's table), so noise patterns look alike but do not match POV-Ray point for point.
#pragma once
#include <cstdint>

#include "rays/math/vec3.h"

namespace rays::pattern {

/// turbulence <amount> with octaves, omega and lambda (POV-Ray's defaults 6, 0.5, 2).
struct Turbulence {
    Vec3 amount{0, 0, 0};
    int octaves = 6;
    double omega = 0.5, lambda = 2;
    bool on() const { return amount.x != 0 || amount.y != 0 || amount.z != 0; }
};

/// Solid noise in [0, 1] (noise_generator 2 range).
double noise(Vec3 p);
/// Vector noise, each component in about [−1, 1].
Vec3 vectorNoise(Vec3 p);
/// Σ omega^i · vectorNoise(p · lambda^i) over the octaves: the displacement direction of turbulence.
Vec3 turbulenceVector(Vec3 p, const Turbulence& t);
/// Σ omega^i · |2·noise(p · lambda^i) − 1|: the scalar turbulence of marble, agate and granite-like sums.
double turbulenceScalar(Vec3 p, int octaves, double omega, double lambda);
/// Σ omega^i · noise(p · lambda^i) over the octaves (each term in [0, 1]): the scalar turbulence fog
/// reads (measured with POV-Ray 3.7: its mean grows as Σ omega^i / 2, about 1 for the defaults).
double turbulenceSum(Vec3 p, const Turbulence& t);
/// p displaced by the turbulence: p + amount ⊙ turbulenceVector(p).
inline Vec3 turbulent(Vec3 p, const Turbulence& t) {
    const Vec3 d = turbulenceVector(p, t);
    return {p.x + t.amount.x * d.x, p.y + t.amount.y * d.y, p.z + t.amount.z * d.z};
}

}  // namespace rays::pattern
