// Writes the seed corpus of the image fuzzer: small PNG, JPEG, BMP, TGA and PPM/PGM files with 1 to 4
// channels, made by the library's own writer (as the image I/O tests make theirs).
// Usage: make_image_seeds DIR
#include <cstdio>
#include <string>

#include "rays/error.h"
#include "rays/io/image_io.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_image_seeds DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    int written = 0;
    try {
        for (int channels = 1; channels <= 4; ++channels)
            for (const auto& [w, h] : {std::pair{5, 3}, std::pair{16, 9}}) {
                rays::Image8 img(w, h, channels);
                for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = uint8_t(i * 29 + i / 7);
                for (const char* ext : {"png", "jpg", "bmp", "tga", "ppm"}) {
                    const std::string name = dir + "/seed-" + std::to_string(w) + "x" + std::to_string(h) + "-c" +
                                             std::to_string(channels) + "." + ext;
                    rays::writeImage(name, img, 75);
                    ++written;
                }
            }
    } catch (const rays::Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    std::printf("wrote %d seed images to %s\n", written, dir.c_str());
    return 0;
}
