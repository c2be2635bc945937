// POV-Ray mesh and mesh2 items → Rays' indexed Mesh (POV-Ray 3.7 reference, "Mesh", "Mesh2").
#pragma once
#include <memory>
#include <string>

#include "rays/pov/item_values.h"
#include "rays/scene/mesh.h"

namespace rays::pov {

/// The triangles of a mesh item (triangle and smooth_triangle entries, with uv_vectors), or of a
/// mesh2 item (vertex/normal/uv vectors and their index lists). Empty triangles are dropped.
/// Throws std::string-free Error-compatible messages through `problem` (empty when fine).
std::unique_ptr<Mesh> meshFromItem(const Item& mesh, std::string& problem);

}  // namespace rays::pov
