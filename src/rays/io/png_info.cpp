#include "rays/io/png_info.h"

#include <cstring>
#include <fstream>

namespace rays {

namespace {

uint32_t be32(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

}  // namespace

PngInfo pngInfoOf(const uint8_t* data, size_t size) {
    static const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    PngInfo info;
    if (size < 8 || std::memcmp(data, kSignature, 8) != 0) return info;
    info.png = true;
    size_t at = 8;
    while (at + 8 <= size) {
        const uint32_t length = be32(data + at);
        const uint8_t* type = data + at + 4;
        const uint8_t* body = data + at + 8;
        if (length > size - at - 8) break;  // a truncated chunk: stop
        if (std::memcmp(type, "IDAT", 4) == 0 || std::memcmp(type, "IEND", 4) == 0) break;
        if (std::memcmp(type, "IHDR", 4) == 0 && length >= 13) {
            info.bitDepth = body[8];
            info.colorType = body[9];
        } else if (std::memcmp(type, "PLTE", 4) == 0) {
            for (uint32_t i = 0; i + 3 <= length; i += 3) info.palette.push_back({body[i], body[i + 1], body[i + 2]});
        } else if (std::memcmp(type, "sRGB", 4) == 0) {
            info.srgb = true;
        } else if (std::memcmp(type, "gAMA", 4) == 0 && length >= 4) {
            const uint32_t g = be32(body);  // the file gamma × 100000 (1/2.2 → 45455)
            if (g > 0) info.gamma = 100000.0 / g;
        }
        at += 12 + size_t(length);
    }
    return info;
}

PngInfo readPngInfo(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    // The header chunks come first; 1 MiB is plenty for IHDR, PLTE, gAMA and sRGB before IDAT.
    std::vector<uint8_t> bytes(1 << 20);
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
    bytes.resize(size_t(in.gcount()));
    return pngInfoOf(bytes.data(), bytes.size());
}

}  // namespace rays
