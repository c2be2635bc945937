// The edge type of each line pixel, for the `edgetype` AOV (docs/aov.md): which kinds of line
// (EdgeType bits, docs/edges.md) run through a pixel the lines cover.
#pragma once
#include <vector>

#include "rays/npr/edge_settings.h"
#include "rays/npr/feature_lines.h"

namespace rays {

/// Per pixel (top row first): where lines.coverage > 0, the EdgeType bits of e.types that hold
/// between the pixel's centre record and a centre within the line's reach (⌈width/2 + ½⌉
/// pixels, as far as a line stamp spreads); 0 elsewhere. centre: the records the lines used.
std::vector<float> lineEdgeTypes(const LineRecords& centre, const LineCoverage& lines, const EdgeSettings& e);

}  // namespace rays
