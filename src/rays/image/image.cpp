#include "rays/image/image.h"

namespace rays {

Image8 toImage8(const ImageF& img) {
    Image8 out(img.width, img.height, 3);
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        out.pixels[3 * i + 0] = toByte(img.pixels[i].x);
        out.pixels[3 * i + 1] = toByte(img.pixels[i].y);
        out.pixels[3 * i + 2] = toByte(img.pixels[i].z);
    }
    return out;
}

}  // namespace rays
