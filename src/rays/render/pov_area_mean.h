// POV-Ray's mean of an area light's samples (measured with povray 3.7, docs/povray-lighting.md
// "Area lights"): each axis's index range is halved again and again, an odd number of samples
// sharing its middle one, an even number split into two disjoint halves, the parts weighing
// alike, down to single cells (two samples along each axis), whose corners average. So 3, 5, 9
// or 17 samples follow the trapezoid rule and 4 or 8 the plain mean. With `adaptive A`, a part at
// depth A or deeper (the whole light is depth 0) whose four corner samples agree is taken as
// their value without looking inside.
#pragma once

#include "rays/math/vec3.h"

namespace rays {

namespace pov_area_detail {

// The halves of the index range [a, b] (b − a ≥ 2): [a, lo] and [hi, b].
inline void halves(int a, int b, int& lo, int& hi) {
    const int d = b - a;
    lo = a + d / 2;  // d odd: rounded down, the lower half's last sample
    hi = d % 2 == 0 ? lo : lo + 1;
}

template <class At>
Vec3 part(At& at, int adaptive, int u0, int u1, int v0, int v1, int depth) {
    const bool splitU = u1 - u0 >= 2, splitV = v1 - v0 >= 2;
    if (!splitU && !splitV) {  // a cell (or an edge, or a point): its distinct corners' mean
        Vec3 sum = at(u0, v0);
        int n = 1;
        if (u1 != u0) sum += at(u1, v0), ++n;
        if (v1 != v0) {
            sum += at(u0, v1), ++n;
            if (u1 != u0) sum += at(u1, v1), ++n;
        }
        return sum / double(n);
    }
    if (adaptive >= 0 && depth >= adaptive) {
        const Vec3 c = at(u0, v0);
        if (at(u1, v0) == c && at(u0, v1) == c && at(u1, v1) == c) return c;
    }
    int ua = u1, ub = u0, va = v1, vb = v0;  // an axis not split keeps its whole range
    if (splitU) halves(u0, u1, ua, ub);
    if (splitV) halves(v0, v1, va, vb);
    const int us[2][2] = {{u0, ua}, {ub, u1}}, vs[2][2] = {{v0, va}, {vb, v1}};
    Vec3 sum;
    int parts = 0;
    for (int i = 0; i < (splitU ? 2 : 1); ++i)
        for (int j = 0; j < (splitV ? 2 : 1); ++j, ++parts)
            sum += part(at, adaptive, us[i][0], us[i][1], vs[j][0], vs[j][1], depth + 1);
    return sum / double(parts);
}

}  // namespace pov_area_detail

/// The mean of the n1 × n2 samples at(u, v) (u < n1, v < n2) as POV-Ray weighs them; adaptive < 0:
/// no early stop. at may be asked for a sample more than once (the caller keeps what it traced).
template <class At>
Vec3 povAreaMean(int n1, int n2, int adaptive, At&& at) {
    return pov_area_detail::part(at, adaptive, 0, n1 - 1, 0, n2 - 1, 0);
}

}  // namespace rays
