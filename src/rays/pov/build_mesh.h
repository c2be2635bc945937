// POV-Ray mesh and mesh2 items → Rays' indexed Mesh (POV-Ray 3.7 reference, "Mesh", "Mesh2").
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "rays/pov/item_values.h"
#include "rays/scene/mesh.h"

namespace rays::pov {

/// The textures a mesh's own triangles name: a mesh triangle's `texture { }`, or mesh2's
/// texture_list entry that face_indices gives after a face (POV-Ray 3.7 reference, "Mesh", "Mesh2").
struct FaceTextures {
    std::vector<const Item*> textures;  ///< the texture items named (each once)
    std::vector<int32_t> face;          ///< per triangle of the Mesh: its index in textures, −1 none (the mesh's)
    std::vector<int32_t> corners;       ///< when a face names three (one per corner): 3 per triangle, −1 for the others
};

/// The triangles of a mesh item (triangle and smooth_triangle entries, with uv_vectors), or of a
/// mesh2 item (vertex/normal/uv vectors and their index lists), and in `textures` (when given)
/// the textures they name. Empty triangles are dropped. Gives null and the reason in `problem`
/// (empty when fine) for an index out of range.
std::unique_ptr<Mesh> meshFromItem(const Item& mesh, std::string& problem, FaceTextures* textures = nullptr);

}  // namespace rays::pov
