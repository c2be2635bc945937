// Parameters of a shape that do not fit in Object's fixed fields (polygon edges, polynomial
// coefficients), owned by the Scene; Object::data points at them.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "rays/geometry/ray.h"
#include "rays/scene/object.h"

namespace rays {

namespace fn {
struct Program;
}

/// A node of a box tree over a shape's pieces: a leaf holds pieces [first, first + count), an inner
/// node (count 0) its two children at nodes first and first + 1.
struct BoxNode {
    Bounds box;
    int first = 0, count = 0;
};

struct ShapeData {
    std::vector<double> values;  ///< the shape's numbers (each shape's header says their layout)
    int order = 0;               ///< Poly only: the polynomial's degree
    bool conic = false;          ///< Prism only: conic_sweep (the outline scaled by the height)
    Bounds bounds;               ///< object-space bounds (empty: unbounded)
    std::vector<BoxNode> tree;   ///< Blob only: its components' box tree (root first)
    std::vector<Object> parts;   ///< Blob, Mesh: copies of the object with a component's or a face's texture (ShapeHit::part)
    std::vector<int32_t> faceParts;  ///< Mesh only: each triangle's texture, an index in parts (−1: the mesh's own)
    std::vector<int32_t> cornerParts;  ///< Mesh only: 3 per triangle, its corners' textures in parts (−1: none)
    std::shared_ptr<const fn::Program> function;  ///< Isosurface only: its function (rays/fn)
};

}  // namespace rays
