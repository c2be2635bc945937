// Procedural texture images for tests, demos and `rays assets`: checkers, bricks, and a
// tangent-space normal map derived from a height image.
#pragma once
#include "rays/image/image.h"

namespace rays {

/// size×size RGB checker with n×n squares of colours a and b (0..255 each).
Image8 checkerImage(int size, int n, const uint8_t a[3], const uint8_t b[3]);

/// Greyscale brick heights (255 on bricks, sloping to 0 in the mortar), w×h, `rows` courses.
Image8 brickHeightImage(int w, int h, int rows);

/// Brick colours matching brickHeightImage: varied reds on bricks, grey mortar.
Image8 brickColorImage(int w, int h, int rows);

/// Tangent-space normal map (+Z up, RGB = (n·127 + 128)) of a greyscale height image.
Image8 normalMapFromHeight(const Image8& height, double strength);

}  // namespace rays
