#include "rays/io/png_info.h"

#include <cstring>
#include <fstream>
#include <memory>

#include <spng.h>

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

bool readPngSamples(const std::string& path, PngSamples& out, bool packedPalettes) {
    const PngInfo info = readPngInfo(path);
    if (!info.png) return false;
    const bool packed = packedPalettes && info.colorType == 3 && info.bitDepth < 8;
    if (!packed && info.bitDepth != 8 && info.bitDepth != 16) return false;
    if (info.colorType != 0 && info.colorType != 3 && info.colorType != 4) return false;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return false;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(f, std::fclose);
    std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> ctx{spng_ctx_new(0), spng_ctx_free};
    if (!ctx || spng_set_png_file(ctx.get(), f) != 0) return false;
    // The same limits readImage keeps (image_io).
    spng_set_image_limits(ctx.get(), 65536, 65536);
    spng_set_chunk_limits(ctx.get(), 1 << 26, 1 << 28);
    spng_ihdr ihdr{};
    if (spng_get_ihdr(ctx.get(), &ihdr) != 0) return false;
    if (uint64_t(ihdr.width) * ihdr.height > (uint64_t(1) << 28)) return false;
    size_t size = 0;
    if (spng_decoded_image_size(ctx.get(), SPNG_FMT_RAW, &size) != 0) return false;
    std::vector<uint8_t> raw(size);
    if (spng_decode_image(ctx.get(), raw.data(), size, SPNG_FMT_RAW, 0) != 0) return false;
    const size_t n = size_t(ihdr.width) * ihdr.height;
    if (packed) {  // 1, 2 or 4 bits an index, the leftmost pixel in the high bits, rows byte-aligned
        const size_t depth = ihdr.bit_depth, rowBytes = (size_t(ihdr.width) * depth + 7) / 8;
        if (raw.size() < rowBytes * ihdr.height) return false;
        out.width = int(ihdr.width);
        out.height = int(ihdr.height);
        out.maxValue = 255;
        out.samples.resize(n);
        for (size_t y = 0; y < ihdr.height; ++y)
            for (size_t x = 0; x < ihdr.width; ++x) {
                const size_t bit = x * depth;
                const uint8_t b = raw[y * rowBytes + bit / 8];
                out.samples[y * ihdr.width + x] = uint16_t((b >> (8 - depth - bit % 8)) & ((1u << depth) - 1));
            }
        return true;
    }
    const size_t bytes = ihdr.bit_depth / 8, perPixel = bytes * (ihdr.color_type == 4 ? 2 : 1);
    if (raw.size() < n * perPixel) return false;
    out.width = int(ihdr.width);
    out.height = int(ihdr.height);
    out.maxValue = ihdr.bit_depth == 16 ? 65535 : 255;
    out.samples.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* p = raw.data() + i * perPixel;
        out.samples[i] = bytes == 2 ? uint16_t(p[0] << 8 | p[1]) : p[0];  // SPNG_FMT_RAW: big-endian
    }
    return true;
}

}  // namespace rays
