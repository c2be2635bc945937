// Tiny palette images written by hand for tests: a palette PNG of 1, 2, 4 or 8 bits an index (PNG
// specification: IHDR colour type 3, PLTE, one zlib stream of filter-0 rows) and a GIF whose LZW
// stream sends a clear code before every index, so its codes stay 9 bits wide (GIF89a, appendix F).
#pragma once
#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace rays::test {

inline void writeBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return;
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
}

using Palette = std::vector<std::array<uint8_t, 3>>;

// A chunk written after IHDR (gAMA, sRGB): its four-letter type and its body.
struct PngChunk {
    std::string type;
    std::vector<uint8_t> body;
};

// A PNG of filter-0 rows `raw` (each row's filter byte first) with the given IHDR bit depth and
// colour type, the `extra` chunks, and a PLTE chunk when `plte` is not empty.
inline std::vector<uint8_t> pngBytes(int w, int h, int bitDepth, int colorType, const std::vector<uint8_t>& raw,
                                     const std::vector<uint8_t>& plte = {}, const std::vector<PngChunk>& extra = {}) {
    uLongf size = compressBound(uLong(raw.size()));
    std::vector<uint8_t> z(size);
    compress(z.data(), &size, raw.data(), uLong(raw.size()));
    z.resize(size);
    std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    auto chunk = [&](const char* type, const std::vector<uint8_t>& body) {
        const uint32_t n = uint32_t(body.size());
        for (int s = 24; s >= 0; s -= 8) out.push_back(uint8_t(n >> s));
        std::vector<uint8_t> tb(type, type + 4);
        tb.insert(tb.end(), body.begin(), body.end());
        out.insert(out.end(), tb.begin(), tb.end());
        const uint32_t crc = uint32_t(crc32(0, tb.data(), uInt(tb.size())));
        for (int s = 24; s >= 0; s -= 8) out.push_back(uint8_t(crc >> s));
    };
    chunk("IHDR", {uint8_t(w >> 24), uint8_t(w >> 16), uint8_t(w >> 8), uint8_t(w), uint8_t(h >> 24), uint8_t(h >> 16),
                   uint8_t(h >> 8), uint8_t(h), uint8_t(bitDepth), uint8_t(colorType), 0, 0, 0});
    for (const PngChunk& c : extra) chunk(c.type.c_str(), c.body);
    if (!plte.empty()) chunk("PLTE", plte);
    chunk("IDAT", z);
    chunk("IEND", {});
    return out;
}

inline void writePalettePng(const std::string& path, int w, int h, const std::vector<uint8_t>& indices,
                            const Palette& palette, int bitDepth = 8) {
    std::vector<uint8_t> raw;
    const int rowBytes = (w * bitDepth + 7) / 8;
    for (int y = 0; y < h; ++y) {
        raw.push_back(0);
        std::vector<uint8_t> row(size_t(rowBytes), 0);
        for (int x = 0; x < w; ++x) {
            const int bit = x * bitDepth;
            row[size_t(bit / 8)] |= uint8_t(indices[size_t(y * w + x)] << (8 - bitDepth - bit % 8));
        }
        raw.insert(raw.end(), row.begin(), row.end());
    }
    std::vector<uint8_t> plte;
    for (const auto& c : palette) plte.insert(plte.end(), c.begin(), c.end());
    writeBytes(path, pngBytes(w, h, bitDepth, 3, raw, plte));
}

inline void writeGif(const std::string& path, int w, int h, const std::vector<uint8_t>& indices, Palette palette) {
    palette.resize(256);
    std::vector<uint8_t> out = {'G', 'I', 'F', '8', '9', 'a', uint8_t(w), uint8_t(w >> 8), uint8_t(h), uint8_t(h >> 8),
                                0xF7, 0, 0};
    for (const auto& c : palette) out.insert(out.end(), c.begin(), c.end());
    out.insert(out.end(), {0x2C, 0, 0, 0, 0, uint8_t(w), uint8_t(w >> 8), uint8_t(h), uint8_t(h >> 8), 0, 8});
    std::vector<uint8_t> codes;
    uint32_t acc = 0;
    int bits = 0;
    auto put = [&](int code) {
        acc |= uint32_t(code) << bits;
        bits += 9;
        while (bits >= 8) {
            codes.push_back(uint8_t(acc));
            acc >>= 8;
            bits -= 8;
        }
    };
    for (uint8_t i : indices) {
        put(256);  // clear: the table never grows
        put(i);
    }
    put(257);
    if (bits > 0) codes.push_back(uint8_t(acc));
    for (size_t at = 0; at < codes.size(); at += 255) {
        const size_t n = std::min<size_t>(255, codes.size() - at);
        out.push_back(uint8_t(n));
        out.insert(out.end(), codes.begin() + long(at), codes.begin() + long(at + n));
    }
    out.push_back(0);
    out.push_back(0x3B);
    writeBytes(path, out);
}

}  // namespace rays::test
