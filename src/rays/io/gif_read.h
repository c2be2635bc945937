// GIF files (the GIF89a specification, W3C/CompuServe 1990; GIF87a is its subset): the first image's
// palette indices and its colour table (local, else global). LZW decoding as the specification's
// appendix F describes it: variable-width codes from the minimum code size + 1 up to 12 bits, read
// least significant bit first, clear and end-of-information codes; interlaced rows put back in order.
// POV-Ray reads GIFs for image maps, height fields and Fractint's pot files.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rays {

struct GifImage {
    int width = 0, height = 0;
    std::vector<uint8_t> indices;                 ///< width × height, top row first
    std::vector<std::array<uint8_t, 3>> palette;  ///< the image's colour table
};

/// True when the bytes start as a GIF file ("GIF87a" or "GIF89a").
bool isGif(const uint8_t* data, size_t size);

/// The first image of a GIF file's bytes; throws Error "WHY" (no place: the caller adds it) when the
/// file is truncated or corrupt, or larger than maxPixels.
GifImage decodeGif(const uint8_t* data, size_t size, size_t maxPixels = size_t(1) << 28);

}  // namespace rays
