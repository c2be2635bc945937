// Image files: encode/write 8-bit images as PNG, JPEG, PPM/PGM, TGA or BMP (chosen by extension) and
// read PNG, JPEG, BMP, TGA and PPM/PGM. Failures throw rays::Error ("PATH: error: ...").
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "rays/image/image.h"

namespace rays {

/// True when path ends in a supported output extension (.png .jpg .jpeg .ppm .tga .bmp, case-insensitive).
bool isSupportedImageExtension(const std::string& path);

/// Writes img (1..4 channels, top row first) to path, format by extension. Atomic: the data goes to a
/// temporary file in the same directory (path + ".tmp.<pid>.<counter>") which is renamed over path only
/// when complete; on any failure the temporary is removed and rays::Error "PATH: error: ..." is thrown.
/// Channels a format cannot store are dropped (JPEG and PPM drop alpha; BMP stores grey as RGB).
void writeImage(const std::string& path, const Image8& img, int jpegQuality = 90);

/// Encodes img to memory in the format named by extension ("png", ".png", "out.PNG" all work).
/// Throws rays::Error "error: ..." for an unknown extension, an invalid image or an encoder failure.
std::vector<uint8_t> encodeImage(const std::string& extension, const Image8& img, int jpegQuality = 90);

/// The zlib strategy (Z_RLE or Z_FILTERED) the PNG encoder uses for img: Z_RLE unless Z_FILTERED
/// compresses a sample of the image's rows much better (clean synthetic images). Exposed for tests.
int pngZlibStrategy(const Image8& img);

/// Reads PNG, JPEG, BMP, TGA or binary PPM/PGM, keeping the file's channel count (1..4; 16-bit files are
/// reduced to 8 bits). Throws rays::Error "PATH: error: cannot read image: <reason>".
Image8 readImage(const std::string& path);

}  // namespace rays
