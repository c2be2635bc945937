// Image textures: pigment image maps, tangent-space normal maps and bump (height) maps.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rays/math/vec3.h"

namespace rays {

/// Texels keep the 8 bits per channel they came with (as POV-Ray keeps them); a 256-entry table
/// turns a byte into its value (the gamma decoding included).
struct Texture {
    std::string path;
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;           ///< width·height·3 bytes, top row first
    std::array<float, 256> decode{};    ///< value of a byte: (b/255)^gamma

    /// Texel (x, y) with x, y wrapped into the image.
    Vec3 texel(int x, int y) const;
    /// Colour at texture coordinates (u, v) ∈ [0,1)², v = 0 at the BOTTOM row (POV-Ray);
    /// bilinear between the four nearest texel centres, else the nearest texel. Repeats.
    Vec3 sample(double u, double v, bool bilinear) const;
    /// Bytes held.
    uint64_t bytes() const { return rgb.capacity() + sizeof(Texture); }
};

/// Loads an image file as a texture; gamma ≠ 1 decodes texels as c^gamma. Throws Error naming
/// the path when it cannot be read.
Texture loadTexture(const std::string& path, double gamma);

}  // namespace rays
