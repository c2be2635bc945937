// Surface appearance of an object: pigment colour with filter, and the course finish values.
#pragma once
#include "rays/math/vec3.h"
#include "rays/scene/shading_model.h"

namespace rays {

struct Material {
    Vec3 color{0, 0, 0};     ///< pigment colour (linear, unclamped)
    double filter = 0;       ///< rgbf filter: > 0 makes the object refract
    double ambient = 0;      ///< ka: ambient = ka·C
    double diffuse = 0;      ///< kd
    double specular = 0;     ///< ks
    double roughness = 1;    ///< course default 1; Blinn-Phong exponent 2/roughness² − 2, GGX α = roughness²
    double reflection = 0;   ///< mirror weight r
    double ior = 1;          ///< index of refraction
    double metallic = 0;     ///< Cook-Torrance only: blends F0 toward 1 and removes diffuse
    double refraction = 0;   ///< accepted and ignored (course): refraction follows filter
    double sigma = 20;       ///< Oren-Nayar surface roughness σ in degrees (finish { sigma S })
    int shading = -1;        ///< ShadingModel of this object (`shading NAME`), −1 = the render's
    int pov = -1;            ///< POV-Ray scenes: index into Scene::povSurfaces (lit by POV-Ray's model)

    // Texture maps (indices into Scene::textures, −1 = none).
    int pigmentMap = -1;     ///< image_map: replaces the pigment colour
    int mapType = 0;         ///< 0 planar, 1 spherical, 2 cylindrical, 3 uv (mesh coordinates)
    bool mapOnce = false;    ///< outside [0,1]² the plain pigment colour shows (else the map repeats)
    bool mapBilinear = false;///< interpolate 2: bilinear filtering (else nearest texel)
    int normalMap = -1;      ///< normal_map: tangent-space RGB normals, +Z up
    int bumpMap = -1;        ///< bump_map: greyscale heights
    int normalMapType = 0;   ///< map type of the normal / bump map
    double normalStrength = 1; ///< normal_map strength (scales the tangent-plane tilt)
    double bumpSize = 1;     ///< bump_map bump_size
    int pigmentTransform = -1; ///< index into Scene::textureTransforms (pigment { ... scale rotate translate })
    int normalTransform = -1;  ///< same for the normal block
    bool hasSpecular = false, hasRoughness = false, hasReflection = false, hasIor = false,
         hasRefraction = false, hasMetallic = false;  ///< written in the file (for sceneinfo)
};

}  // namespace rays
