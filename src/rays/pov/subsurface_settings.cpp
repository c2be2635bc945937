#include "rays/pov/subsurface_settings.h"

#include <cmath>

#include "rays/pov/item_values.h"

namespace rays::pov {

void readSubsurfaceSettings(const sdl::Item& block, PovSubsurfaceSettings& s) {
    s.enabled = true;
    auto whole = [](const Value& v) { return clampedInt(std::round(toFloat(v)), 1, kMaxSubsurfaceSamples); };
    for (const Entry& e : block.entries) {
        if (e.positional() || e.args.empty()) continue;
        if (e.kw() == Kw::samples) {
            s.samples = whole(e.args[0]);
            if (e.args.size() > 1) s.singleSamples = whole(e.args[1]);
        }
        if (e.kw() == Kw::radiosity) s.radiosity = toFloat(e.args[0]) != 0;
    }
}

}  // namespace rays::pov
