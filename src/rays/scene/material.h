// Surface appearance of an object: pigment colour with filter, and the course finish values.
#pragma once
#include "rays/math/vec3.h"

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
    bool hasSpecular = false, hasRoughness = false, hasReflection = false, hasIor = false,
         hasRefraction = false, hasMetallic = false;  ///< written in the file (for sceneinfo)
};

}  // namespace rays
