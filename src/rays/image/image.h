// Image types: linear float RGB for rendering, 8-bit for files. Rows are stored top row first.
#pragma once
#include <cstdint>
#include <type_traits>
#include <vector>

#include "rays/accel/huge_pages.h"
#include "rays/math/vec3.h"

namespace rays {

/// Pixel storage: huge pages for big images, and elements left unconstructed when the vector
/// grows without a value (Vec3 is an implicit-lifetime type), so that an image whose every pixel
/// is written by the render threads is first touched by those threads, in parallel, instead of
/// being zero-filled by one thread first.
template <class T>
struct PixelAllocator : tribvh::HugePageAllocator<T> {
    using value_type = T;
    PixelAllocator() = default;
    template <class U>
    PixelAllocator(const PixelAllocator<U>&) noexcept {}
    template <class U>
    struct rebind {
        using other = PixelAllocator<U>;
    };
    template <class U>
    void construct(U*) noexcept {
        static_assert(std::is_trivially_copyable_v<U> && std::is_trivially_destructible_v<U>);
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

/// Float RGB image; pixel (x, y) with y = 0 the TOP row.
struct ImageF {
    int width = 0, height = 0;
    std::vector<Vec3, PixelAllocator<Vec3>> pixels;

    ImageF() = default;
    /// All pixels black.
    ImageF(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h), Vec3{}) {}
    /// Pixels left unset: for producers that write every pixel.
    static ImageF uninitialized(int w, int h) {
        ImageF img;
        img.width = w;
        img.height = h;
        img.pixels.resize(size_t(w) * size_t(h));
        return img;
    }
    Vec3& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
    const Vec3& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

/// 8-bit image with 1..4 interleaved channels, top row first.
struct Image8 {
    int width = 0, height = 0, channels = 3;
    std::vector<uint8_t> pixels;

    Image8() = default;
    Image8(int w, int h, int c) : width(w), height(h), channels(c), pixels(size_t(w) * size_t(h) * size_t(c)) {}
    uint8_t* row(int y) { return pixels.data() + size_t(y) * size_t(width) * size_t(channels); }
    const uint8_t* row(int y) const { return pixels.data() + size_t(y) * size_t(width) * size_t(channels); }
};

/// Course colour quantisation: round(c·255) clamped to [0, 255].
inline uint8_t toByte(double c) {
    const double v = c * 255.0 + 0.5;
    return v <= 0.0 ? 0 : (v >= 255.0 ? 255 : uint8_t(v));
}

/// Quantises a float image to 8-bit RGB with toByte.
Image8 toImage8(const ImageF& img);
/// Quantises count pixels to RGB bytes (3·count of them) with toByte.
void toBytes(const Vec3* pixels, size_t count, uint8_t* rgb);

}  // namespace rays
