// Image files: encode/write 8-bit images as PNG, JPEG, PPM/PGM, TGA or BMP (chosen by extension) and
// read PNG, JPEG, BMP, TGA and PPM/PGM. Failures throw rays::Error ("PATH: error: ...").
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rays/image/image.h"

namespace rays {

/// True when path ends in a supported output extension (.png .jpg .jpeg .ppm .tga .bmp, case-insensitive).
bool isSupportedImageExtension(const std::string& path);
/// True when path ends in .png (case-insensitive).
bool isPngPath(const std::string& path);

/// Writes img (1..4 channels, top row first) to path, format by extension. Atomic: the data goes to a
/// temporary file in the same directory (path + ".tmp.<pid>.<counter>") which is renamed over path only
/// when complete; on any failure the temporary is removed and rays::Error "PATH: error: ..." is thrown.
/// Channels a format cannot store are dropped (JPEG and PPM drop alpha; BMP stores grey as RGB).
void writeImage(const std::string& path, const Image8& img, int jpegQuality = 90);

/// The bytes writeImage(path, img, jpegQuality) writes (format by path's extension); throws rays::Error
/// "PATH: error: ..." as writeImage does. For a run that commits several files together (OutputFiles).
std::vector<uint8_t> encodeImageFile(const std::string& path, const Image8& img, int jpegQuality = 90);

/// Encodes img to memory in the format named by extension ("png", ".png", "out.PNG" all work).
/// Throws rays::Error "error: ..." for an unknown extension, an invalid image or an encoder failure.
std::vector<uint8_t> encodeImage(const std::string& extension, const Image8& img, int jpegQuality = 90);

/// The zlib strategy (Z_RLE or Z_FILTERED) the PNG encoder uses for img: Z_RLE unless Z_FILTERED
/// compresses a sample of the image's rows much better (clean synthetic images). Reads only rows
/// up to pngStrategyLastRow(img.height), so a caller can pick it before the rest of the image exists.
int pngZlibStrategy(const Image8& img);
int pngStrategyLastRow(int height);

/// Writes data to path atomically, as writeImage does (temporary file in the same directory, renamed
/// over path when complete; on failure removed, and rays::Error "PATH: error: ..." thrown). A file
/// replaced keeps its permission bits (OutputFiles, which commits several files together).
void writeFileAtomically(const std::string& path, const std::vector<uint8_t>& data);

/// PNG encoding row by row, top row first, into memory: the bytes encodeImage("png", img) gives when
/// constructed with pngZlibStrategy(img) and handed img's rows in order. Lets a caller compress rows
/// while the rest of the image is still being made. Errors throw rays::Error ("error: PNG encoder: ...").
class PngRowEncoder {
public:
    /// bitDepth 8 or 16 (16: each sample a uint16_t in the host's byte order; the file has them
    /// most significant byte first, as PNG stores them).
    PngRowEncoder(int width, int height, int channels, int zlibStrategy, int bitDepth = 8);
    ~PngRowEncoder();
    PngRowEncoder(const PngRowEncoder&) = delete;
    PngRowEncoder& operator=(const PngRowEncoder&) = delete;

    /// The next row: width * channels samples of bitDepth / 8 bytes.
    void row(const uint8_t* pixels);
    /// The PNG file's bytes; every row must have been given.
    std::vector<uint8_t> finish();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// img as an RGB PNG of 16 bits per channel: each value c clamped to [0, 1] and rounded to
/// c·65535 (POV-Ray's Bits_Per_Color=16, +FN16). Throws rays::Error "error: PNG encoder: ...".
std::vector<uint8_t> encodePng16(const ImageF& img);

/// Reads PNG, JPEG, BMP, TGA or binary PPM/PGM, keeping the file's channel count (1..4; 16-bit files are
/// reduced to 8 bits). Throws rays::Error "PATH: error: cannot read image: <reason>".
Image8 readImage(const std::string& path);

}  // namespace rays
