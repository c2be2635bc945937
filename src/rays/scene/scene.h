// Scene: everything a scene file describes. Built by the parser, then immutable while rendering.
#pragma once
#include <string>
#include <vector>

#include "rays/npr/edge_settings.h"
#include "rays/scene/camera.h"
#include "rays/scene/light.h"
#include "rays/scene/object.h"

namespace rays {

struct Scene {
    std::string fileName;
    std::vector<Camera> cameras;  ///< the first is the default; later ones are alternatives
    std::vector<Light> lights;
    std::vector<Object> objects;  ///< course object ID = index + 1
    EdgeSettings edges;           ///< feature lines asked for by an `edges { }` block (CLI overrides)
};

}  // namespace rays
