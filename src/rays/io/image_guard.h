// Checks on image files before they reach the stb_image decoder (Debian's stb_image 2.27), for
// malformed inputs that decoder does not survive. Found by fuzzing (docs/fuzzing.md).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rays {

/// Largest decoded image readImage accepts: 2^28 pixels (as for renders), at most 65536 per side.
inline constexpr uint64_t kMaxImagePixels = uint64_t(1) << 28;
inline constexpr int kMaxImageSide = 65536;

/// Returns "" when the bytes may be handed to stb_image, else why not (a short reason for
/// "cannot read image: <reason>"). Today: a JPEG whose Huffman table (DHT segment) declares more
/// than 256 codes, which overflows stb_image 2.27's tables, and a PPM/PGM header number beyond
/// 2^31 − 1, which overflows its int (both fixed upstream in 2.28); a PNG chunk running past the
/// end of the file, for which stb allocates the declared length (up to 4 GiB) first; a PNG chunk
/// whose CRC does not match (stb does not check them: a damaged file would be decoded as it is).
std::string imageDecoderHazard(const uint8_t* data, size_t size);

/// Removes the zero-length IDAT chunks of a PNG (legal, and empty): stb_image 2.27 copies an empty
/// first IDAT from a null buffer (memcpy(NULL, p, 0), undefined behaviour). Other files are untouched.
void removeEmptyPngData(std::vector<uint8_t>& bytes);

/// Returns "" when a file of `size` bytes can hold a width×height image in its format (told by its
/// signature, as stb_image tells it), else a reason. No complete file packs more pixels per byte
/// than: PNG 8256 (1-bit pixels, deflate's 1032:1), JPEG 512 (one bit per 8×8 block at least),
/// TGA 64 (RLE packets of 128 pixels), BMP 8 (1-bit pixels), PPM/PGM 1; the limits used are twice
/// that. stb_image decodes a truncated file as if the rest were zeros, so a forged header of a few
/// bytes would otherwise make it allocate and fill up to 2^28 pixels.
std::string imageSizeHazard(const uint8_t* data, size_t size, int width, int height);

}  // namespace rays
