// Parameters of a shape that do not fit in Object's fixed fields (polygon edges, polynomial
// coefficients), owned by the Scene; Object::data points at them.
#pragma once
#include <vector>

#include "rays/geometry/ray.h"

namespace rays {

struct ShapeData {
    std::vector<double> values;  ///< the shape's numbers (each shape's header says their layout)
    int order = 0;               ///< Poly only: the polynomial's degree
    Bounds bounds;               ///< object-space bounds (empty: unbounded)
};

}  // namespace rays
