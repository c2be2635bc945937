#include "rays/npr/edge_types.h"

#include <algorithm>
#include <cmath>

#include "rays/npr/edge_classify.h"

namespace rays {

std::vector<float> lineEdgeTypes(const LineRecords& centre, const LineCoverage& lines, const EdgeSettings& e) {
    const int W = lines.width, H = lines.height;
    std::vector<float> out(size_t(W) * size_t(H), 0.0f);
    const EdgeThresholds th = thresholdsFor(e);
    const int reach = int(std::ceil(e.width / 2 + 0.5));
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (lines.at(x, y) <= 0) continue;
            const EdgeRecord& c = centre.rec[size_t(y) * W + x];
            uint32_t bits = 0;
            for (int ny = std::max(0, y - reach); ny <= std::min(H - 1, y + reach); ++ny)
                for (int nx = std::max(0, x - reach); nx <= std::min(W - 1, x + reach); ++nx)
                    bits |= classifyPair(c, centre.rec[size_t(ny) * W + nx], th);
            out[size_t(y) * W + x] = float(bits & e.types);
        }
    return out;
}

}  // namespace rays
