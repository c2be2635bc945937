// High-dynamic-range image files: OpenEXR (named float or half channels, through OpenEXR's C
// library OpenEXRCore when the build found it) and PFM (1 or 3 float channels). Atomic as the
// 8-bit writers (image_io.h): no partial file is left behind on failure. Docs: docs/aov.md.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace rays {

/// One named channel of an HdrImage: width × height floats, top row first.
struct HdrChannel {
    std::string name;   ///< EXR channel name ("R", "Z", "N.X", ...)
    bool half = false;  ///< EXR: stored as 16-bit half (else 32-bit float); PFM always float
    std::vector<float> values;
};

/// A float image of any number of named channels (planar), top row first.
struct HdrImage {
    int width = 0, height = 0;
    std::vector<HdrChannel> channels;

    HdrImage() = default;
    HdrImage(int w, int h) : width(w), height(h) {}
    /// Appends a channel of zeros and returns it.
    HdrChannel& add(const std::string& name, bool half = false);
    /// The channel called name, or nullptr.
    const HdrChannel* find(const std::string& name) const;
};

/// True when path ends in .exr (case-insensitive).
bool isExrPath(const std::string& path);
/// True when path ends in .pfm (case-insensitive).
bool isPfmPath(const std::string& path);
/// True when this build can write OpenEXR files (it found OpenEXR at configure time).
bool exrAvailable();

/// The EXR file's bytes: one scanline part, ZIP compression, channels as given (EXR stores them
/// sorted by name). Throws rays::Error "error: ..." (also "built without OpenEXR").
std::vector<uint8_t> encodeExr(const HdrImage& img);
/// The PFM file's bytes: "PF" for 3 channels (taken in order as R, G, B), "Pf" for 1; rows bottom
/// first, little-endian floats (scale −1). Throws rays::Error "error: ..." for other channel counts.
std::vector<uint8_t> encodePfm(const HdrImage& img);

/// The bytes of img as EXR or PFM, by path's extension. Throws rays::Error "PATH: error: ...".
std::vector<uint8_t> encodeHdrImage(const std::string& path, const HdrImage& img);

/// Writes img as EXR or PFM, by path's extension, atomically (writeFileAtomically). Throws
/// rays::Error "PATH: error: ...".
void writeHdrImage(const std::string& path, const HdrImage& img);

/// IEEE 754 binary16 bits of f, rounded to nearest even (overflow to infinity).
uint16_t floatToHalf(float f);

}  // namespace rays
