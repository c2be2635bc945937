// The repeat warp as the manual describes it: the coordinate along the repeat vector is taken
// modulo its length, each copy n is shifted by n·offset, and odd copies are mirrored across
// the axes flip names.
#include "rays/pattern/warp.h"

#include <cmath>

namespace rays::pattern {

Vec3 applyWarp(const WarpStep& w, Vec3 p) {
    switch (w.kind) {
        case WarpStep::Kind::Transform: return w.toInner.point(p);
        case WarpStep::Kind::Turbulence: return turbulent(p, w.turbulence);
        case WarpStep::Kind::Mapping: return applyMappingWarp(w.mapping, p);
        case WarpStep::Kind::BlackHole: return applyBlackHole(w.hole, p);
        case WarpStep::Kind::Repeat: {
            if (w.width == 0) return p;
            const double copy = std::floor(p[w.axis] / w.width);
            p[w.axis] -= copy * w.width;
            p += copy * w.offset;
            if (std::fmod(std::fabs(copy), 2.0) == 1.0)
                for (int i = 0; i < 3; ++i)
                    if (w.flip[i] != 0) p[i] = i == w.axis ? w.width - p[i] : -p[i];
            return p;
        }
    }
    return p;
}

}  // namespace rays::pattern
