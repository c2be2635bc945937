// POV-Ray's blend-map modifiers (POV-Ray 3.7 reference, "Frequency and Phase", "Waveforms"):
// the pattern value is scaled by frequency, shifted by phase, wrapped into [0, 1] and shaped by
// the wave type before the map is looked up.
#pragma once
#include <cstdint>

namespace rays::pattern {

enum class WaveType : uint8_t { Ramp, Triangle, Sine, Scallop, Cubic, Poly };

struct Wave {
    WaveType type = WaveType::Ramp;
    double frequency = 1, phase = 0;
    double exponent = 1;  ///< poly_wave's exponent
};

/// The map position of pattern value v under the wave (measured against POV-Ray 3.7.0.10).
double applyWave(const Wave& w, double v);

}  // namespace rays::pattern
