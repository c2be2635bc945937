// Noise-based internal functions: f_noise3d, f_noise_generator, f_hetero_mf, f_ridged_mf,
// f_ridge. They use fn/noise.h, which is not POV-Ray's noise yet, so their values differ from
// POV-Ray's; the fractal sums follow F. K. Musgrave's published multifractals ("Texturing and
// Modeling: A Procedural Approach", Ebert et al., chapter 16: HeteroTerrain and
// RidgedMultifractal) with the parameters the reference names. Tests check ranges, continuity
// and determinism, not POV-Ray's values.
#include <algorithm>
#include <cmath>

#include "rays/fn/internal_impl.h"
#include "rays/fn/noise.h"

namespace rays::fn::internal {
namespace {

// Noise in [-1, 1] at p·scale from generator g.
double signedNoise(const double* p, double scale, int g) {
    return 2 * noise3d(p[0] * scale, p[1] * scale, p[2] * scale, g) - 1;
}

int generator(double g) { return g >= 1 && g <= 3 ? static_cast<int>(g) : 2; }

// Octave counts are capped so that a huge parameter cannot stall a render (NaN counts as 0).
double octaves(double o) { return o > 0 ? std::min(o, 64.0) : 0.0; }

}  // namespace

// POV-Ray's noise3d: solid noise in [0, 1].
double f_noise3d(const double* p) { return noise3d(p[0], p[1], p[2]); }

// noise3d with generator P0 (1, 2 or 3; others use 2).
double f_noise_generator(const double* p) { return noise3d(p[0], p[1], p[2], generator(p[3])); }

// Musgrave's heterogeneous terrain: value = offset + n(p); each further octave i (frequency
// lacunarity^i, amplitude lacunarity^(−iH)) adds (n + offset)·amplitude·((1 − T) + T·value), so T
// = 0 is plain 1/f noise and T = 1 damps high frequencies at low altitudes; a fractional octave
// count adds that fraction of the next octave. P0 H, P1 lacunarity, P2 octaves, P3 offset, P4 T,
// P5 noise generator.
double f_hetero_mf(const double* p) {
    const double H = p[3], lac = p[4], oct = octaves(p[5]), offset = p[6], T = p[7];
    const int g = generator(p[8]);
    double value = offset + signedNoise(p, 1, g);
    double freq = lac;
    int i = 1;
    for (; i < static_cast<int>(oct); ++i, freq *= lac) {
        const double inc = (signedNoise(p, freq, g) + offset) * std::pow(freq, -H) * ((1 - T) + T * value);
        value += inc;
    }
    const double rest = oct - std::floor(oct);
    if (rest > 0 && oct >= 1) {
        value += rest * (signedNoise(p, freq, g) + offset) * std::pow(freq, -H) * ((1 - T) + T * value);
    }
    return value;
}

// Musgrave's ridged multifractal: signal = (offset − |n|)², each further octave weighted by the
// previous signal times the gain (clamped to [0, 1]) and by lacunarity^(−iH). P0 H, P1
// lacunarity, P2 octaves, P3 offset, P4 gain, P5 noise generator.
double f_ridged_mf(const double* p) {
    const double H = p[3], lac = p[4], oct = octaves(p[5]), offset = p[6], gain = p[7];
    const int g = generator(p[8]);
    double signal = offset - std::fabs(signedNoise(p, 1, g));
    signal *= signal;
    double result = signal, freq = 1;
    for (int i = 1; i < static_cast<int>(oct); ++i) {
        freq *= lac;
        const double weight = std::clamp(signal * gain, 0.0, 1.0);
        signal = offset - std::fabs(signedNoise(p, freq, g));
        signal = signal * signal * weight;
        result += signal * std::pow(freq, -H);
    }
    return result;
}

// Ridges: Σ ω^i·r_i over the octaves i (frequency λ^i), with r = offset − |n| blended with the
// plain noise n by the ridge weight: (1 − ridge)·n + ridge·r. P0 λ, P1 octaves, P2 ω, P3 offset,
// P4 ridge, P5 noise generator.
double f_ridge(const double* p) {
    const double lambda = p[3], oct = octaves(p[4]), omega = p[5], offset = p[6], ridge = p[7];
    const int g = generator(p[8]);
    double sum = 0, amp = 1, freq = 1;
    for (int i = 0; i < std::max(1, static_cast<int>(oct)); ++i, amp *= omega, freq *= lambda) {
        const double n = signedNoise(p, freq, g);
        sum += amp * ((1 - ridge) * n + ridge * (offset - std::fabs(n)));
    }
    return sum;
}

}  // namespace rays::fn::internal
