// Light sources. The course uses point lights with an RGB colour.
#pragma once
#include "rays/math/vec3.h"

namespace rays {

struct PointLight {
    Vec3 position;
    Vec3 color{1, 1, 1};
};

}  // namespace rays
