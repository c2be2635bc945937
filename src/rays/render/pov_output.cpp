#include "rays/render/pov_output.h"

#include <algorithm>
#include <cmath>

namespace rays {

double srgbEncode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

Vec3 povOutputColor(Vec3 c, double assumedGamma, double fileGamma) {
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
        const double v = std::clamp(c[i], 0.0, 1.0);
        if (!(assumedGamma > 0)) {
            out[i] = v;
            continue;
        }
        const double linear = assumedGamma == 1 ? v : std::pow(v, assumedGamma);
        out[i] = fileGamma > 0 ? (fileGamma == 1 ? linear : std::pow(linear, 1 / fileGamma)) : srgbEncode(linear);
    }
    return out;
}

}  // namespace rays
