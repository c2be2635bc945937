#include "rays/io/image_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <spng.h>

#include <memory>

#include "rays/error.h"
#include "support/files.h"

namespace fs = std::filesystem;
using rays::Image8;

using rays::test::writeFile;

namespace { namespace RAYS_TEST_UNIT {

/// A fresh, empty directory removed (with its contents) when the test ends.
class TempDir {
public:
    TempDir() {
        static int counter = 0;
        path_ = fs::temp_directory_path() /
                ("rays_image_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    const fs::path& path() const { return path_; }
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    fs::path path_;
};

/// A deterministic test pattern with structure and some noise in every channel.
Image8 pattern(int w, int h, int channels) {
    Image8 img(w, h, channels);
    uint32_t s = 12345;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c) {
                s = s * 1664525u + 1013904223u;
                img.row(y)[x * channels + c] = uint8_t((x * 7 + y * 3 + c * 50) + ((s >> 24) & 7));
            }
    return img;
}

/// A smooth pattern (JPEG-friendly).
Image8 smooth(int w, int h, int channels) {
    Image8 img(w, h, channels);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c)
                img.row(y)[x * channels + c] = uint8_t(255 * (x + y + c * 10) / (w + h + 40));
    return img;
}

void expectSame(const Image8& a, const Image8& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    ASSERT_EQ(a.channels, b.channels);
    EXPECT_TRUE(a.pixels == b.pixels);
}

/// The image with only its first `channels` channels.
Image8 firstChannels(const Image8& img, int channels) {
    Image8 out(img.width, img.height, channels);
    for (size_t i = 0; i < size_t(img.width) * size_t(img.height); ++i)
        for (int c = 0; c < channels; ++c) out.pixels[i * size_t(channels) + size_t(c)] =
            img.pixels[i * size_t(img.channels) + size_t(c)];
    return out;
}

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const rays::Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected rays::Error";
    return "";
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

TEST(ImageIoExtension, SupportedExtensions) {
    for (const char* p : {"a.png", "a.PNG", "dir/a.jpg", "a.JPEG", "a.jpeg", "a.ppm", "a.tga", "a.Bmp"})
        EXPECT_TRUE(rays::isSupportedImageExtension(p)) << p;
    for (const char* p : {"a.gif", "a", "png", "a.png.txt", "dir.png/a", "a.", ".png/x", "a.pn"})
        EXPECT_FALSE(rays::isSupportedImageExtension(p)) << p;
}

TEST(ImageIoPng, RoundTripRgbRgbaGreyGreyAlpha) {
    TempDir dir;
    for (int c = 1; c <= 4; ++c) {
        const Image8 img = pattern(37, 23, c);
        const std::string path = dir.file("img" + std::to_string(c) + ".png");
        rays::writeImage(path, img);
        expectSame(rays::readImage(path), img);
    }
}

TEST(ImageIoPng, SixteenBitsPerChannelKeepTheValuesToOne65535th) {
    rays::ImageF img(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) img.at(x, y) = rays::Vec3{x / 4.0, y / 2.0 + 1e-5, 0.123456} * (x == 4 ? 1.5 : 1.0);
    const std::vector<uint8_t> png = rays::encodePng16(img);
    ASSERT_GT(png.size(), 33u);
    EXPECT_EQ(png[24], 16);  // IHDR: bit depth 16,
    EXPECT_EQ(png[25], 2);   // colour type 2 (RGB)
    std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> ctx(spng_ctx_new(0), spng_ctx_free);
    ASSERT_EQ(spng_set_png_buffer(ctx.get(), png.data(), png.size()), 0);
    std::vector<uint16_t> rgba(5 * 3 * 4);
    ASSERT_EQ(spng_decode_image(ctx.get(), rgba.data(), rgba.size() * 2, SPNG_FMT_RGBA16, 0), 0);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            for (int k = 0; k < 3; ++k) {
                const double want = std::clamp(std::round(img.at(x, y)[k] * 65535), 0.0, 65535.0);
                EXPECT_EQ(rgba[size_t(y * 5 + x) * 4 + size_t(k)], uint16_t(want)) << x << " " << y << " " << k;
            }
}

TEST(ImageIoPng, EncodeStartsWithSignature) {
    const std::vector<uint8_t> png = rays::encodeImage(".png", pattern(8, 8, 3));
    ASSERT_GE(png.size(), 8u);
    EXPECT_EQ(png[0], 0x89);
    EXPECT_EQ(png[1], 'P');
    EXPECT_EQ(png[2], 'N');
    EXPECT_EQ(png[3], 'G');
    // Extension spelt without the dot or as a file name works too.
    EXPECT_EQ(rays::encodeImage("png", pattern(8, 8, 3)), png);
    EXPECT_EQ(rays::encodeImage("x/out.PNG", pattern(8, 8, 3)), png);
}

// A smooth RGB gradient: its UP-filtered rows repeat with a period of 3 bytes, which only
// Z_FILTERED's match search finds (about 20x smaller and faster than Z_RLE there).
Image8 rgbGradient(int w, int h) {
    Image8 img;
    img.width = w;
    img.height = h;
    img.channels = 3;
    img.pixels.resize(size_t(w) * size_t(h) * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            uint8_t* p = &img.pixels[(size_t(y) * size_t(w) + size_t(x)) * 3];
            p[0] = uint8_t(x * 255 / w);
            p[1] = uint8_t(y * 255 / h);
            p[2] = uint8_t((x + y) * 255 / (w + h));
        }
    return img;
}

// Like a render: a black background and a shaded disc with a little sampling noise. Its mean
// left-to-right difference is low (0.31), so the earlier roughness rule (Z_FILTERED below 0.5)
// took it for a clean image, although Z_RLE is ~1.4x faster on such images at about the same size.
Image8 renderLike(int w, int h) {
    Image8 img;
    img.width = w;
    img.height = h;
    img.channels = 3;
    img.pixels.assign(size_t(w) * size_t(h) * 3, 0);
    uint32_t state = 12345;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double dx = (x - w / 2.0) / (0.4 * w), dy = (y - h / 2.0) / (0.4 * h);
            if (dx * dx + dy * dy > 1) continue;
            state = state * 1664525u + 1013904223u;
            const int noise = (state >> 29) == 0 ? 1 : 0;  // one pixel in eight
            uint8_t* p = &img.pixels[(size_t(y) * size_t(w) + size_t(x)) * 3];
            const int shade = int(200 * std::sqrt(1 - dx * dx - dy * dy));
            for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::clamp(shade / (c + 1) + noise, 0, 255));
        }
    return img;
}

// zlib strategies, as in zlib.h.
constexpr int kZFiltered = 1, kZRle = 3;

TEST(ImageIoPng, CleanGradientsUseTheMatchSearch) {
    EXPECT_EQ(rays::pngZlibStrategy(rgbGradient(640, 480)), kZFiltered);
    EXPECT_EQ(rays::pngZlibStrategy(rgbGradient(37, 5)), kZFiltered);  // fewer rows than the sample
}

TEST(ImageIoPng, RendersUseRunLengthMatches) {
    EXPECT_EQ(rays::pngZlibStrategy(renderLike(640, 480)), kZRle);
    // Tiny and one-row images still get a strategy and encode.
    EXPECT_EQ(rays::pngZlibStrategy(renderLike(3, 1)), kZRle);
    EXPECT_FALSE(rays::encodeImage("png", renderLike(3, 1)).empty());
}

TEST(ImageIoJpeg, RoundTripWithinSmallError) {
    TempDir dir;
    for (int quality : {95, 80}) {
        const Image8 img = smooth(64, 48, 3);
        const std::string path = dir.file("img" + std::to_string(quality) + ".jpg");
        rays::writeImage(path, img, quality);
        const Image8 back = rays::readImage(path);
        ASSERT_EQ(back.width, img.width);
        ASSERT_EQ(back.height, img.height);
        ASSERT_EQ(back.channels, 3);
        int maxErr = 0;
        for (size_t i = 0; i < img.pixels.size(); ++i)
            maxErr = std::max(maxErr, std::abs(int(img.pixels[i]) - int(back.pixels[i])));
        EXPECT_LE(maxErr, quality >= 90 ? 4 : 8) << "quality " << quality;
    }
}

TEST(ImageIoJpeg, GreyStaysGreyAndAlphaIsDropped) {
    TempDir dir;
    const std::string grey = dir.file("g.jpeg");
    rays::writeImage(grey, smooth(32, 32, 1));
    EXPECT_EQ(rays::readImage(grey).channels, 1);

    const std::string rgba = dir.file("a.JPG");
    const Image8 img = smooth(32, 32, 4);
    rays::writeImage(rgba, img);
    const Image8 back = rays::readImage(rgba);
    ASSERT_EQ(back.channels, 3);
    const Image8 rgb = firstChannels(img, 3);
    for (size_t i = 0; i < rgb.pixels.size(); ++i) ASSERT_NEAR(int(rgb.pixels[i]), int(back.pixels[i]), 4);
}

TEST(ImageIoJpeg, BadQualityThrows) {
    EXPECT_THROW(rays::encodeImage("jpg", smooth(8, 8, 3), 0), rays::Error);
    EXPECT_THROW(rays::encodeImage("jpg", smooth(8, 8, 3), 101), rays::Error);
}

TEST(ImageIoPpm, RoundTripExact) {
    TempDir dir;
    const Image8 rgb = pattern(31, 17, 3);
    rays::writeImage(dir.file("a.ppm"), rgb);
    expectSame(rays::readImage(dir.file("a.ppm")), rgb);

    // Grey becomes P5 (PGM data in a .ppm file), alpha is dropped.
    const Image8 grey = pattern(31, 17, 1);
    rays::writeImage(dir.file("g.ppm"), grey);
    expectSame(rays::readImage(dir.file("g.ppm")), grey);
    const std::vector<uint8_t> p5 = rays::encodeImage("ppm", grey);
    EXPECT_EQ(std::string(p5.begin(), p5.begin() + 2), "P5");

    const Image8 rgba = pattern(31, 17, 4);
    rays::writeImage(dir.file("a4.ppm"), rgba);
    expectSame(rays::readImage(dir.file("a4.ppm")), firstChannels(rgba, 3));
    const std::vector<uint8_t> p6 = rays::encodeImage(".ppm", rgba);
    EXPECT_EQ(std::string(p6.begin(), p6.begin() + 11), "P6\n31 17\n25");
}

TEST(ImageIoTga, RoundTripExact) {
    TempDir dir;
    for (int c = 1; c <= 4; ++c) {
        const Image8 img = pattern(29, 19, c);
        const std::string path = dir.file("t" + std::to_string(c) + ".tga");
        rays::writeImage(path, img);
        expectSame(rays::readImage(path), img);
    }
}

TEST(ImageIoBmp, RoundTripExact) {
    TempDir dir;
    for (int c : {3, 4}) {
        const Image8 img = pattern(29, 19, c);
        const std::string path = dir.file("b" + std::to_string(c) + ".bmp");
        rays::writeImage(path, img);
        expectSame(rays::readImage(path), img);
    }
    // BMP has no grey format here: grey is stored (and read back) as RGB.
    const Image8 grey = pattern(29, 19, 1);
    rays::writeImage(dir.file("g.bmp"), grey);
    const Image8 back = rays::readImage(dir.file("g.bmp"));
    ASSERT_EQ(back.channels, 3);
    for (size_t i = 0; i < grey.pixels.size(); ++i) ASSERT_EQ(back.pixels[i * 3 + 1], grey.pixels[i]);
}

TEST(ImageIoWrite, UnknownExtensionThrowsAndCreatesNothing) {
    TempDir dir;
    const std::string path = dir.file("out.gif");
    const std::string msg = messageOf([&] { rays::writeImage(path, pattern(4, 4, 3)); });
    EXPECT_TRUE(startsWith(msg, path + ": error: ")) << msg;
    EXPECT_NE(msg.find(".png"), std::string::npos) << msg;
    EXPECT_NE(msg.find(".bmp"), std::string::npos) << msg;
    EXPECT_TRUE(dir.entries().empty());

    const std::string noExt = dir.file("out");
    EXPECT_THROW(rays::writeImage(noExt, pattern(4, 4, 3)), rays::Error);
    EXPECT_TRUE(dir.entries().empty());
    EXPECT_THROW(rays::encodeImage("gif", pattern(4, 4, 3)), rays::Error);
}

TEST(ImageIoWrite, InvalidImageThrowsAndCreatesNothing) {
    TempDir dir;
    Image8 bad(4, 4, 3);
    bad.pixels.resize(10);
    EXPECT_THROW(rays::writeImage(dir.file("a.png"), bad), rays::Error);
    EXPECT_THROW(rays::writeImage(dir.file("a.png"), Image8(4, 4, 5)), rays::Error);
    EXPECT_THROW(rays::writeImage(dir.file("a.png"), Image8()), rays::Error);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageIoWrite, MissingDirectoryThrowsAndLeavesNothing) {
    TempDir dir;
    const std::string path = dir.file("no/such/dir/out.png");
    const std::string msg = messageOf([&] { rays::writeImage(path, pattern(4, 4, 3)); });
    EXPECT_TRUE(startsWith(msg, path + ": error: ")) << msg;
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageIoWrite, TargetIsADirectoryThrowsAndLeavesNoTemporary) {
    TempDir dir;
    fs::create_directory(dir.file("taken.png"));
    const std::string path = dir.file("taken.png");
    const std::string msg = messageOf([&] { rays::writeImage(path, pattern(4, 4, 3)); });
    EXPECT_TRUE(startsWith(msg, path + ": error: ")) << msg;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken.png"});
}

TEST(ImageIoWrite, OverwriteReplacesAtomically) {
    TempDir dir;
    const std::string path = dir.file("out.png");
    writeFile(path, "old contents that are not an image");
    const Image8 first = pattern(16, 16, 3);
    rays::writeImage(path, first);
    expectSame(rays::readImage(path), first);

    // Replacing is a rename: a reader holding the old file keeps seeing complete old data.
    std::ifstream held(path, std::ios::binary);
    const Image8 second = pattern(40, 30, 4);
    rays::writeImage(path, second);
    expectSame(rays::readImage(path), second);
    const std::string oldBytes((std::istreambuf_iterator<char>(held)), std::istreambuf_iterator<char>());
    EXPECT_EQ(std::vector<uint8_t>(oldBytes.begin(), oldBytes.end()), rays::encodeImage("png", first));

    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.png"});  // no temporaries left
}

TEST(ImageIoRead, MissingFileThrowsWithPath) {
    TempDir dir;
    const std::string path = dir.file("missing.png");
    const std::string msg = messageOf([&] { rays::readImage(path); });
    EXPECT_TRUE(startsWith(msg, path + ": error: cannot read image: ")) << msg;
}

TEST(ImageIoRead, GarbageFileThrowsWithPath) {
    TempDir dir;
    const std::string path = dir.file("garbage.png");
    writeFile(path, "this is certainly not an image file, just some text\n");
    const std::string msg = messageOf([&] { rays::readImage(path); });
    EXPECT_TRUE(startsWith(msg, path + ": error: cannot read image: ")) << msg;

    const std::string empty = dir.file("empty.jpg");
    writeFile(empty, "");
    EXPECT_TRUE(startsWith(messageOf([&] { rays::readImage(empty); }), empty + ": error: cannot read image: "));

    // A truncated PNG.
    const std::string cut = dir.file("cut.png");
    const std::vector<uint8_t> png = rays::encodeImage("png", pattern(64, 64, 3));
    writeFile(cut, std::string(png.begin(), png.begin() + long(png.size() / 2)));
    EXPECT_TRUE(startsWith(messageOf([&] { rays::readImage(cut); }), cut + ": error: cannot read image: "));

    // A directory.
    EXPECT_TRUE(startsWith(messageOf([&] { rays::readImage(dir.path().string()); }),
                           dir.path().string() + ": error: cannot read image: "));
}

}}  // namespace RAYS_TEST_UNIT, namespace
