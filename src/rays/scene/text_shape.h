// The geometry of POV-Ray's `text` object (reference 3.4.5.1.16 "Text"): glyph outlines in the
// x-y plane, each extruded from its z0 to z0 + thickness. Outlines are made of lines and quadratic
// Béziers split into pieces monotone in y, all contours turning so that the filled side is on the
// left (counter-clockwise outer contours). A point is inside a glyph by the nonzero winding rule.
//
// Rays are intersected exactly: the caps (planes z0 and z0 + thickness, kept where the point is
// inside the outline) and the walls (the ray's x-y projection against each segment: a line
// equation for lines, a quadratic in the curve parameter for Béziers). Glyphs are sorted by their
// left edge with a running maximum of their right edges, so a ray tests only the glyphs whose
// x range its own x range meets (binary search), then their boxes. No heap allocation per ray.
#pragma once
#include <cstdint>
#include <vector>

#include "rays/geometry/ray.h"

namespace rays {

/// One outline piece in glyph-layout units: a line a→b, or a quadratic Bézier a→c→b when quad,
/// with y monotone along it.
struct TextSegment {
    double ax = 0, ay = 0, cx = 0, cy = 0, bx = 0, by = 0;
    bool quad = false;
};

/// One laid-out glyph: its outline segments [first, first + count) and its box.
struct TextGlyph {
    uint32_t first = 0, count = 0;
    double xMin = 0, yMin = 0, xMax = 0, yMax = 0;
    double z0 = 0;  ///< front face; the back face is z0 + thickness
};

struct TextShape {
    std::vector<TextSegment> segments;
    std::vector<TextGlyph> glyphs;       ///< after finish(): sorted by xMin, empty ones dropped
    std::vector<double> xMaxPrefix;      ///< after finish(): max xMax of glyphs[0..i]
    double thickness = 1;                ///< ≥ 0
    Bounds bounds;                       ///< after finish(): the box of all glyphs (may be widened after)

    /// Adds a contour segment to the glyph being built (the last of glyphs): lines as given,
    /// quadratic Béziers split where y turns. Contours must fill to their left.
    void addLine(double ax, double ay, double bx, double by);
    void addQuad(double ax, double ay, double cx, double cy, double bx, double by);
    /// Call once all glyphs are added: drops empty glyphs, sets boxes, order and bounds.
    void finish();
};

/// Nearest hit of ray r (text space) with t in (tMin, tMax): t and the outward unit normal.
bool intersectText(const TextShape& s, const Ray& r, double tMin, double tMax, double& t, Vec3& normal);

/// Whether text-space point p is strictly inside the solid text.
bool insideText(const TextShape& s, Vec3 p);

/// Nonzero-rule winding number of glyph g around point (x, y) (0: outside its outline).
int glyphWinding(const TextShape& s, const TextGlyph& g, double x, double y);

}  // namespace rays
