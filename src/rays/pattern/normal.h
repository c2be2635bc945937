// Normals compiled for rendering (POV-Ray 3.7 reference, "Normal", "Normal Map", "Slope Map",
// "Normals, Accuracy"): flat, immutable nodes built once with the scene. A node's pattern (kind,
// modifiers, transformations, warps, wave) is a node of the scene's PigmentTable whose map is
// unused; the normal adds its amount (bump_size), accuracy, slope_map, and the normals of its
// normal_map or block-pattern list. Evaluation is a switch: no virtual calls, no allocation.
#pragma once
#include <cstdint>
#include <vector>

#include "rays/pattern/pigment.h"

namespace rays::pattern {

enum class NormalKind : uint8_t {
    Pattern,  ///< any pattern: the gradient of its value (through the slope_map) tilts the normal
    Block,    ///< checker, hexagon, brick with a list of normals
    Map,      ///< normal_map: the pattern value blends the entries' normals
    Average,  ///< average: the weighted mean of the map's normals
    Bumps, Dents, Ripples, Waves, Wrinkles,  ///< POV-Ray's specialised normals (look-alikes)
    Quilted,  ///< quilted's own tilt (pattern/quilted.h, measured)
    BumpMap,  ///< bump_map: an image's heights (the pattern node is its ImagePattern), bumpMapTilt
};

/// One slope_map entry: at pattern value `value` the height and its slope (height per value).
struct SlopeEntry {
    double value = 0, height = 0, slope = 0;
};

/// A normal_map or list entry: the normal node (-1: the surface's own normal) at `value`.
struct NormalEntry {
    double value = 0;
    int node = -1;
};

struct NormalNode {
    NormalKind kind = NormalKind::Pattern;
    int pattern = -1;         ///< the PigmentTable node with the pattern and its modifiers
    Transform toPattern;      ///< linear part: enclosing space → pattern space (transformations only)
    Transform fromPattern;    ///< its inverse
    double amount = 0.5;      ///< the pattern's amount or bump_size
    double accuracy = 0.02;   ///< distance of the gradient's sample points (pattern space)
    /// no_bump_scale: the tilt is the world gradient's, so the bumps deepen as the pattern shrinks
    /// (by default a uniform scale keeps their depth).
    bool noBumpScale = false;
    int slopeBegin = 0, slopeCount = 0;  ///< NormalTable::slopes (none: height = value)
    int mapBegin = 0, mapCount = 0;      ///< NormalTable::entries
};

/// A normal as an object uses it: world space → texture space, then the node.
struct NormalRoot {
    Transform worldToTexture, textureToWorld;
    int node = -1;
};

struct NormalTable {
    std::vector<NormalNode> nodes;
    std::vector<SlopeEntry> slopes;
    std::vector<NormalEntry> entries;
    std::vector<NormalRoot> roots;

    /// Node n's normal at p (the enclosing space) for the unit surface normal `normal` there;
    /// stretch: the length the world normal took on its way into the enclosing space before it
    /// was made a unit vector again (product over the spaces above), which no_bump_scale undoes.
    Vec3 perturb(const PigmentTable& patterns, int n, Vec3 p, Vec3 normal, double stretch = 1) const;
    /// Root r's unit normal at world point P for the unit surface normal N (world space).
    Vec3 atRoot(const PigmentTable& patterns, int r, Vec3 P, Vec3 N) const;
    /// The height a pattern node (NormalKind::Pattern) gives at p (pattern value, wave and
    /// slope_map), enclosing space.
    double height(const PigmentTable& patterns, const NormalNode& node, Vec3 p) const;
};

/// Measured with POV-Ray 3.7: `normal { gradient x B }` on a plane facing −z tilts the normal by
/// atan(kPovBumpScale·B) away from +x (cos of the tilt 0.6 at B = 10, 0.0748 at B = 100).
inline constexpr double kPovBumpScale = 2.0 / 15.0;

}  // namespace rays::pattern
