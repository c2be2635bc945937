// RenderSettings: every option that changes the rendered image, with the course defaults.
#pragma once
#include <cstdint>

#include "rays/scene/shading_model.h"

namespace rays {


/// How the samples of a pixel are placed.
enum class AaMode {
    Grid,        ///< regular k×k grid, k = round(√spp) (the course's -ss=N is Grid with N×N)
    Random,      ///< spp uniform random positions
    Stratified,  ///< k×k grid cells, one jittered sample in each
};

/// Reconstruction filter: how samples are weighted by their offset from the pixel centre.
enum class PixelFilter {
    Box,       ///< samples over the pixel, equal weights
    Tent,      ///< samples within 1 pixel of the centre, weight (1−|x|)(1−|y|)
    Gaussian,  ///< samples within 1.5 pixels, weight exp(−r²/(2·0.5²))
};

struct RenderSettings {
    int width = 640;
    int height = 480;
    ShadingModel shading = ShadingModel::BlinnPhong;
    bool fresnel = false;      ///< -fresnel: Schlick Fresnel moves weight between reflection and transmission
    bool beers = false;        ///< -beers: refracted colour attenuated by exp(−(1−C)·0.15·d)
    int maxDepth = 6;          ///< secondary-ray recursion limit (primary rays are depth 0)

    AaMode aa = AaMode::Grid;  ///< sample placement
    int spp = 1;               ///< samples per pixel; 1 with Grid is the pixel centre (course)
    PixelFilter filter = PixelFilter::Box;
    bool aaEdges = false;      ///< one sample per pixel, then spp samples only where ids or shadows change
    double aaThreshold = -1;   ///< ≥ 0 with aaEdges: POV-Ray's rule instead, where the colour changes by more (renderer.h)
    double aaGamma = 2.5;      ///< colours compared as linear^(1/aaGamma) under aaThreshold (POV-Ray's Antialias_Gamma)
    double fileGamma = 0;      ///< POV-Ray scenes' File_Gamma: 0 sRGB (the default), else the image holds linear^(1/fileGamma)
    uint64_t seed = 0;         ///< seeds the per-sample hash RNG

    int areaSamples = 0;       ///< > 0: area lights use this many samples per axis instead of the scene's
    double aperture = -1;      ///< ≥ 0: lens radius overriding the camera's aperture
    double focalDistance = -1; ///< > 0: focal distance overriding the camera's focal_point
    int dofSamples = 0;        ///< > 0: samples per pixel with depth of field, overriding blur_samples

    bool gi = false;           ///< course part 6: the mean of cosine-weighted hemisphere samples replaces the ambient term
    bool giPhysical = false;   ///< with gi: the Lambertian estimate kd·C·mean instead of the course's plain mean
    int giSamples[2] = {64, 16};  ///< samples at the first and at later bounces
    int giBounces = 2;         ///< levels of indirect light

    int threads = 0;           ///< worker threads; 0 = all hardware threads
    int cameraIndex = 0;       ///< which camera of the scene
    /// A part of the image to render (POV-Ray's Start_Row, End_Row, Start_Column, End_Column):
    /// pixel columns regionX0..regionX1 and rows regionY0..regionY1 (inclusive, 0-based, the top
    /// row 0); the other pixels are black. regionX1 < 0: the whole image.
    int regionX0 = 0, regionY0 = 0, regionX1 = -1, regionY1 = -1;
    bool wholeImage() const { return regionX1 < 0; }
    bool inRegion(int x, int y) const {
        return wholeImage() || (x >= regionX0 && x <= regionX1 && y >= regionY0 && y <= regionY1);
    }
    bool linearOutput = false; ///< POV-Ray scenes: pixels in linear light (povLinearColor, HDR files), not encoded
};


}  // namespace rays
