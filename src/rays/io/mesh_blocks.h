// The bodies of POV-Ray's inline meshes, read with a TokenReader positioned after the '{':
// mesh { triangle { ... } smooth_triangle { ... } ... } and mesh2 { vertex_vectors { } ... }.
// The caller reads the rest of the object block (modifiers, '}') and finalizes the mesh.
#pragma once
#include <memory>

#include "rays/io/token_reader.h"
#include "rays/scene/mesh.h"

namespace rays::scenetext {

/// mesh { triangle { <a>, <b>, <c> [uv_vectors <uv>, <uv>, <uv>] }
///        smooth_triangle { <a>, <na>, <b>, <nb>, <c>, <nc> [uv_vectors ...] } ... }: reads the
/// triangles up to the first other token.
std::unique_ptr<Mesh> readMeshTriangles(TokenReader& r);

/// mesh2 { vertex_vectors { } [normal_vectors { }] [uv_vectors { }] face_indices { }
///         [normal_indices { }] [uv_indices { }] } (zero-based indices): reads the sections up to
/// the first other token.
std::unique_ptr<Mesh> readMesh2Sections(TokenReader& r);

}  // namespace rays::scenetext
