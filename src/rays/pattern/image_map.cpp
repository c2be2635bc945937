#include "rays/pattern/image_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays::pattern {

namespace {

double srgbToLinear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

// x wrapped into [0, n).
int wrap(int x, int n) { return ((x % n) + n) % n; }

}  // namespace

void ImageMap::setWorkingGamma(double assumedGamma) {
    for (int i = 0; i < 256; ++i) {
        const double v = i / 255.0;
        double linear = v;
        // A legacy scene (assumed_gamma unset before #version 3.7) uses the bytes as they are.
        if (assumedGamma > 0) {
            switch (fileGamma.kind) {
                case FileGamma::Kind::Linear: linear = v; break;
                case FileGamma::Kind::Srgb: linear = srgbToLinear(v); break;
                case FileGamma::Kind::Power: linear = std::pow(v, fileGamma.gamma); break;
            }
            // Linear light → the working space: c = linear^(1/assumed_gamma).
            if (fileGamma.kind != FileGamma::Kind::Linear && assumedGamma != 1)
                linear = std::pow(linear, 1 / assumedGamma);
        }
        decode[size_t(i)] = float(linear);
    }
}

bool ImageMap::coordinates(Vec3 p, double& u, double& v) const {
    constexpr double kTwoPi = 2 * std::numbers::pi;
    switch (mapType) {
        case 1: {  // spherical: u from +x toward +z around y, v from the south pole to the north
            const double r = length(p);
            u = std::atan2(p.z, p.x) / kTwoPi;
            v = r > 0 ? 0.5 + std::asin(std::clamp(p.y / r, -1.0, 1.0)) / std::numbers::pi : 0.5;
            u -= std::floor(u);
            return true;
        }
        case 2:  // cylindrical: u as spherical, v = y, one unit tall
            u = std::atan2(p.z, p.x) / kTwoPi;
            u -= std::floor(u);
            v = p.y;
            if (once && (v < 0 || v >= 1)) return false;
            v -= std::floor(v);
            return true;
        case 5: {  // torus of major radius 1 in the xz plane: v around the tube, 0 and 1 on the inner rim
            u = std::atan2(p.z, p.x) / kTwoPi;
            u -= std::floor(u);
            const double rho = std::sqrt(p.x * p.x + p.z * p.z) - majorRadius;
            v = (std::atan2(p.y, rho) + std::numbers::pi) / kTwoPi;
            v -= std::floor(v);
            return true;
        }
        default:  // planar: the unit square of the xy plane
            u = p.x;
            v = p.y;
            if (once && (u < 0 || u >= 1 || v < 0 || v >= 1)) return false;
            u -= std::floor(u);
            v -= std::floor(v);
            return true;
    }
}

Rgbft ImageMap::texel(int x, int y) const {
    const Image8& img = *image;
    x = wrap(x, img.width);
    y = wrap(y, img.height);
    const uint8_t* px = img.pixels.data() + (size_t(y) * size_t(img.width) + size_t(x)) * size_t(img.channels);
    Rgbft c;
    const bool grey = img.channels < 3;
    c.rgb = grey ? Vec3(decode[px[0]]) : Vec3{decode[px[0]], decode[px[1]], decode[px[2]]};
    c.filter = filterAll;
    c.transmit = transmitAll;
    if (!palette.empty() && !grey) {
        for (const PaletteAmount& e : palette)
            if (e.r == px[0] && e.g == px[1] && e.b == px[2]) (e.transmit ? c.transmit : c.filter) = e.amount;
    }
    // The alpha channel: transparency 1 − alpha (alpha itself is linear).
    if (img.channels == 2 || img.channels == 4) {
        const double alpha = px[img.channels - 1] / 255.0;
        c.transmit = 1 - (1 - c.transmit) * alpha;
    }
    return c;
}

ImageMap::Taps ImageMap::taps(double u, double v) const {
    Taps t;
    const int w = image->width, h = image->height;
    // Image rows run top to bottom; v runs bottom to top.
    const double fx = u * w, fy = (1 - v) * h;
    if (interpolate != 2 && interpolate != 4) {
        t.x[0] = std::min(int(fx), w - 1), t.y[0] = std::min(int(fy), h - 1), t.w[0] = 1, t.count = 1;
        return t;
    }
    // Between the four nearest texel centres.
    const double x = fx - 0.5, y = fy - 0.5;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const double tx = x - x0, ty = y - y0;
    const int at[4][2] = {{x0, y0}, {x0 + 1, y0}, {x0, y0 + 1}, {x0 + 1, y0 + 1}};
    for (int i = 0; i < 4; ++i) t.x[i] = at[i][0], t.y[i] = at[i][1];
    t.count = 4;
    if (interpolate == 2) {
        t.w[0] = (1 - tx) * (1 - ty), t.w[1] = tx * (1 - ty), t.w[2] = (1 - tx) * ty, t.w[3] = tx * ty;
        return t;
    }
    // Normalised distance: each texel weighted by the inverse square of its distance to the
    // point, the weights normalised to sum to one (measured with POV-Ray 3.7: a 4×2 image).
    const double dx[4] = {tx, 1 - tx, tx, 1 - tx}, dy[4] = {ty, ty, 1 - ty, 1 - ty};
    double sum = 0;
    for (int i = 0; i < 4; ++i) {
        const double d2 = dx[i] * dx[i] + dy[i] * dy[i];
        if (d2 < 1e-12) {
            t.x[0] = at[i][0], t.y[0] = at[i][1], t.w[0] = 1, t.count = 1;
            return t;
        }
        sum += t.w[i] = 1 / d2;
    }
    for (double& wt : t.w) wt /= sum;
    return t;
}

Rgbft ImageMap::color(Vec3 p) const {
    double u = 0, v = 0;
    if (!image || image->width <= 0 || image->height <= 0) return {};
    if (!coordinates(p, u, v)) return {Vec3(0), 0, 1};  // outside a `once` image: fully transparent
    const Taps t = taps(u, v);
    if (t.count == 1) return texel(t.x[0], t.y[0]);
    Rgbft out;
    for (int i = 0; i < t.count; ++i) {
        const Rgbft c = texel(t.x[i], t.y[i]);
        out.rgb += c.rgb * t.w[i];
        out.filter += c.filter * t.w[i];
        out.transmit += c.transmit * t.w[i];
    }
    return out;
}

void ImageMap::setPatternGamma(double g) {
    for (int i = 0; i < 256; ++i) patternDecode[size_t(i)] = float(g == 1 ? i / 255.0 : std::pow(i / 255.0, g));
}

double ImageMap::texelValue(int x, int y) const {
    const Image8& img = *image;
    x = wrap(x, img.width);
    y = wrap(y, img.height);
    const uint8_t* px = img.pixels.data() + (size_t(y) * size_t(img.width) + size_t(x)) * size_t(img.channels);
    if (useAlpha) return img.channels == 2 || img.channels == 4 ? 1 - px[img.channels - 1] / 255.0 : 0.0;
    const auto& d = patternDecode;
    if (img.channels < 3) return d[px[0]];
    return 0.297 * d[px[0]] + 0.589 * d[px[1]] + 0.114 * d[px[2]];
}

double ImageMap::value(Vec3 p) const {
    double u = 0, v = 0;
    if (!image || image->width <= 0 || image->height <= 0 || !coordinates(p, u, v)) return 0;
    return valueAt(u, v);
}

int ImageMap::materialIndex(Vec3 p) const {
    double u = 0, v = 0;
    if (!image || image->width <= 0 || image->height <= 0 || !coordinates(p, u, v)) return 0;
    const Image8& img = *image;
    const int x = std::clamp(int(u * img.width), 0, img.width - 1), y = std::clamp(int((1 - v) * img.height), 0, img.height - 1);
    const uint8_t* px = img.pixels.data() + (size_t(y) * size_t(img.width) + size_t(x)) * size_t(img.channels);
    if (img.channels < 3) return px[0];
    return int(std::lround(0.297 * px[0] + 0.589 * px[1] + 0.114 * px[2]));
}

double ImageMap::valueAt(double u, double v) const {
    if (!image || image->width <= 0 || image->height <= 0) return 0;
    const Taps t = taps(u - std::floor(u), v - std::floor(v));
    double out = 0;
    for (int i = 0; i < t.count; ++i) out += texelValue(t.x[i], t.y[i]) * t.w[i];
    return out;
}

}  // namespace rays::pattern
