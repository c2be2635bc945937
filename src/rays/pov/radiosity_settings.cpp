#include "rays/pov/radiosity_settings.h"

#include <algorithm>
#include <cmath>

#include "rays/pov/item_values.h"

namespace rays::pov {

PovRadiosity readRadiosity(const sdl::Item& block) {
    PovRadiosity r;
    r.enabled = true;
    auto number = [](const Entry& e) { return e.args.empty() ? 1.0 : toFloat(e.args[0]); };
    auto count = [&](const Entry& e, int lo, int hi) {
        const double v = number(e);
        return std::isfinite(v) ? std::clamp(int(std::lround(v)), lo, hi) : lo;
    };
    for (const Entry& e : block.entries) {
        if (e.positional()) continue;
        switch (e.kw()) {
            case Kw::count: r.count = count(e, 1, 1600); break;  // 1600: POV-Ray's limit of directions
            case Kw::error_bound: r.errorBound = number(e); break;
            case Kw::low_error_factor: r.lowErrorFactor = number(e); break;
            case Kw::minimum_reuse: r.minimumReuse = number(e); break;
            case Kw::maximum_reuse: r.maximumReuse = number(e); break;
            case Kw::nearest_count: r.nearestCount = count(e, 1, 20); break;
            case Kw::pretrace_start: r.pretraceStart = number(e); break;
            case Kw::pretrace_end: r.pretraceEnd = number(e); break;
            case Kw::recursion_limit: r.recursionLimit = count(e, 1, 20); break;
            case Kw::brightness: r.brightness = number(e); break;
            case Kw::gray_threshold: r.grayThreshold = std::clamp(number(e), 0.0, 1.0); break;
            case Kw::adc_bailout: r.adcBailout = number(e); break;
            case Kw::always_sample: r.alwaysSample = number(e) != 0; break;
            default: break;  // normal, media, subsurface, max_sample, save_file, load_file, importance
        }
    }
    if (!(r.errorBound > 0)) r.errorBound = 1.8;
    if (!(r.lowErrorFactor > 0)) r.lowErrorFactor = 0.5;
    if (!(r.minimumReuse >= 0)) r.minimumReuse = 0.015;
    if (!(r.maximumReuse >= r.minimumReuse)) r.maximumReuse = std::max(r.minimumReuse, 0.2);
    return r;
}

}  // namespace rays::pov
