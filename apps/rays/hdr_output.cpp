#include "hdr_output.h"

namespace rays::cli {
namespace {

constexpr AovBit kOrder[] = {kAovDepth, kAovNormal, kAovAlbedo, kAovObjectId, kAovMaterialId, kAovCoverage,
                             kAovEdgeType};

void addVec(HdrImage& out, const std::vector<Vec3>& v, const char* const names[3], bool half = false) {
    for (int c = 0; c < 3; ++c) {
        HdrChannel& ch = out.add(names[c], half);
        for (size_t i = 0; i < v.size(); ++i) ch.values[i] = float(v[i][c]);
    }
}

// Appends AOV bit's channels (named as in the EXR).
void addAov(HdrImage& out, const AovBuffers& a, const LineCoverage* lines, AovBit bit) {
    static const char* const kNormal[3] = {"N.X", "N.Y", "N.Z"};
    static const char* const kAlbedo[3] = {"albedo.R", "albedo.G", "albedo.B"};
    switch (bit) {
        case kAovDepth: out.add("Z").values.assign(a.depth.begin(), a.depth.end()); break;
        case kAovNormal: addVec(out, a.normal, kNormal); break;
        case kAovAlbedo: addVec(out, a.albedo, kAlbedo); break;
        case kAovObjectId: out.add("objectId").values = a.objectId; break;
        case kAovMaterialId: out.add("materialId").values = a.materialId; break;
        case kAovCoverage: {
            HdrChannel& ch = out.add("coverage");  // zeros without lines
            if (lines && lines->width == out.width && lines->height == out.height)
                ch.values.assign(lines->coverage.begin(), lines->coverage.end());
            break;
        }
        case kAovEdgeType: {
            HdrChannel& ch = out.add("edgeType");  // zeros without lines
            if (a.edgeType.size() == ch.values.size()) ch.values = a.edgeType;
            break;
        }
    }
}

}  // namespace

bool isHdrOutput(const std::string& output) { return isExrPath(output) || isPfmPath(output); }

std::string aovFilePath(const std::string& output, AovBit bit) {
    const size_t slash = output.find_last_of('/');
    const size_t dot = output.find_last_of('.');
    const std::string stem = dot != std::string::npos && (slash == std::string::npos || dot > slash) ? output.substr(0, dot) : output;
    return stem + "." + aovName(bit) + ".pfm";
}

HdrImage colourImage(const ImageF& img, bool half) {
    HdrImage out(img.width, img.height);
    static const char* const kRgb[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        HdrChannel& ch = out.add(kRgb[c], half);
        for (size_t i = 0; i < img.pixels.size(); ++i) ch.values[i] = float(img.pixels[i][c]);
    }
    return out;
}

HdrImage exrImage(const ImageF& img, bool half, const AovBuffers& aov, const LineCoverage* lines, unsigned kinds) {
    HdrImage out = colourImage(img, half);
    for (AovBit bit : kOrder)
        if (kinds & bit) addAov(out, aov, lines, bit);
    return out;
}

HdrImage aovImage(const AovBuffers& aov, const LineCoverage* lines, AovBit bit) {
    HdrImage out(aov.width, aov.height);
    addAov(out, aov, lines, bit);
    return out;
}

}  // namespace rays::cli
