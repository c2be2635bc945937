// Image file encoding/decoding: libspng (PNG out), TurboJPEG (JPEG in and out), stb_image_write (TGA,
// BMP out), a few lines of our own (PPM/PGM out) and stb_image (PNG, BMP, TGA, PPM/PGM in).
#include "rays/io/image_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <memory>

#include <spng.h>
#include <turbojpeg.h>
#include <zlib.h>

#include "rays/error.h"
#include "rays/io/image_guard.h"
#include "rays/io/output_files.h"
#include "rays/util/memory_limit.h"

#define STBI_NO_STDIO
#define STBI_ONLY_PNG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_ONLY_PNM
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_FAILURE_USERMSG
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
// stb is a system include dir in our build; these keep it quiet when it is not.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#include <stb_image.h>
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace rays {
namespace {

enum class Format { Unknown, Png, Jpeg, Ppm, Tga, Bmp };

const char* const kValidExtensions = ".png, .jpg, .jpeg, .ppm, .tga or .bmp";

/// Lower-cased text after the last '.' of s (or all of s when it has no '.'); "" when s ends in '.'.
std::string extensionOf(const std::string& s) {
    const size_t slash = s.find_last_of('/');
    const size_t dot = s.find_last_of('.');
    std::string ext;
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        ext = s.find('/') == std::string::npos ? s : std::string();
    else
        ext = s.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c); });
    return ext;
}

Format formatOf(const std::string& ext) {
    if (ext == "png") return Format::Png;
    if (ext == "jpg" || ext == "jpeg") return Format::Jpeg;
    if (ext == "ppm") return Format::Ppm;
    if (ext == "tga") return Format::Tga;
    if (ext == "bmp") return Format::Bmp;
    return Format::Unknown;
}

/// An encoder failure, turned into rays::Error by the callers (with or without a path).
struct EncodeFailure {
    std::string msg;
};

void validate(const Image8& img) {
    if (img.width <= 0 || img.height <= 0 || img.channels < 1 || img.channels > 4 ||
        img.pixels.size() != size_t(img.width) * size_t(img.height) * size_t(img.channels))
        throw EncodeFailure{"invalid image (" + std::to_string(img.width) + "x" + std::to_string(img.height) +
                            ", " + std::to_string(img.channels) + " channels, " +
                            std::to_string(img.pixels.size()) + " bytes)"};
    // stb_image_write and TurboJPEG take int sizes.
    if (img.pixels.size() > size_t(1) << 30) throw EncodeFailure{"image too large to encode"};
}

/// The image without its alpha channel (1 or 3 channels); a copy only when img has alpha.
struct NoAlpha {
    const uint8_t* data;
    int channels;
    std::vector<uint8_t> storage;
};

NoAlpha dropAlpha(const Image8& img) {
    if (img.channels == 1 || img.channels == 3) return {img.pixels.data(), img.channels, {}};
    const int outC = img.channels - 1;
    const size_t n = size_t(img.width) * size_t(img.height);
    std::vector<uint8_t> out(n * size_t(outC));
    const uint8_t* src = img.pixels.data();
    uint8_t* dst = out.data();
    for (size_t i = 0; i < n; ++i, src += img.channels, dst += outC)
        for (int c = 0; c < outC; ++c) dst[c] = src[c];
    const uint8_t* p = out.data();
    return {p, outC, std::move(out)};
}

// ---- PNG (libspng) ----
//
// Speed matters more than size (renders are written often, e.g. progressive output): zlib level 1, the
// UP filter only, and the zlib strategy picked per image. Z_RLE (distance-1 matches only) is ~1.5-2x
// faster than the match search of Z_FILTERED on most images, rendered scenes included (flat
// backgrounds filter to runs of zeros, shading to noise), at about the same size; but on clean
// synthetic images whose rows repeat with a period above one byte (an RGB gradient) Z_FILTERED is
// both faster and ~20x smaller. So both are tried on a sample, two blocks of 4 consecutive rows
// (UP-filtered as the encoder will), and Z_RLE is used unless Z_FILTERED's sample is much smaller.
// Measured (Release -O2, best of 30; zlib 1.2.13, libspng 0.7.3; 2-vCPU AMD EPYC VM), time and size:
//                                    spng defaults     SUB+Z_RLE        UP+Z_FILTERED    UP+Z_RLE
//   640x480 RGB smooth gradient      10.6 ms   2 KB    4.1 ms  114 KB   2.3 ms    6 KB
//   640x480 RGB gradient, +-6 noise  61 ms   471 KB   10.2 ms  492 KB  15.4 ms  563 KB   10.2 ms
//   4096x4096 RGB uniform noise      2.1-2.3 s 48 MB   0.6-0.8 s 48 MB  1.3-1.7 s 48 MB  0.6-0.7 s
// and, best of 15 (r = x, g = y, b = x + y gradients; renders of the course scenes):
//   640x480 gradient, clean / +-2 / +-6 noise   UP+Z_FILTERED 2.0 / 9.7 / 12.0 ms, UP+Z_RLE 4.1 / 7.2 / 6.7 ms
//   gnarly.pov / balls2.pov 640x480 renders     UP+Z_FILTERED 8.7 / 9.5 ms,       UP+Z_RLE 6.1 / 6.3 ms
//   (sizes: Z_RLE 118 KB vs 25 KB on the clean gradient, within 5 % elsewhere). The sample costs ~0.3 ms.
// (Trying several filters per row, NONE+SUB or ALL, costs 1.5-4x more for little gain at level 1.)
// JPEG q90 4:4:4 for comparison: 0.8 ms for the 640x480 gradient, 240 ms for the 4096x4096 noise.
constexpr int kPngLevel = 1;
constexpr int kPngFilters = SPNG_FILTER_CHOICE_UP;
constexpr int kSampleRows = 4;          // rows per sample block
constexpr double kFilteredGain = 0.8;   // Z_FILTERED when its sample is below this fraction of Z_RLE's

// Compressed size of data with zlib level kPngLevel and the given strategy (0 when zlib fails). The
// window only needs to reach back a row or two: a smaller one is cheaper to set up.
size_t deflatedSize(const std::vector<uint8_t>& data, size_t rowBytes, int strategy) {
    int windowBits = 9;
    while (windowBits < 15 && (size_t(1) << windowBits) < 2 * rowBytes) ++windowBits;
    z_stream zs{};
    if (deflateInit2(&zs, kPngLevel, Z_DEFLATED, windowBits, 8, strategy) != Z_OK) return 0;
    std::vector<uint8_t> out(deflateBound(&zs, uLong(data.size())));
    zs.next_in = const_cast<Bytef*>(data.data());
    zs.avail_in = uInt(data.size());
    zs.next_out = out.data();
    zs.avail_out = uInt(out.size());
    const int rc = deflate(&zs, Z_FINISH);
    const size_t size = rc == Z_STREAM_END ? size_t(zs.total_out) : 0;
    deflateEnd(&zs);
    return size;
}

}  // namespace

int pngZlibStrategy(const Image8& img) {
    const size_t rowBytes = size_t(img.width) * size_t(img.channels);
    std::vector<uint8_t> sample;
    auto addBlock = [&](int y0) {  // UP-filtered rows y0 .. y0 + kSampleRows - 1, each after its row above
        for (int y = std::max(y0, 1); y < std::min(y0 + kSampleRows, img.height); ++y) {
            const uint8_t* r = img.row(y);
            const uint8_t* above = img.row(y - 1);
            const size_t at = sample.size();
            sample.resize(at + rowBytes);
            for (size_t i = 0; i < rowBytes; ++i) sample[at + i] = uint8_t(r[i] - above[i]);
        }
    };
    sample.reserve(2 * kSampleRows * rowBytes);
    addBlock(img.height / 3);
    addBlock(2 * img.height / 3);
    const size_t rle = deflatedSize(sample, rowBytes, Z_RLE), filtered = deflatedSize(sample, rowBytes, Z_FILTERED);
    return double(filtered) < kFilteredGain * double(rle) ? Z_FILTERED : Z_RLE;
}

int pngStrategyLastRow(int height) { return std::min(2 * height / 3 + kSampleRows, height) - 1; }

namespace {

int spngWrite(spng_ctx*, void* user, void* src, size_t length) {
    auto* out = static_cast<std::vector<uint8_t>*>(user);
    const auto* p = static_cast<const uint8_t*>(src);
    out->insert(out->end(), p, p + length);
    return 0;
}

[[noreturn]] void pngEncoderFailed(const std::string& why) { throw Error("error: PNG encoder: " + why); }

}  // namespace

// One spng context in progressive mode writing to `out`; rows are handed over one at a time.
struct PngRowEncoder::Impl {
    std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> ctx{spng_ctx_new(SPNG_CTX_ENCODER), spng_ctx_free};
    std::vector<uint8_t> out;
    size_t rowBytes = 0;
    int rowsLeft = 0;
};

PngRowEncoder::PngRowEncoder(int width, int height, int channels, int zlibStrategy, int bitDepth)
    : impl_(std::make_unique<Impl>()) {
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || (bitDepth != 8 && bitDepth != 16))
        pngEncoderFailed("invalid image");
    if (!impl_->ctx) pngEncoderFailed("out of memory");
    static const uint8_t colorTypes[4] = {SPNG_COLOR_TYPE_GRAYSCALE, SPNG_COLOR_TYPE_GRAYSCALE_ALPHA,
                                          SPNG_COLOR_TYPE_TRUECOLOR, SPNG_COLOR_TYPE_TRUECOLOR_ALPHA};
    spng_ihdr ihdr{};
    ihdr.width = uint32_t(width);
    ihdr.height = uint32_t(height);
    ihdr.bit_depth = uint8_t(bitDepth);
    ihdr.color_type = colorTypes[channels - 1];
    impl_->rowBytes = size_t(width) * size_t(channels) * size_t(bitDepth / 8);
    impl_->rowsLeft = height;
    impl_->out.reserve(impl_->rowBytes * size_t(height) / 4 + 1024);
    spng_ctx* ctx = impl_->ctx.get();
    int err = spng_set_png_stream(ctx, spngWrite, &impl_->out);
    if (!err) err = spng_set_ihdr(ctx, &ihdr);
    if (!err) err = spng_set_option(ctx, SPNG_IMG_COMPRESSION_LEVEL, kPngLevel);
    if (!err) err = spng_set_option(ctx, SPNG_FILTER_CHOICE, kPngFilters);
    if (!err) err = spng_set_option(ctx, SPNG_IMG_COMPRESSION_STRATEGY, zlibStrategy);
    if (!err) err = spng_encode_image(ctx, nullptr, 0, SPNG_FMT_PNG, SPNG_ENCODE_PROGRESSIVE | SPNG_ENCODE_FINALIZE);
    if (err) pngEncoderFailed(spng_strerror(err));
}

PngRowEncoder::~PngRowEncoder() = default;

void PngRowEncoder::row(const uint8_t* pixels) {
    if (impl_->rowsLeft <= 0) pngEncoderFailed("more rows than the image has");
    const int err = spng_encode_row(impl_->ctx.get(), pixels, impl_->rowBytes);
    --impl_->rowsLeft;
    // The last row ends the image (SPNG_EOI) and, with SPNG_ENCODE_FINALIZE, writes IEND.
    if (err && !(err == SPNG_EOI && impl_->rowsLeft == 0))
        pngEncoderFailed(spng_strerror(err));
}

std::vector<uint8_t> PngRowEncoder::finish() {
    if (impl_->rowsLeft != 0)
        pngEncoderFailed(std::to_string(impl_->rowsLeft) + " rows were never given");
    return std::move(impl_->out);
}

std::vector<uint8_t> encodePng16(const ImageF& img) {
    PngRowEncoder enc(img.width, img.height, 3, Z_RLE, 16);
    std::vector<uint16_t> row(size_t(img.width) * 3);  // in the host's byte order: spng swaps them
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const Vec3 c = img.at(x, y);
            for (int k = 0; k < 3; ++k) {
                const double v = c[k] * 65535.0 + 0.5;
                row[size_t(x) * 3 + size_t(k)] = v <= 0.0 ? 0 : (v >= 65535.0 ? 65535 : uint16_t(v));
            }
        }
        enc.row(reinterpret_cast<const uint8_t*>(row.data()));
    }
    return enc.finish();
}

namespace {

std::vector<uint8_t> encodePng(const Image8& img) {
    if (img.pixels.size() != size_t(img.width) * size_t(img.height) * size_t(img.channels))
        throw EncodeFailure{"invalid image buffer"};
    try {
        PngRowEncoder enc(img.width, img.height, img.channels, pngZlibStrategy(img));
        for (int y = 0; y < img.height; ++y) enc.row(img.row(y));
        return enc.finish();
    } catch (const Error& e) {
        std::string why = e.what();  // "error: PNG encoder: ..."; the caller adds its own prefix
        if (why.rfind("error: ", 0) == 0) why.erase(0, 7);
        throw EncodeFailure{why};
    }
}

// ---- JPEG (TurboJPEG) ----

std::vector<uint8_t> encodeJpeg(const Image8& img, int quality) {
    if (quality < 1 || quality > 100)
        throw EncodeFailure{"JPEG quality must be 1..100, got " + std::to_string(quality)};
    const NoAlpha src = dropAlpha(img);
    const bool grey = src.channels == 1;
    std::unique_ptr<void, int (*)(tjhandle)> tj(tjInitCompress(), tjDestroy);
    if (!tj) throw EncodeFailure{std::string("JPEG encoder: ") + tjGetErrorStr2(nullptr)};
    unsigned char* buf = nullptr;
    unsigned long size = 0;
    const int samp = grey ? TJSAMP_GRAY : (quality >= 90 ? TJSAMP_444 : TJSAMP_420);
    const int rc = tjCompress2(tj.get(), src.data, img.width, img.width * src.channels, img.height,
                               grey ? TJPF_GRAY : TJPF_RGB, &buf, &size, samp, quality, TJFLAG_ACCURATEDCT);
    if (rc != 0) {
        const std::string why = tjGetErrorStr2(tj.get());
        tjFree(buf);
        throw EncodeFailure{"JPEG encoder: " + why};
    }
    std::vector<uint8_t> out(buf, buf + size);
    tjFree(buf);
    return out;
}

// ---- PPM / PGM (binary) ----

std::vector<uint8_t> encodePpm(const Image8& img) {
    const NoAlpha src = dropAlpha(img);
    const std::string header = std::string(src.channels == 1 ? "P5" : "P6") + "\n" + std::to_string(img.width) +
                               " " + std::to_string(img.height) + "\n255\n";
    const size_t n = size_t(img.width) * size_t(img.height) * size_t(src.channels);
    std::vector<uint8_t> out;
    out.reserve(header.size() + n);
    out.insert(out.end(), header.begin(), header.end());
    out.insert(out.end(), src.data, src.data + n);
    return out;
}

// ---- TGA / BMP (stb_image_write) ----

void stbWrite(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const auto* p = static_cast<const uint8_t*>(data);
    out->insert(out->end(), p, p + size);
}

std::vector<uint8_t> encodeStb(Format f, const Image8& img) {
    std::vector<uint8_t> out;
    out.reserve(img.pixels.size() + 1024);
    const int ok = f == Format::Tga
                       ? stbi_write_tga_to_func(stbWrite, &out, img.width, img.height, img.channels,
                                                img.pixels.data())
                       : stbi_write_bmp_to_func(stbWrite, &out, img.width, img.height, img.channels,
                                                img.pixels.data());
    if (!ok) throw EncodeFailure{f == Format::Tga ? "TGA encoder failed" : "BMP encoder failed"};
    return out;
}

std::vector<uint8_t> encodeAs(Format f, const Image8& img, int jpegQuality) {
    validate(img);
    switch (f) {
    case Format::Png: return encodePng(img);
    case Format::Jpeg: return encodeJpeg(img, jpegQuality);
    case Format::Ppm: return encodePpm(img);
    case Format::Tga:
    case Format::Bmp: return encodeStb(f, img);
    case Format::Unknown: break;
    }
    throw EncodeFailure{"unsupported image format"};
}

std::string unknownExtensionMessage(const std::string& ext) {
    if (ext.empty())
        return std::string("missing image file extension (expected ") + kValidExtensions + ")";
    return "unsupported image file extension '." + ext + "' (expected " + kValidExtensions + ")";
}

std::string errnoText(int e) { return std::strerror(e); }

}  // namespace

bool isSupportedImageExtension(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return false;
    return formatOf(extensionOf(path)) != Format::Unknown;
}

bool isPngPath(const std::string& path) {
    return formatOf(extensionOf(path)) == Format::Png;
}

std::vector<uint8_t> encodeImage(const std::string& extension, const Image8& img, int jpegQuality) {
    const std::string ext = extensionOf(extension);
    const Format f = formatOf(ext);
    if (f == Format::Unknown) throw Error("error: " + unknownExtensionMessage(ext));
    try {
        return encodeAs(f, img, jpegQuality);
    } catch (const EncodeFailure& e) {
        throw Error("error: " + e.msg);
    }
}

std::vector<uint8_t> encodeImageFile(const std::string& path, const Image8& img, int jpegQuality) {
    if (!isSupportedImageExtension(path)) {
        const size_t slash = path.find_last_of('/');
        const size_t dot = path.find_last_of('.');
        const bool hasExt = dot != std::string::npos && (slash == std::string::npos || dot > slash);
        failFile(path, unknownExtensionMessage(hasExt ? extensionOf(path) : std::string()));
    }
    std::vector<uint8_t> data;
    try {
        data = encodeAs(formatOf(extensionOf(path)), img, jpegQuality);
    } catch (const EncodeFailure& e) {
        failFile(path, e.msg);
    }
    return data;
}

void writeImage(const std::string& path, const Image8& img, int jpegQuality) {
    writeFileAtomically(path, encodeImageFile(path, img, jpegQuality));
}

void writeFileAtomically(const std::string& path, const std::vector<uint8_t>& data) {
    OutputFiles files;
    files.stage(path, data);
    files.commit();
}

namespace {

bool isJpeg(const std::vector<uint8_t>& b) { return b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF; }

// Refuses, before anything is allocated, a decode needing more than the memory limit: `copies`
// images of w×h×channels bytes (stb_image's buffer and the Image8 it is copied into).
template <class Fail>
void checkDecodeBudget(int w, int h, int channels, int copies, Fail&& failRead) {
    const double need = double(w) * double(h) * double(channels) * copies;
    const uint64_t limit = memoryLimit();
    if (need > double(limit))
        failRead("a " + std::to_string(w) + "x" + std::to_string(h) + " image needs " + formatBytes(need) +
                 " to decode, more than the memory limit of " + formatBytes(double(limit)) + memoryLimitSource());
}

std::string tooLargeMessage(int w, int h) {
    return "image is " + std::to_string(w) + "x" + std::to_string(h) +
           ", larger than the limit (65536 per side and 268435456 pixels)";
}

// JPEG input goes to libjpeg-turbo (continuously fuzzed upstream) rather than stb_image, whose 2.27
// decoder misbehaves on corrupt entropy-coded data. Warnings (truncated or corrupt data, which the
// library would otherwise fill with grey) are errors, so a damaged file is refused, not half-read.
template <class Fail>
Image8 decodeJpeg(const std::vector<uint8_t>& bytes, Fail&& failRead) {
    std::unique_ptr<void, int (*)(tjhandle)> tj(tjInitDecompress(), tjDestroy);
    if (!tj) failRead(std::string("JPEG decoder: ") + tjGetErrorStr2(nullptr));
    int w = 0, h = 0, subsampling = 0, colorspace = 0;
    if (tjDecompressHeader3(tj.get(), bytes.data(), static_cast<unsigned long>(bytes.size()), &w, &h, &subsampling,
                            &colorspace) != 0)
        failRead(std::string("corrupt JPEG (") + tjGetErrorStr2(tj.get()) + ")");
    if (w <= 0 || h <= 0) failRead("image has no pixels (" + std::to_string(w) + "x" + std::to_string(h) + ")");
    if (w > kMaxImageSide || h > kMaxImageSide || uint64_t(w) * uint64_t(h) > kMaxImagePixels)
        failRead(tooLargeMessage(w, h));
    if (const std::string why = imageSizeHazard(bytes.data(), bytes.size(), w, h); !why.empty()) failRead(why);
    if (colorspace == TJCS_CMYK || colorspace == TJCS_YCCK) failRead("CMYK JPEG images are not supported");
    checkDecodeBudget(w, h, colorspace == TJCS_GRAY ? 1 : 3, 1, failRead);
    Image8 img;
    img.width = w;
    img.height = h;
    img.channels = colorspace == TJCS_GRAY ? 1 : 3;
    img.pixels.resize(size_t(w) * size_t(h) * size_t(img.channels));
    if (tjDecompress2(tj.get(), bytes.data(), static_cast<unsigned long>(bytes.size()), img.pixels.data(), w, 0, h,
                      img.channels == 1 ? TJPF_GRAY : TJPF_RGB, TJFLAG_STOPONWARNING) != 0)
        failRead(std::string("corrupt JPEG (") + tjGetErrorStr2(tj.get()) + ")");
    return img;
}

}  // namespace

Image8 readImage(const std::string& path) {
    auto failRead = [&](const std::string& why) { failFile(path, "cannot read image: " + why); };

    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) failRead(errnoText(errno));
    std::vector<uint8_t> bytes;
    {
        struct stat st {};
        if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) bytes.reserve(size_t(st.st_size));
        uint8_t chunk[1 << 16];
        for (;;) {
            const ssize_t n = ::read(fd, chunk, sizeof chunk);
            if (n < 0) {
                if (errno == EINTR) continue;
                const int e = errno;
                ::close(fd);
                failRead(errnoText(e));
            }
            if (n == 0) break;
            bytes.insert(bytes.end(), chunk, chunk + n);
            if (bytes.size() > size_t(INT32_MAX)) {  // also stops endless sources such as /dev/zero
                ::close(fd);
                failRead("file too large");
            }
        }
        ::close(fd);
    }
    if (bytes.empty()) failRead("file is empty");
    removeEmptyPngData(bytes);
    if (const std::string hazard = imageDecoderHazard(bytes.data(), bytes.size()); !hazard.empty()) failRead(hazard);
    if (isJpeg(bytes)) return decodeJpeg(bytes, failRead);
    int infoW = 0, infoH = 0, infoC = 0;
    if (stbi_info_from_memory(bytes.data(), int(bytes.size()), &infoW, &infoH, &infoC) &&
        (infoW > kMaxImageSide || infoH > kMaxImageSide || uint64_t(infoW) * uint64_t(infoH) > kMaxImagePixels))
        failRead(tooLargeMessage(infoW, infoH));
    if (const std::string why = imageSizeHazard(bytes.data(), bytes.size(), infoW, infoH); !why.empty()) failRead(why);
    checkDecodeBudget(infoW, infoH, std::clamp(infoC, 1, 4), 2, failRead);

    int w = 0, h = 0, comp = 0;
    stbi_uc* px = stbi_load_from_memory(bytes.data(), int(bytes.size()), &w, &h, &comp, 0);
    if (!px) {
        const char* reason = stbi_failure_reason();
        std::string why = reason ? reason : "unknown error";
        if (why == "Image not of any known type, or corrupt")
            why = "not a PNG, JPEG, BMP, TGA or binary PPM/PGM file, or corrupt";
        failRead(why);
    }
    if (w <= 0 || h <= 0 || comp < 1 || comp > 4) {  // stb_image accepts a PPM of height 0
        stbi_image_free(px);
        failRead("image has no pixels (" + std::to_string(w) + "x" + std::to_string(h) + ")");
    }
    Image8 img;
    img.width = w;
    img.height = h;
    img.channels = comp;
    img.pixels.assign(px, px + size_t(w) * size_t(h) * size_t(comp));
    stbi_image_free(px);
    return img;
}

}  // namespace rays
