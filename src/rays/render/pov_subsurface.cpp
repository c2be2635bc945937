#include "rays/render/pov_subsurface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays {

double dipoleTotalReflectance(double albedo, double A) {
    const double s = std::sqrt(3 * (1 - std::clamp(albedo, 0.0, 1.0)));
    return 0.5 * albedo * (1 + std::exp(-(4.0 / 3.0) * A * s)) * std::exp(-s);
}

double dipoleAlbedoFor(double Rd, double A) {
    const double target = std::clamp(Rd, 0.0, 1.0);
    double lo = 0, hi = 1;
    for (int i = 0; i < 48; ++i) {
        const double mid = 0.5 * (lo + hi);
        (dipoleTotalReflectance(mid, A) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

Dipole makeDipole(double Rd, double meanFreePath, double A) {
    return dipoleOfAlbedo(dipoleAlbedoFor(Rd, A), meanFreePath, A);
}

Dipole dipoleOfAlbedo(double albedo, double meanFreePath, double A) {
    Dipole d;
    d.albedo = albedo;
    d.sigmaT = 1 / meanFreePath;
    d.sigmaTr = d.sigmaT * std::sqrt(3 * (1 - d.albedo));
    d.zr = meanFreePath;
    d.zv = d.zr * (1 + 4 * A / 3);
    return d;
}

double dipoleProfile(const Dipole& d, double r) {
    const double r2 = r * r;
    const double dr = std::sqrt(r2 + d.zr * d.zr), dv = std::sqrt(r2 + d.zv * d.zv);
    const double real = d.zr * (d.sigmaTr * dr + 1) * std::exp(-d.sigmaTr * dr) / (dr * dr * dr);
    const double virt = d.zv * (d.sigmaTr * dv + 1) * std::exp(-d.sigmaTr * dv) / (dv * dv * dv);
    return d.albedo / (4 * std::numbers::pi) * (real + virt);
}

}  // namespace rays
