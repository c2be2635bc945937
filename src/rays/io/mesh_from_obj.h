// Turns a loaded OBJ into an indexed Mesh.
#pragma once
#include <memory>

#include "rays/io/obj_loader.h"
#include "rays/scene/mesh.h"

namespace rays {

/// Copies positions, normals and uvs with their per-face indices (faces missing normals or uvs
/// when others have them get the face normal / uv (0, 0)) and finalizes the mesh (BVH built).
std::unique_ptr<Mesh> meshFromObj(const ObjMesh& obj);

}  // namespace rays
