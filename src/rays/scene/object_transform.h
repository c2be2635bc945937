// The transform an object's file wrote, recovered from what prepareObject keeps (for sceneinfo).
#pragma once
#include "rays/math/transform.h"
#include "rays/scene/object.h"

namespace rays {

/// The object → world transform M the file wrote (identity when none), recovered from toObject.
Transform objectToWorld(const Object& o);

}  // namespace rays
