// POV-Ray items → the shapes of scene/shapes (torus, disc, polygon, superellipsoid, prism, lathe,
// sor, quadric, cubic, quartic, poly,
// polynomial), from the POV-Ray 3.7 reference's syntax of each.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "rays/pov/item_values.h"
#include "rays/scene/mesh.h"
#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays::pov {

/// Result of buildShape.
enum class ShapeBuild { NotAShape, Empty, Made };

/// Fills o's type and shape fields (and data, for polygons and polys) from the item's positional
/// values a and, for polynomial, its xyz entries. NotAShape: kind is not one of these shapes;
/// Empty: the shape has nothing to draw (a zero radius, points on a line). Throws Error prefixed
/// by `where` (FILE:LINE:COL) for values the reference forbids.
/// A bicubic_patch's triangles into mesh (not finalized) from its 16 points and its type, flatness,
/// u_steps, v_steps and uv_vectors entries. Throws Error prefixed by `where` when points are missing.
void buildBicubicPatch(const std::vector<const Value*>& a, const std::vector<const Entry*>& terms, Mesh& mesh,
                       const std::string& where);

/// A parametric's triangles into mesh (not finalized) from its three functions, its (u, v) corners
/// and its contained_by entry. NotAShape when a function is not a float function of the machine
/// (a pattern or pigment function: noted); throws Error prefixed by `where` when parts are missing.
ShapeBuild buildParametric(const std::vector<const Value*>& a, const std::vector<const Entry*>& terms, Mesh& mesh,
                           const std::string& where);

/// Shapes already built in this scene whose data a copy can share: julia fractals by their
/// parameters (each costs a proof of its bounds, julia_fractal.cpp), texts' outlines by font file,
/// string, thickness and offset (SceneBuilder::addText). The data stay the scene's.
struct ShapeMemo {
    std::map<std::vector<double>, const ShapeData*> julia;
    using TextKey = std::tuple<std::string, std::string, double, double, double, double>;
    std::map<TextKey, const TextShape*> texts;
};

/// memo: a julia fractal whose parameters it holds gets o.data from it and no data of its own;
/// a new one is added once the caller keeps data (its address does not change).
ShapeBuild buildShape(Kw kind, const std::vector<const Value*>& a, const std::vector<const Entry*>& terms, Object& o,
                      std::unique_ptr<ShapeData>& data, const std::string& where, ShapeMemo& memo);

}  // namespace rays::pov
