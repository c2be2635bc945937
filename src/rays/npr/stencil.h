// Ray stencil of Choudhury & Parker ("Ray Tracing NPR-Style Feature Lines", NPAR 2009): N rings
// around the camera ray, ring r with 8r rays at radius r·R/N pixels.
#pragma once
#include <cmath>
#include <numbers>
#include <vector>

namespace rays {

struct StencilOffset {
    double dx, dy;  ///< pixels from the centre ray
};

/// Disc radius R for a line of the given width. With m of n stencil rays differing the strength
/// is e = 1 − |m − n/2|/(n/2); across a straight edge e integrates to 8R/(3π) ≈ 0.85·R pixels of
/// ink, so R = width · 3π/8 makes the measured line width equal the requested width.
inline double stencilRadius(double width) { return width * 3.0 * std::numbers::pi / 8.0; }

/// The offsets for a disc of radius R: max(1, ⌈R⌉) rings.
inline std::vector<StencilOffset> makeStencil(double radius) {
    const int rings = std::max(1, int(std::ceil(radius)));
    std::vector<StencilOffset> out;
    for (int r = 1; r <= rings; ++r) {
        const int count = 8 * r;
        const double rad = r * radius / rings;
        const double phase = (r % 2) * std::numbers::pi / count;  // stagger alternate rings
        for (int k = 0; k < count; ++k) {
            const double a = phase + 2 * std::numbers::pi * k / count;
            out.push_back({rad * std::cos(a), rad * std::sin(a)});
        }
    }
    return out;
}

/// Line strength for m of n differing stencil rays: 0 when none differ, 1 when half do.
inline double stencilStrength(int m, int n) { return 1.0 - std::fabs(m - n / 2.0) / (n / 2.0); }

}  // namespace rays
