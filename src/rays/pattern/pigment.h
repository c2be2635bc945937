// Pigments compiled for rendering: flat, immutable nodes built once with the scene (POV-Ray 3.7
// reference, "Pigment", "Color Maps", "Pigment Maps", "Average"). A node is a pattern with its
// transformation, turbulence, wave and map (or block-pattern list); map entries are colours or
// other nodes of the same table. Evaluation is a switch over the node's kind: no virtual calls,
// no allocation.
#pragma once
#include <memory>
#include <vector>

#include "rays/math/transform.h"
#include "rays/pattern/color_map.h"
#include "rays/pattern/image_map.h"
#include "rays/pattern/pattern.h"
#include "rays/pattern/warp.h"
#include "rays/pattern/wave.h"

namespace rays::pattern {

struct PigmentNode {
    PatternKind kind = PatternKind::Solid;
    bool transformed = false;
    Transform toPattern;  ///< the enclosing space → this pigment's pattern space (when transformed)
    int warpBegin = 0, warpCount = 0;  ///< PigmentTable::warps replacing toPattern when there are warps
    PatternParams params;
    Wave wave;
    int mapBegin = 0, mapCount = 0;  ///< PigmentTable::entries: the map, or a block pattern's list
    Rgbft color;                     ///< Solid's colour
    int image = -1;                  ///< ImageMap: PigmentTable::images
};

/// A pigment as an object uses it: world space → texture space, then the node.
struct PigmentRoot {
    Transform worldToTexture;
    int node = -1;
    /// POV-Ray's uv_mapping: the pattern is looked up at the surface's (u, v, 0) (when the surface
    /// has texture coordinates) moved by worldToTexture, instead of at the world point.
    bool uv = false;
};

struct PigmentTable {
    std::vector<PigmentNode> nodes;
    std::vector<MapEntry> entries;
    std::vector<PigmentRoot> roots;
    std::vector<std::shared_ptr<const fn::Program>> programs;  ///< function patterns' programs, kept alive
    std::vector<WarpStep> warps;  ///< each node's steps, outermost (written last) first
    std::vector<ImageMap> images;  ///< image_map pigments (their images shared per file)
    std::vector<std::shared_ptr<const DensityGrid>> grids;  ///< density_file patterns' grids, kept alive
    std::vector<std::shared_ptr<const PatternObject>> objects;  ///< object patterns' objects, kept alive

    /// Decodes the image maps' texels into the scene's working gamma (assumed_gamma; 0 legacy).
    void setWorkingGamma(double assumedGamma) {
        for (ImageMap& m : images) m.setWorkingGamma(assumedGamma);
    }

    /// The colour of node n at p, p in the space enclosing the node. N: the world normal facing
    /// the viewer at the surface point, for the slope and aoi patterns, D the direction of the
    /// ray that met it, for aoi (both zero off surfaces).
    Rgbft evaluate(int n, Vec3 p, Vec3 N = {}, Vec3 D = {}) const;
    /// The colour of root r at the world point p.
    /// uv: the surface's (u, v, 0), when it has texture coordinates (for uv-mapped roots).
    Rgbft atRoot(int r, Vec3 world, Vec3 N = {}, const Vec3* uv = nullptr, Vec3 D = {}) const {
        const PigmentRoot& root = roots[size_t(r)];
        return evaluate(root.node, root.worldToTexture.point(root.uv && uv ? *uv : world), N, D);
    }
    /// The value of node n's pattern at p (p in the space enclosing the node), as a pattern
    /// function gives it: after the node's transformations, warps, turbulence and wave, its map
    /// ignored; a block pattern's list index (0, 1 or 2); 0 for nodes without a pattern value.
    double value(int n, Vec3 p, Vec3 N = {}, Vec3 D = {}) const;
    /// The value of node's pattern at q (its pattern space), turbulence included, before the
    /// wave: patternValue, or for pigment_pattern the grey of its pigment (POV-Ray 3.7 reference,
    /// "Pigment Pattern"; measured: 0.297·r + 0.589·g + 0.114·b, filter and transmit ignored).
    double rawValue(const PigmentNode& node, Vec3 q, Vec3 N = {}, Vec3 D = {}) const;
    /// True when some colour of node n filters or transmits.
    bool mayLetLightThrough(int n) const;
    /// Where node n's pattern puts p (p in the space enclosing the node): the place in its map, or
    /// for a block pattern the entry of its list (lo == hi). For nodes with a pattern and a map.
    MapPlace place(int n, Vec3 p, Vec3 N = {}, Vec3 D = {}) const;
    /// place() of root r's node at the world point.
    MapPlace placeAtRoot(int r, Vec3 world, Vec3 N = {}, const Vec3* uv = nullptr, Vec3 D = {}) const {
        const PigmentRoot& root = roots[size_t(r)];
        return place(root.node, root.worldToTexture.point(root.uv && uv ? *uv : world), N, D);
    }

private:
    /// material_map's entry at q (its pattern space): the texel's index modulo the entries.
    int materialEntry(const PigmentNode& node, Vec3 q) const;
    /// p (in the space enclosing node) moved into the node's pattern space: warps or transformation.
    Vec3 inNodeSpace(const PigmentNode& node, Vec3 p) const;
};

}  // namespace rays::pattern
