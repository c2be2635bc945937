// The formulas are the manual's ("New_Value = fmod(Old_Value * Frequency + Phase, 1.0)", the wave
// shapes described under "Waveforms"); the wrapping details were measured with POV-Ray 3.7.0.10
// through `function { pigment { ... } }`: values already in [0, 1] are kept (gradient x at x = 1
// gives the map's end), others wrap by fmod with a divisor of 1.00001 (frequency 2 at x = 1 gives
// 0.99999), negative remainders move up by 1.
#include "rays/pattern/wave.h"

#include <cmath>
#include <numbers>

namespace rays::pattern {

double applyWave(const Wave& w, double v) {
    if (w.frequency != 1 || w.phase != 0) v = v * w.frequency + w.phase;
    if (v < 0 || v > 1) {
        v = std::fmod(v, 1.00001);
        if (v < 0) v += 1;
    }
    switch (w.type) {
        case WaveType::Ramp: return v;
        case WaveType::Triangle: return v < 0.5 ? 2 * v : 2 - 2 * v;
        case WaveType::Sine: return 0.5 + 0.5 * std::sin(2 * std::numbers::pi * v);
        case WaveType::Scallop: return std::fabs(std::sin(std::numbers::pi * v));
        case WaveType::Cubic: return v * v * (3 - 2 * v);
        case WaveType::Poly: return std::pow(v, w.exponent);
    }
    return v;
}

}  // namespace rays::pattern
