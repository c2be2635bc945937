#include "rays/io/gif_read.h"

#include <cstring>

#include "rays/error.h"

namespace rays {

namespace {

struct Bytes {
    const uint8_t* data;
    size_t size, at = 0;
    uint8_t byte() {
        if (at >= size) throw Error("the GIF file is truncated");
        return data[at++];
    }
    int word() {  // little-endian 16 bits
        const int lo = byte();
        return lo | byte() << 8;
    }
    void skip(size_t n) {
        if (n > size - at) throw Error("the GIF file is truncated");
        at += n;
    }
};

std::vector<std::array<uint8_t, 3>> colourTable(Bytes& in, int flags) {
    std::vector<std::array<uint8_t, 3>> out;
    if (!(flags & 0x80)) return out;
    const size_t n = size_t(2) << (flags & 7);
    for (size_t i = 0; i < n; ++i) out.push_back({in.byte(), in.byte(), in.byte()});
    return out;
}

// The data sub-blocks (a size byte, then that many bytes, up to a zero size) joined.
std::vector<uint8_t> subBlocks(Bytes& in) {
    std::vector<uint8_t> out;
    for (int n = in.byte(); n != 0; n = in.byte()) {
        const size_t at = in.at;
        in.skip(size_t(n));
        out.insert(out.end(), in.data + at, in.data + at + n);
    }
    return out;
}

// LZW codes → indices (appendix F); stops at the end-of-information code, the data's end or
// when the image is full.
void lzw(const std::vector<uint8_t>& data, int minSize, std::vector<uint8_t>& out, size_t count) {
    if (minSize < 2 || minSize > 11) throw Error("the GIF file's LZW code size is invalid");
    const int clear = 1 << minSize, end = clear + 1;
    static constexpr int kMax = 4096;
    std::vector<uint16_t> prefix(kMax);
    std::vector<uint8_t> suffix(kMax), first(kMax), stack(kMax + 1);
    for (int i = 0; i < clear; ++i) suffix[size_t(i)] = first[size_t(i)] = uint8_t(i);
    int size = minSize + 1, next = clear + 2, prev = -1;
    size_t bitPos = 0;
    const size_t bits = data.size() * 8;
    out.clear();
    out.reserve(count);
    while (out.size() < count && bitPos + size_t(size) <= bits) {
        int code = 0;
        for (int b = 0; b < size; ++b, ++bitPos) code |= ((data[bitPos >> 3] >> (bitPos & 7)) & 1) << b;
        if (code == clear) {
            size = minSize + 1;
            next = clear + 2;
            prev = -1;
            continue;
        }
        if (code == end) break;
        if (code > next || (prev < 0 && code >= clear)) throw Error("the GIF file's image data is corrupt");
        // The string of `code` (or, for the code about to be made, prev's string and its first index).
        int c = code == next ? prev : code;
        size_t depth = 0;
        if (code == next) stack[depth++] = first[size_t(prev)];
        while (c >= clear) {
            stack[depth++] = suffix[size_t(c)];
            c = prefix[size_t(c)];
        }
        stack[depth++] = uint8_t(c);
        while (depth > 0 && out.size() < count) out.push_back(stack[--depth]);
        if (prev >= 0 && next < kMax) {
            prefix[size_t(next)] = uint16_t(prev);
            suffix[size_t(next)] = uint8_t(c);  // the first index of code's string
            first[size_t(next)] = first[size_t(prev)];
            ++next;
            if (next == (1 << size) && size < 12) ++size;
        }
        prev = code;
    }
    out.resize(count, 0);
}

}  // namespace

bool isGif(const uint8_t* data, size_t size) {
    return size >= 6 && (std::memcmp(data, "GIF87a", 6) == 0 || std::memcmp(data, "GIF89a", 6) == 0);
}

GifImage decodeGif(const uint8_t* data, size_t size, size_t maxPixels) {
    if (!isGif(data, size)) throw Error("not a GIF file");
    Bytes in{data, size};
    in.skip(6);
    in.word();
    in.word();
    const int screenFlags = in.byte();
    in.skip(2);
    const auto global = colourTable(in, screenFlags);
    for (;;) {
        const int block = in.byte();
        if (block == 0x3B) throw Error("the GIF file holds no image");
        if (block == 0x21) {  // an extension: its label, then sub-blocks
            in.byte();
            subBlocks(in);
            continue;
        }
        if (block != 0x2C) throw Error("the GIF file is corrupt");
        GifImage img;
        in.word();
        in.word();
        img.width = in.word();
        img.height = in.word();
        const int flags = in.byte();
        const auto local = colourTable(in, flags);
        img.palette = local.empty() ? global : local;
        const size_t count = size_t(img.width) * size_t(img.height);
        if (img.width <= 0 || img.height <= 0 || count > maxPixels) throw Error("the GIF image's size is invalid");
        const int minSize = in.byte();
        std::vector<uint8_t> raw;
        lzw(subBlocks(in), minSize, raw, count);
        if (!(flags & 0x40)) {
            img.indices = std::move(raw);
            return img;
        }
        // Interlaced: rows 0, 8, 16 ..., then 4, 12 ..., then 2, 6 ..., then 1, 3 ...
        img.indices.resize(count);
        size_t row = 0;
        const int starts[4] = {0, 4, 2, 1}, steps[4] = {8, 8, 4, 2};
        for (int pass = 0; pass < 4; ++pass)
            for (int y = starts[pass]; y < img.height; y += steps[pass], ++row)
                std::memcpy(img.indices.data() + size_t(y) * size_t(img.width),
                            raw.data() + row * size_t(img.width), size_t(img.width));
        return img;
    }
}

}  // namespace rays
