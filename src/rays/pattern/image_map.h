// POV-Ray's image_map pigment (POV-Ray 3.7 reference, "Image Map", "Bitmap Modifiers"): an 8-bit
// image projected onto the object — map_type 0 planar (the unit square x, y in [0, 1] of the xy
// plane, repeated unless `once`), 1 spherical, 2 cylindrical, 5 torus — with `interpolate 2`
// (bilinear) or `4` (normalised distance), `filter`/`transmit` (all texels or one palette entry)
// and the image's alpha as transmit. Texels stay 8-bit; a 256-entry table per map decodes them
// into the scene's working gamma.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "rays/image/image.h"
#include "rays/pattern/color_map.h"

namespace rays::pattern {

/// How an image file's values are encoded (POV-Ray 3.7 tutorial, "Gamma in Input Images").
struct FileGamma {
    enum class Kind : uint8_t { Linear, Srgb, Power } kind = Kind::Srgb;
    double gamma = 1;  ///< Power: the value is v^gamma in linear light
};

/// One palette entry's filter or transmit (`filter N, F`): the texels whose colour is palette
/// entry N's get it.
struct PaletteAmount {
    uint8_t r = 0, g = 0, b = 0;
    bool transmit = false;
    float amount = 0;
};

struct ImageMap {
    std::shared_ptr<const Image8> image;  ///< 1..4 channels, top row first (shared per file)
    int mapType = 0;                      ///< 0 planar, 1 spherical, 2 cylindrical, 5 torus
    int interpolate = 0;                  ///< 0 nearest, 2 bilinear, 4 normalised distance
    bool once = false;
    double filterAll = 0, transmitAll = 0;
    std::vector<PaletteAmount> palette;  ///< per-entry amounts, matched by colour
    double majorRadius = 1;              ///< map_type 5's torus
    FileGamma fileGamma;
    std::array<float, 256> decode{};  ///< byte → working-space value (setWorkingGamma)

    /// Fills decode for the scene's assumed_gamma (0: legacy scene, bytes used as they are).
    void setWorkingGamma(double assumedGamma);
    bool useAlpha = false;               ///< image_pattern's use_alpha
    std::array<float, 256> patternDecode{};  ///< image_pattern: byte → value (setPatternGamma)

    /// image_pattern's decoding: the bytes as they are, or to the power of an explicit `gamma G`
    /// (measured: POV-Ray's image_pattern ignores the file's own gamma).
    void setPatternGamma(double g);

    /// The colour at p (the image map's pattern space).
    Rgbft color(Vec3 p) const;
    /// image_pattern's value at p (POV-Ray 3.7 reference, "Image Pattern"; measured with POV-Ray's
    /// pattern functions on 4×2 images): a colour texel's grey 0.297·r + 0.589·g + 0.114·b of its
    /// decoded channels, a grey texel's value, or with use_alpha the transparency 1 − alpha (0
    /// without an alpha channel); placed and interpolated as the colour; 0 outside a `once` image.
    /// POV-Ray re-quantises grey images (80 reads as 79/255): not reproduced.
    double value(Vec3 p) const;
    /// material_map's index at p: the nearest texel's palette index (an image of indices) or its
    /// grey as a byte, 0 outside a `once` image.
    int materialIndex(Vec3 p) const;
    /// image_pattern's value at texture coordinates (u, v), interpolated as value() (u, v outside
    /// [0, 1) wrap around the image).
    double valueAt(double u, double v) const;
    /// Texture coordinates (u, v) ∈ [0, 1)² (v = 0 at the bottom row) of p for the map type;
    /// false where `once` leaves p outside the image.
    bool coordinates(Vec3 p, double& u, double& v) const;
    /// Texel (x, y) (y = 0 the top row) as a colour, with filter and transmit.
    Rgbft texel(int x, int y) const;
    /// Texel (x, y) as image_pattern reads it.
    double texelValue(int x, int y) const;

    /// Up to four texels and their weights about texture coordinates (u, v).
    struct Taps {
        int x[4], y[4];
        double w[4];
        int count = 0;
    };
    Taps taps(double u, double v) const;
};

}  // namespace rays::pattern
