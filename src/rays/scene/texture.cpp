#include "rays/scene/texture.h"

#include <cmath>

#include "rays/io/image_io.h"

namespace rays {

Vec3 Texture::texel(int x, int y) const {
    x = ((x % width) + width) % width;
    y = ((y % height) + height) % height;
    const uint8_t* p = &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3];
    return {decode[p[0]], decode[p[1]], decode[p[2]]};
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
    Image8 img = readImage(path);
    Texture t;
    t.path = path;
    t.width = img.width;
    t.height = img.height;
    for (int b = 0; b < 256; ++b) {
        const double value = b / 255.0;
        t.decode[size_t(b)] = float(gamma == 1.0 ? value : std::pow(value, gamma));
    }
    const size_t n = size_t(img.width) * size_t(img.height);
    if (img.channels == 3) {
        t.rgb = std::move(img.pixels);  // no copy of a big image
        return t;
    }
    t.rgb.resize(n * 3);
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* p = &img.pixels[i * size_t(img.channels)];
        for (size_t c = 0; c < 3; ++c) t.rgb[i * 3 + c] = img.channels >= 3 ? p[c] : p[0];
    }
    return t;
}

}  // namespace rays
