// PNG written row by row (PngRowEncoder) and while the rows are still being made (PngStream): the
// same bytes as encoding the finished image, whatever order and threads the rows arrive in.
#include "rays/io/png_stream.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "rays/error.h"
#include "rays/image/image.h"
#include "rays/io/image_io.h"

using rays::Image8;
using rays::ImageF;
using rays::Vec3;

namespace { namespace RAYS_TEST_UNIT {

// Smooth colours: the PNG encoder picks Z_FILTERED for these.
ImageF gradient(int w, int h) {
    ImageF img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) img.at(x, y) = Vec3{double(x) / w, double(y) / h, double(x + y) / (w + h)};
    return img;
}

// A shaded disc with sparse noise over black, like a render: Z_RLE.
ImageF renderLike(int w, int h) {
    ImageF img(w, h);
    std::mt19937 rng(7);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double dx = (x - w / 2.0) / (0.4 * w), dy = (y - h / 2.0) / (0.4 * h);
            if (dx * dx + dy * dy > 1) continue;
            const double shade = 0.8 * std::sqrt(1 - dx * dx - dy * dy) + (rng() % 8 == 0 ? 0.01 : 0.0);
            img.at(x, y) = Vec3{shade, 0.5 * shade, 0.2};
        }
    return img;
}

std::vector<uint8_t> encodedWhole(const ImageF& img) { return rays::encodeImage("png", rays::toImage8(img)); }

// Reports img's rows to a PngStream in bands of `band` rows, in the order given by `order` (band
// indices), split over `threads` threads.
std::vector<uint8_t> streamed(const ImageF& img, int band, std::vector<int> order, int threads) {
    rays::PngStream png(img.width, img.height);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            for (size_t i = size_t(t); i < order.size(); i += size_t(threads)) {
                const int y0 = order[i] * band;
                png.rowsDone(img, y0, std::min(y0 + band, img.height));
            }
        });
    for (std::thread& th : pool) th.join();
    return png.finish();
}

std::vector<int> bands(int height, int band) {
    std::vector<int> v(size_t((height + band - 1) / band));
    for (size_t i = 0; i < v.size(); ++i) v[i] = int(i);
    return v;
}

TEST(PngRowEncoder, SameBytesAsTheWholeImageEncoder) {
    for (const ImageF& f : {gradient(97, 61), renderLike(160, 120)}) {
        const Image8 img = rays::toImage8(f);
        rays::PngRowEncoder enc(img.width, img.height, 3, rays::pngZlibStrategy(img));
        for (int y = 0; y < img.height; ++y) enc.row(img.row(y));
        EXPECT_EQ(enc.finish(), rays::encodeImage("png", img));
    }
}

TEST(PngRowEncoder, RowCountMustMatchTheImage) {
    const Image8 img = rays::toImage8(gradient(8, 4));
    rays::PngRowEncoder few(8, 4, 3, rays::pngZlibStrategy(img));
    for (int y = 0; y < 3; ++y) few.row(img.row(y));
    EXPECT_THROW(few.finish(), rays::Error);

    rays::PngRowEncoder many(8, 4, 3, rays::pngZlibStrategy(img));
    for (int y = 0; y < 4; ++y) many.row(img.row(y));
    EXPECT_THROW(many.row(img.row(0)), rays::Error);

    EXPECT_THROW(rays::PngRowEncoder(0, 4, 3, 0), rays::Error);
}

TEST(PngStrategy, ReadsNoRowBelowItsLastRow) {
    // The streamed encoder picks the strategy before the last rows exist: they must not matter.
    for (int h : {1, 2, 5, 12, 480}) {
        const int last = rays::pngStrategyLastRow(h);
        ASSERT_GE(last, 0);
        ASSERT_LT(last, h);
        Image8 clean = rays::toImage8(gradient(64, h)), noisy = clean;
        std::mt19937 rng(3);
        for (int y = last + 1; y < h; ++y)
            for (int i = 0; i < 64 * 3; ++i) noisy.row(y)[i] = uint8_t(rng());
        EXPECT_EQ(rays::pngZlibStrategy(clean), rays::pngZlibStrategy(noisy)) << "height " << h;
    }
}

TEST(PngStream, RowsInOrderGiveTheWholeImagesBytes) {
    for (const ImageF& img : {gradient(640, 480), renderLike(640, 480), gradient(5, 1)})
        EXPECT_EQ(streamed(img, 16, bands(img.height, 16), 1), encodedWhole(img));
}

TEST(PngStream, RowsOutOfOrderFromSeveralThreads) {
    const ImageF img = renderLike(320, 250);  // last band short
    std::vector<int> order = bands(img.height, 16);
    std::reverse(order.begin(), order.end());
    EXPECT_EQ(streamed(img, 16, order, 1), encodedWhole(img));
    std::shuffle(order.begin(), order.end(), std::mt19937(11));
    for (int threads : {2, 4}) EXPECT_EQ(streamed(img, 16, order, threads), encodedWhole(img));
    EXPECT_EQ(streamed(img, 1, bands(img.height, 1), 3), encodedWhole(img));
}

TEST(PngStream, MissingRowsAreAnError) {
    const ImageF img = gradient(32, 32);
    rays::PngStream png(32, 32);
    png.rowsDone(img, 0, 16);
    png.rowsDone(img, 24, 32);  // rows 16..23 never come
    EXPECT_THROW(png.finish(), rays::Error);
}

}}  // namespace RAYS_TEST_UNIT, namespace
