#include "rays/io/image_guard.h"

#include <zlib.h>

#include <cstring>

namespace rays {
namespace {

int be16(const uint8_t* p) { return (int(p[0]) << 8) | int(p[1]); }
uint32_t be32(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

// The tables of one DHT segment (payload of `length` bytes at p), read exactly as stb_image reads
// them: while payload is left, a class/id byte, 16 code counts and that many symbols, taken from the
// stream (past the segment, and as zeros past the end of the file, when the segment is short).
// Returns false when a table declares more than 256 codes (stb stores them in 257-entry arrays
// without checking).
bool dhtTablesFit(const uint8_t* p, long length, const uint8_t* fileEnd) {
    auto byteAt = [&](const uint8_t* q) { return q < fileEnd ? int(*q) : 0; };
    while (length > 0) {
        const int q = byteAt(p);
        if ((q >> 4) > 1 || (q & 15) > 3) return true;  // stb rejects the header first
        int n = 0;
        for (int i = 1; i <= 16; ++i) n += byteAt(p + i);
        if (n > 256) return false;
        p += 17 + n;
        length -= 17 + n;
        if (p >= fileEnd) break;
    }
    return true;
}

// Walks the marker segments of a JPEG the way stb_image finds them, but more permissively (it
// resynchronises on any 0xFF and skips restart markers and stuffed bytes), so that every DHT segment
// stb could process is seen. Returns false at the first DHT with an oversized table.
bool jpegHuffmanTablesFit(const uint8_t* p, const uint8_t* end) {
    while (p < end) {
        if (*p != 0xFF) {
            ++p;
            continue;
        }
        while (p < end && *p == 0xFF) ++p;  // fill bytes
        if (p >= end) break;
        const uint8_t m = *p++;
        if (m == 0x00 || (m >= 0xD0 && m <= 0xD7) || m == 0x01) continue;  // stuffing, RSTn, TEM
        if (m == 0xD8 || m == 0xD9) continue;  // SOI, EOI
        if (end - p < 2) break;
        const int length = be16(p);
        if (length < 2) continue;
        const uint8_t* segEnd = end - p < length ? end : p + length;
        if (m == 0xC4 && !dhtTablesFit(p + 2, length - 2, end)) return false;
        p = segEnd;  // after SOS the entropy-coded bytes follow: skipped byte by byte above
    }
    return true;
}

// The width, height and maximum value of a binary PPM/PGM header, read as stb_image reads them
// (whitespace and '#' comments between them). stb_image 2.27 accumulates each in an int without an
// overflow check; returns false when one would overflow.
bool pnmHeaderNumbersFit(const uint8_t* p, const uint8_t* end) {
    auto isSpace = [](uint8_t c) { return c == ' ' || (c >= '\t' && c <= '\r'); };
    for (int field = 0; field < 3; ++field) {
        for (;;) {
            while (p < end && isSpace(*p)) ++p;
            if (p >= end || *p != '#') break;
            while (p < end && *p != '\n' && *p != '\r') ++p;
        }
        int64_t value = 0;
        while (p < end && *p >= '0' && *p <= '9') {
            value = value * 10 + (*p++ - '0');
            if (value > INT32_MAX) return false;
        }
    }
    return true;
}

// The chunks of a PNG up to IEND must lie inside the file. stb_image 2.27 grows its IDAT buffer to
// the declared chunk length before reading it, so a few bytes declaring a 2 GiB chunk made it
// allocate 2 GiB (found by fuzzing). A chunk running past the end fails in stb anyway.
bool pngChunksFit(const uint8_t* data, size_t size) {
    size_t pos = 8;
    while (size - pos >= 8) {
        const uint8_t* c = data + pos;
        const uint32_t length = uint32_t(c[0]) << 24 | uint32_t(c[1]) << 16 | uint32_t(c[2]) << 8 | c[3];
        if (std::memcmp(c + 4, "IEND", 4) == 0) break;
        if (length > size - pos - 8) return false;
        pos += 8 + size_t(length) + 4;
        if (pos > size) break;
    }
    return true;
}

// The first chunk (up to IEND) whose CRC does not match its type and data, or "" when all do.
// stb_image does not check CRCs, so a damaged file would otherwise be decoded as it stands.
std::string pngChunkWithBadCrc(const uint8_t* data, size_t size) {
    size_t pos = 8;
    while (size - pos >= 12) {
        const uint8_t* c = data + pos;
        const uint32_t length = be32(c);
        if (length > size - pos - 12) break;  // pngChunksFit reports it
        const uint32_t stored = be32(c + 8 + length);
        if (uint32_t(crc32(crc32(0L, Z_NULL, 0), c + 4, uInt(length) + 4)) != stored)
            return std::string(reinterpret_cast<const char*>(c + 4), 4);
        if (std::memcmp(c + 4, "IEND", 4) == 0) break;
        pos += 12 + size_t(length);
    }
    return {};
}

}  // namespace

std::string imageDecoderHazard(const uint8_t* data, size_t size) {
    // stb_image takes any 0xFF, further 0xFF fill bytes and 0xD8 (SOI) at the start as a JPEG.
    size_t i = 0;
    while (i < size && data[i] == 0xFF) ++i;
    if (i >= 1 && i < size && data[i] == 0xD8 && !jpegHuffmanTablesFit(data + i + 1, data + size))
        return "corrupt JPEG (Huffman table with more than 256 codes)";
    if (size >= 8 && std::memcmp(data, "\x89PNG\r\n\x1a\n", 8) == 0) {
        if (!pngChunksFit(data, size)) return "corrupt PNG (a chunk runs past the end of the file)";
        if (const std::string chunk = pngChunkWithBadCrc(data, size); !chunk.empty())
            return "corrupt PNG (the CRC of a chunk '" + chunk + "' does not match its data)";
    }
    if (size >= 2 && data[0] == 'P' && (data[1] == '5' || data[1] == '6') && !pnmHeaderNumbersFit(data + 2, data + size))
        return "corrupt PPM/PGM header (number too large)";
    return {};
}

void removeEmptyPngData(std::vector<uint8_t>& bytes) {
    static const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0) return;
    size_t pos = 8;  // chunks: 4-byte length, 4-byte type, data, 4-byte CRC (stb does not check it)
    while (bytes.size() - pos >= 12) {
        const uint8_t* c = bytes.data() + pos;
        const uint32_t length = uint32_t(c[0]) << 24 | uint32_t(c[1]) << 16 | uint32_t(c[2]) << 8 | c[3];
        if (length == 0 && std::memcmp(c + 4, "IDAT", 4) == 0) {
            bytes.erase(bytes.begin() + long(pos), bytes.begin() + long(pos + 12));
            continue;
        }
        if (length > bytes.size() - pos - 12) break;
        pos += 12 + size_t(length);
    }
}

std::string imageSizeHazard(const uint8_t* data, size_t size, int width, int height) {
    auto starts = [&](const char* sig, size_t n) { return size >= n && std::memcmp(data, sig, n) == 0; };
    size_t ff = 0;
    while (ff < size && data[ff] == 0xFF) ++ff;
    uint64_t perByte = 128;  // TGA: stb's fallback when no signature matches
    if (starts("\x89PNG\r\n\x1a\n", 8)) perByte = 16512;
    else if (starts("BM", 2)) perByte = 16;
    else if (ff >= 1 && ff < size && data[ff] == 0xD8) perByte = 1024;
    else if (starts("P5", 2) || starts("P6", 2)) perByte = 2;
    const uint64_t pixels = uint64_t(width > 0 ? width : 0) * uint64_t(height > 0 ? height : 0);
    if (pixels > perByte * uint64_t(size))
        return "file of " + std::to_string(size) + " bytes is too small for a " + std::to_string(width) + "x" +
               std::to_string(height) + " image (truncated or corrupt)";
    return {};
}

}  // namespace rays
