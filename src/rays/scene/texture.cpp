#include "rays/scene/texture.h"

#include <cmath>

#include "rays/io/image_io.h"

namespace rays {

Vec3 Texture::texel(int x, int y) const {
    x = ((x % width) + width) % width;
    y = ((y % height) + height) % height;
    const float* p = &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3];
    return {p[0], p[1], p[2]};
}

Vec3 Texture::sample(double u, double v, bool bilinear) const {
    u -= std::floor(u);
    v -= std::floor(v);
    // Image rows run top to bottom; v runs bottom to top.
    const double fx = u * width, fy = (1.0 - v) * height;
    if (!bilinear) return texel(int(fx), int(fy));
    const double x = fx - 0.5, y = fy - 0.5;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const double tx = x - x0, ty = y - y0;
    return (1 - tx) * (1 - ty) * texel(x0, y0) + tx * (1 - ty) * texel(x0 + 1, y0) + (1 - tx) * ty * texel(x0, y0 + 1) +
           tx * ty * texel(x0 + 1, y0 + 1);
}

Texture loadTexture(const std::string& path, double gamma) {
    const Image8 img = readImage(path);
    Texture t;
    t.path = path;
    t.width = img.width;
    t.height = img.height;
    t.rgb.resize(size_t(img.width) * size_t(img.height) * 3);
    for (size_t i = 0; i < size_t(img.width) * size_t(img.height); ++i) {
        const uint8_t* p = &img.pixels[i * size_t(img.channels)];
        for (int c = 0; c < 3; ++c) {
            const uint8_t byte = img.channels >= 3 ? p[c] : p[0];
            const double value = byte / 255.0;
            t.rgb[i * 3 + size_t(c)] = float(gamma == 1.0 ? value : std::pow(value, gamma));
        }
    }
    return t;
}

}  // namespace rays
