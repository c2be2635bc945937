// The HDR side of `rays render`: -o out.exr (colour and AOVs as channels of one file), -o out.pfm,
// and --aov next to other outputs (one PFM per AOV). Docs: docs/aov.md.
#pragma once
#include <string>

#include "rays/image/image.h"
#include "rays/io/hdr_io.h"
#include "rays/npr/feature_lines.h"
#include "rays/render/aov.h"

namespace rays::cli {

/// True when output is written from the linear float image (.exr, .pfm).
bool isHdrOutput(const std::string& output);

/// Where AOV `bit` goes next to a non-EXR output: "out.png" → "out.depth.pfm".
std::string aovFilePath(const std::string& output, AovBit bit);

/// The EXR's channels: R, G, B (half when half), then the AOVs of `kinds` as float channels —
/// Z, N.X N.Y N.Z, albedo.R albedo.G albedo.B, objectId, materialId, coverage, edgeType. lines may be
/// null (no lines drawn: coverage 0).
HdrImage exrImage(const ImageF& img, bool half, const AovBuffers& aov, const LineCoverage* lines, unsigned kinds);

/// The one AOV `bit` as a 1- or 3-channel image (for its PFM file).
HdrImage aovImage(const AovBuffers& aov, const LineCoverage* lines, AovBit bit);

/// The colour alone as R, G, B floats (for a PFM output).
HdrImage colourImage(const ImageF& img, bool half);

}  // namespace rays::cli
