#include "rays/image/image.h"

namespace rays {

Image8 toImage8(const ImageF& img) {
    Image8 out(img.width, img.height, 3);
    toBytes(img.pixels.data(), img.pixels.size(), out.pixels.data());
    return out;
}

void toBytes(const Vec3* pixels, size_t count, uint8_t* rgb) {
    for (size_t i = 0; i < count; ++i) {
        rgb[3 * i + 0] = toByte(pixels[i].x);
        rgb[3 * i + 1] = toByte(pixels[i].y);
        rgb[3 * i + 2] = toByte(pixels[i].z);
    }
}

}  // namespace rays
