// The colours POV-Ray 3.7 writes: a working-space colour c becomes sRGB(c^assumed_gamma) in the
// image file, or (c^assumed_gamma)^(1/File_Gamma) for a File_Gamma number (measured:
// docs/povray-lighting.md, "Output"). Applied to each final pixel of scenes
// with Scene::pov.enabled, before the PNG stream, feature lines and post filters see the image.
#pragma once
#include "rays/math/vec3.h"

namespace rays {

/// sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1].
double srgbEncode(double linear);

/// The displayed colour of working-space colour c: each channel clamped to [0, 1], raised to
/// assumedGamma (to linear light) and sRGB-encoded, or with fileGamma > 0 (POV-Ray's File_Gamma)
/// raised to 1/fileGamma; assumedGamma 0 (legacy scenes without assumed_gamma, `assumed_gamma
/// srgb`) leaves the clamped colour as it is whatever fileGamma says (measured).
Vec3 povOutputColor(Vec3 c, double assumedGamma, double fileGamma = 0);

}  // namespace rays
