// Image textures: pigment image maps, tangent-space normal maps and bump (height) maps.
#pragma once
#include <string>
#include <vector>

#include "rays/math/vec3.h"

namespace rays {

struct Texture {
    std::string path;
    int width = 0, height = 0;
    std::vector<float> rgb;  ///< width·height·3 values in [0, 1], top row first

    /// Texel (x, y) with x, y wrapped into the image.
    Vec3 texel(int x, int y) const;
    /// Colour at texture coordinates (u, v) ∈ [0,1)², v = 0 at the BOTTOM row (POV-Ray);
    /// bilinear between the four nearest texel centres, else the nearest texel. Repeats.
    Vec3 sample(double u, double v, bool bilinear) const;
};

/// Loads an image file as a texture; gamma ≠ 1 decodes texels as c^gamma. Throws Error naming
/// the path when it cannot be read.
Texture loadTexture(const std::string& path, double gamma);

}  // namespace rays
