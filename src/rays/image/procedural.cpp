#include "rays/image/procedural.h"

#include <algorithm>
#include <cmath>

namespace rays {
namespace {

// Distance (in pixels) from (x, y) to the nearest mortar line of a running-bond brick wall,
// and the brick's index for colour variation.
double mortarDistance(int x, int y, int w, int h, int rows, int& brick) {
    const double courseH = double(h) / rows;
    const int course = std::min(rows - 1, int(y / courseH));
    const double brickW = courseH * 2.0;
    const double shift = (course % 2) * brickW / 2;
    const double bx = (x + shift) / brickW;
    const int col = int(std::floor(bx));
    brick = course * 1000 + col;
    const double dy = std::min(y - course * courseH, (course + 1) * courseH - y);
    const double dx = std::min((bx - col) * brickW, (col + 1 - bx) * brickW);
    (void)w;
    return std::min(dx, dy);
}

}  // namespace

Image8 checkerImage(int size, int n, const uint8_t a[3], const uint8_t b[3]) {
    Image8 img(size, size, 3);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const bool odd = ((x * n / size) + (y * n / size)) % 2;
            for (int c = 0; c < 3; ++c) img.row(y)[x * 3 + c] = odd ? b[c] : a[c];
        }
    return img;
}

Image8 brickHeightImage(int w, int h, int rows) {
    Image8 img(w, h, 1);
    const double mortar = double(h) / rows * 0.08, bevel = double(h) / rows * 0.12;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int brick;
            const double d = mortarDistance(x, y, w, h, rows, brick);
            const double t = std::clamp((d - mortar) / bevel, 0.0, 1.0);
            img.row(y)[x] = uint8_t(std::lround(255 * t * t * (3 - 2 * t)));
        }
    return img;
}

Image8 brickColorImage(int w, int h, int rows) {
    Image8 img(w, h, 3);
    const double mortar = double(h) / rows * 0.08;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int brick;
            const double d = mortarDistance(x, y, w, h, rows, brick);
            uint8_t* p = img.row(y) + x * 3;
            if (d < mortar) {
                p[0] = p[1] = p[2] = 170;
            } else {
                const unsigned hash = unsigned(brick) * 2654435761u;
                const int v = int(hash >> 27) - 16;  // −16..15
                p[0] = uint8_t(std::clamp(165 + v, 0, 255));
                p[1] = uint8_t(std::clamp(70 + v / 2, 0, 255));
                p[2] = uint8_t(std::clamp(50 + v / 2, 0, 255));
            }
        }
    return img;
}

Image8 normalMapFromHeight(const Image8& height, double strength) {
    Image8 out(height.width, height.height, 3);
    auto hAt = [&](int x, int y) {
        x = (x + height.width) % height.width;
        y = (y + height.height) % height.height;
        return height.row(y)[x * height.channels] / 255.0;
    };
    for (int y = 0; y < height.height; ++y)
        for (int x = 0; x < height.width; ++x) {
            // +v runs up the image, rows run down: the v slope is h(above) − h(below).
            const double du = (hAt(x + 1, y) - hAt(x - 1, y)) * 0.5 * strength;
            const double dv = (hAt(x, y - 1) - hAt(x, y + 1)) * 0.5 * strength;
            const double len = std::sqrt(du * du + dv * dv + 1);
            const double n[3] = {-du / len, -dv / len, 1 / len};
            for (int c = 0; c < 3; ++c)
                out.row(y)[x * 3 + c] = uint8_t(std::clamp(std::lround(n[c] * 127 + 128), 0L, 255L));
        }
    return out;
}

}  // namespace rays
