#include "rays/pattern/ripples.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rays/pattern/noise.h"

namespace rays::pattern {
namespace {

constexpr double kRingTurn = 2 * std::numbers::pi;

}  // namespace

double ripplesValue(Vec3 p, int n) {
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += std::sin(kRingTurn * length(p - kWaveCentres[i]));
    return 0.5 + (0.5 / n) * sum;
}

double wavesValue(Vec3 p, int n) {
    double sum = 0;
    for (int i = 0; i < n; ++i)
        sum += std::sin(kRingTurn * kWaveFrequencies[i] * length(p - kWaveCentres[i])) / kWaveFrequencies[i];
    return 0.5 + (0.2 / n) * sum;
}

double dentsValue(Vec3 p) {
    const double n = std::clamp(0.5 + 0.934 * (noise(p) - 0.5), 0.0, 1.0);  // POV-Ray's spread (0.16 ± 0.11)
    return n * n * n;
}

}  // namespace rays::pattern
