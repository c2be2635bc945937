// The Illinois variant of regula falsi (Dowell and Jarratt, BIT 11, 1971): the root of f between
// lo and hi, where f has opposite signs, narrowed by secant steps that keep it bracketed; an end
// kept twice in a row has its value halved, so that both ends move. A secant point outside the
// bracket (rounding) falls back to the middle.
#pragma once

namespace rays {

/// Narrows [lo, hi] (f(lo) = flo and f(hi) = fhi on opposite sides of 0, "positive" meaning > 0)
/// until wide(lo, hi) is false or after maxSteps steps; f(x) == 0 exactly ends it with lo = hi = x.
template <class F, class Wide>
void illinoisBracket(F&& f, double& lo, double flo, double& hi, double fhi, Wide&& wide, int maxSteps) {
    int kept = 0;  // which end the last step kept: −1 lo, +1 hi
    for (int i = 0; i < maxSteps && wide(lo, hi); ++i) {
        double mid = (flo * hi - fhi * lo) / (flo - fhi);
        if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);
        const double v = f(mid);
        if (v == 0) {
            lo = hi = mid;
            return;
        }
        if ((v > 0) == (flo > 0)) {
            lo = mid, flo = v;
            if (kept == 1) fhi *= 0.5;
            kept = 1;
        } else {
            hi = mid, fhi = v;
            if (kept == -1) flo *= 0.5;
            kept = -1;
        }
    }
}

}  // namespace rays
