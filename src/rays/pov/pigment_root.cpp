// SceneBuilder::pigmentRoot: a look's compiled pattern placed in the world (kept apart from
// scene_builder.cpp, which is mostly about objects).
#include "rays/pov/scene_builder.h"

namespace rays::pov {

int SceneBuilder::pigmentRoot(const Appearance& look) {
    if (look.pigmentNode < 0 || look.pigmentToObject.determinant() == 0) return -1;
    scene_.pigments.roots.push_back(pattern::PigmentRoot{look.pigmentToObject.inverse(), look.pigmentNode});
    return int(scene_.pigments.roots.size()) - 1;
}

}  // namespace rays::pov
