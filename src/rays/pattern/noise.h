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

/// Solid noise in about [0, 1] (noise_generator 2's range): the value of `bozo`.
double noise(Vec3 p);
/// The noise before its range is corrected, 2·noise − 0.5 (about −0.3 to 1.4): measured with
/// POV-Ray 3.7, its turbulence and its granite and wrinkles sums are made of this value of the
/// same noise that bozo shows (docs/povray-patterns.md, "Noise sums").
inline double rawNoise(Vec3 p) { return 2 * noise(p) - 0.5; }
/// rawNoise clamped to [0, 1] (noise_generator 1's value).
inline double clampedNoise(Vec3 p) {
    const double r = rawNoise(p);
    return r < 0 ? 0 : (r > 1 ? 1 : r);
}
/// The noise as bozo shows it under noise_generator 1 (measured with POV-Ray 3.7 at 8,000 random
/// points: clamp(2.0414·noise − 0.5524, 0, 1) to 2e-6), 2 (noise) or 3 (a noise of its own in
/// POV-Ray, 0.492 ± 0.146; here Rays' noise widened to that spread).
double noiseOfGenerator(Vec3 p, int generator);
/// Vector noise, each component in about [−1, 1].
Vec3 vectorNoise(Vec3 p);
/// Σ omega^i · vectorNoise(p · lambda^i) over the octaves: the displacement direction of turbulence.
Vec3 turbulenceVector(Vec3 p, const Turbulence& t);
/// POV-Ray's scalar turbulence, clampedNoise(p) + Σ_{i≥1} omega^i · rawNoise(p · lambda^i) (measured
/// with POV-Ray 3.7's marble at turbulence 0.001, to 1.5e-7: only the first octave is clamped):
/// what marble, agate and fog add. Mean about 1 and spread 0.3 for the default octaves.
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
