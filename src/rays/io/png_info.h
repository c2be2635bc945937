// The chunks of a PNG file that say how to read its values (PNG specification, 11.2.3 PLTE,
// 11.3.3.2 gAMA, 11.3.3.5 sRGB, 11.2.2 IHDR): the palette, the encoding gamma and the bit depth,
// for POV-Ray's image maps (palette-index filter/transmit, file gamma) and height fields.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rays {

struct PngInfo {
    bool png = false;  ///< the file is a PNG (the rest is meaningful)
    int bitDepth = 8, colorType = 0;
    std::vector<std::array<uint8_t, 3>> palette;  ///< PLTE entries
    bool srgb = false;                            ///< an sRGB chunk
    double gamma = 0;                             ///< gAMA's decoding exponent (1 / file gamma); 0 without
};

/// The PngInfo of the file at path; png false for a file that is not a PNG or cannot be read.
/// Reads chunks up to the first IDAT only.
PngInfo readPngInfo(const std::string& path);

/// The PngInfo of a PNG file's bytes (as readPngInfo).
PngInfo pngInfoOf(const uint8_t* data, size_t size);

/// One sample per pixel as the file stores it, top row first: the palette index of a palette
/// image, the grey of a grey image (alpha dropped); 8- or 16-bit (maxValue 255 or 65535).
struct PngSamples {
    int width = 0, height = 0;
    int maxValue = 255;
    std::vector<uint16_t> samples;
};

/// The samples of a PNG file of colour type grey, grey + alpha or palette with 8- or 16-bit
/// samples, and with packedPalettes palette images of 1, 2 or 4 bits too (maxValue 255); false for
/// other files (colour images, 1–4 bit samples, not a PNG, unreadable).
bool readPngSamples(const std::string& path, PngSamples& out, bool packedPalettes = false);

}  // namespace rays
