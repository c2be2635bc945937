// RenderSettings: every option that changes the rendered image, with the course defaults.
#pragma once
#include <cstdint>

namespace rays {

enum class ShadingModel { BlinnPhong, CookTorrance, Flat, Normals };

struct RenderSettings {
    int width = 640;
    int height = 480;
    ShadingModel shading = ShadingModel::BlinnPhong;
    bool fresnel = false;      ///< -fresnel: Schlick Fresnel moves weight between reflection and transmission
    bool beers = false;        ///< -beers: refracted colour attenuated by exp(−(1−C)·0.15·d)
    int maxDepth = 6;          ///< secondary-ray recursion limit (primary rays are depth 0)
    int gridSamples = 1;       ///< -ss=N: N×N regular sub-pixel grid (course supersampling)
    int spp = 0;               ///< --spp N (> 0 overrides gridSamples): jittered samples, stratified when N is square
    uint64_t seed = 0;         ///< seeds the per-sample hash RNG (jittered sampling only)
    int threads = 0;           ///< worker threads; 0 = all hardware threads
    int cameraIndex = 0;       ///< which camera of the scene
};

/// Name printed by the course commands ("Blinn-Phong", "Cook-Torrance", "Flat", "Normals").
const char* shadingName(ShadingModel m);

}  // namespace rays
