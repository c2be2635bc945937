// A pigment's colour: red, green, blue, filter and transmit (POV-Ray 3.7 reference, "Color
// Expressions"); colour maps interpolate all five.
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

struct Rgbft {
    Vec3 rgb;
    double filter = 0, transmit = 0;
};

/// a + (b − a)·t, component by component.
inline Rgbft mix(const Rgbft& a, const Rgbft& b, double t) {
    return {a.rgb + (b.rgb - a.rgb) * t, a.filter + (b.filter - a.filter) * t,
            a.transmit + (b.transmit - a.transmit) * t};
}

}  // namespace rays::pattern
