#include "rays/io/hdr_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "rays/error.h"
#include "rays/io/image_io.h"

#ifndef RAYS_HAVE_OPENEXR  // set for this file by CMakeLists.txt when OpenEXR was found
#define RAYS_HAVE_OPENEXR 0
#endif
#if RAYS_HAVE_OPENEXR
#include <OpenEXR/openexr.h>
#endif

namespace rays {
namespace {

bool endsWithNoCase(const std::string& s, const char* suffix) {
    const size_t n = std::strlen(suffix);
    if (s.size() < n) return false;
    for (size_t i = 0; i < n; ++i) {
        char c = s[s.size() - n + i];
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
        if (c != suffix[i]) return false;
    }
    return true;
}

void checkShape(const HdrImage& img) {
    if (img.width <= 0 || img.height <= 0 || img.channels.empty())
        throw Error("error: invalid HDR image (" + std::to_string(img.width) + "x" + std::to_string(img.height) +
                    ", " + std::to_string(img.channels.size()) + " channels)");
    for (const HdrChannel& c : img.channels)
        if (c.values.size() != size_t(img.width) * size_t(img.height))
            throw Error("error: HDR channel '" + c.name + "' has the wrong size");
}

#if RAYS_HAVE_OPENEXR
// The EXR bytes go to memory (written at the offsets the library asks for), then to the file
// atomically.
struct MemoryStream {
    std::vector<uint8_t> bytes;
};

int64_t writeToMemory(exr_const_context_t, void* user, const void* buffer, uint64_t size, uint64_t offset,
                      exr_stream_error_func_ptr_t) {
    auto* m = static_cast<MemoryStream*>(user);
    if (m->bytes.size() < offset + size) m->bytes.resize(offset + size);
    std::memcpy(m->bytes.data() + offset, buffer, size);
    return int64_t(size);
}

void quietErrors(exr_const_context_t, exr_result_t, const char*) {}

void check(exr_result_t r, const char* what) {
    if (r != EXR_ERR_SUCCESS)
        throw Error(std::string("error: OpenEXR: ") + what + ": " + exr_get_default_error_message(r));
}

// Owns the write context: exr_finish on every path out.
struct WriteContext {
    exr_context_t ctx = nullptr;
    ~WriteContext() {
        if (ctx) exr_finish(&ctx);
    }
};
#endif

}  // namespace

HdrChannel& HdrImage::add(const std::string& name, bool half) {
    channels.push_back(HdrChannel{name, half, std::vector<float>(size_t(width) * size_t(height), 0.0f)});
    return channels.back();
}

const HdrChannel* HdrImage::find(const std::string& name) const {
    for (const HdrChannel& c : channels)
        if (c.name == name) return &c;
    return nullptr;
}

bool isExrPath(const std::string& path) { return endsWithNoCase(path, ".exr"); }
bool isPfmPath(const std::string& path) { return endsWithNoCase(path, ".pfm"); }

bool exrAvailable() { return RAYS_HAVE_OPENEXR != 0; }

uint16_t floatToHalf(float f) {
    uint32_t x;
    std::memcpy(&x, &f, 4);
    const uint32_t sign = (x >> 16) & 0x8000u;
    const uint32_t a = x & 0x7fffffffu;
    if (a >= 0x7f800000u) return uint16_t(sign | 0x7c00u | (a > 0x7f800000u ? 0x200u : 0u));  // inf, NaN
    if (a < 0x38800000u) {
        // Below 2^-14: a subnormal half, in units of 2^-24 (the scaling is exact; nearbyint rounds
        // to nearest even). 1024 units is the smallest normal, whose bits are the same number.
        float mag;
        std::memcpy(&mag, &a, 4);
        return uint16_t(sign | uint32_t(std::nearbyint(mag * 16777216.0f)));
    }
    // Rebias the exponent (127 → 15), keep 10 mantissa bits, round the 13 dropped to nearest even;
    // a carry moves into the exponent, up to infinity.
    uint32_t h = (a >> 13) - (112u << 10);
    const uint32_t rest = a & 0x1fffu;
    if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) ++h;
    return uint16_t(sign | std::min(h, 0x7c00u));
}

std::vector<uint8_t> encodeExr(const HdrImage& img) {
    checkShape(img);
#if !RAYS_HAVE_OPENEXR
    throw Error("error: cannot write EXR: this Rays was built without OpenEXR (install libopenexr-dev and rebuild)");
#else
    MemoryStream out;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &out;
    init.write_fn = &writeToMemory;
    init.error_handler_fn = &quietErrors;
    WriteContext w;
    check(exr_start_write(&w.ctx, "memory", EXR_WRITE_FILE_DIRECTLY, &init), "start");
    int part = 0;
    check(exr_add_part(w.ctx, "rays", EXR_STORAGE_SCANLINE, &part), "add part");
    check(exr_initialize_required_attr_simple(w.ctx, part, img.width, img.height, EXR_COMPRESSION_ZIP), "header");
    for (const HdrChannel& c : img.channels)
        check(exr_result_t(exr_add_channel(w.ctx, part, c.name.c_str(), c.half ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT,
                                           EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1)),
              ("channel " + c.name).c_str());
    check(exr_write_header(w.ctx), "write header");

    // Half channels converted once; float channels read in place.
    std::vector<std::vector<uint16_t>> halves(img.channels.size());
    for (size_t i = 0; i < img.channels.size(); ++i)
        if (img.channels[i].half) {
            halves[i].resize(img.channels[i].values.size());
            std::transform(img.channels[i].values.begin(), img.channels[i].values.end(), halves[i].begin(), floatToHalf);
        }
    int32_t linesPerChunk = 1;
    check(exr_get_scanlines_per_chunk(w.ctx, part, &linesPerChunk), "chunk size");
    exr_encode_pipeline_t encoder = EXR_ENCODE_PIPELINE_INITIALIZER;
    bool initialised = false;
    for (int y = 0; y < img.height; y += linesPerChunk) {
        exr_chunk_info_t chunk;
        check(exr_write_scanline_chunk_info(w.ctx, part, y, &chunk), "chunk");
        check(initialised ? exr_encoding_update(w.ctx, part, &chunk, &encoder)
                          : exr_encoding_initialize(w.ctx, part, &chunk, &encoder),
              "encoder");
        initialised = true;
        for (int k = 0; k < encoder.channel_count; ++k) {
            exr_coding_channel_info_t& ch = encoder.channels[k];
            size_t i = 0;
            while (img.channels[i].name != ch.channel_name) ++i;
            const size_t first = size_t(y) * size_t(img.width);
            if (img.channels[i].half) {
                ch.encode_from_ptr = reinterpret_cast<const uint8_t*>(halves[i].data() + first);
                ch.user_bytes_per_element = 2;
                ch.user_data_type = EXR_PIXEL_HALF;
            } else {
                ch.encode_from_ptr = reinterpret_cast<const uint8_t*>(img.channels[i].values.data() + first);
                ch.user_bytes_per_element = 4;
                ch.user_data_type = EXR_PIXEL_FLOAT;
            }
            ch.user_pixel_stride = ch.user_bytes_per_element;
            ch.user_line_stride = ch.user_bytes_per_element * img.width;
        }
        if (y == 0) check(exr_encoding_choose_default_routines(w.ctx, part, &encoder), "encoder routines");
        check(exr_encoding_run(w.ctx, part, &encoder), "encode");
    }
    if (initialised) check(exr_encoding_destroy(w.ctx, &encoder), "encoder end");
    const exr_result_t finished = exr_finish(&w.ctx);
    w.ctx = nullptr;
    check(finished, "finish");
    return std::move(out.bytes);
#endif
}

std::vector<uint8_t> encodePfm(const HdrImage& img) {
    checkShape(img);
    const size_t n = img.channels.size();
    if (n != 1 && n != 3)
        throw Error("error: PFM holds 1 or 3 channels, not " + std::to_string(n) + " (use .exr for more)");
    char header[64];
    const int len = std::snprintf(header, sizeof header, "%s\n%d %d\n-1.0\n", n == 3 ? "PF" : "Pf", img.width, img.height);
    std::vector<uint8_t> out(header, header + len);
    const size_t start = out.size();
    out.resize(start + size_t(img.width) * size_t(img.height) * n * 4);
    uint8_t* p = out.data() + start;
    // Rows bottom first; little-endian (x86: the floats' own bytes).
    for (int y = img.height - 1; y >= 0; --y)
        for (int x = 0; x < img.width; ++x)
            for (size_t c = 0; c < n; ++c, p += 4) {
                const float v = img.channels[c].values[size_t(y) * size_t(img.width) + size_t(x)];
                uint32_t bits;
                std::memcpy(&bits, &v, 4);
                for (int b = 0; b < 4; ++b) p[b] = uint8_t(bits >> (8 * b));
            }
    return out;
}

std::vector<uint8_t> encodeHdrImage(const std::string& path, const HdrImage& img) {
    try {
        return isExrPath(path) ? encodeExr(img) : encodePfm(img);
    } catch (const Error& e) {
        throw Error(path + ": " + e.what());
    }
}

void writeHdrImage(const std::string& path, const HdrImage& img) { writeFileAtomically(path, encodeHdrImage(path, img)); }

}  // namespace rays
