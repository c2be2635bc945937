#include "rays/pov/photon_settings.h"

#include <algorithm>
#include <cmath>

#include "rays/pov/item_values.h"

namespace rays::pov {
namespace {

double entryNumber(const Entry& e, size_t i = 0, double absent = 1.0) {
    return e.args.size() > i ? toFloat(e.args[i]) : absent;
}

// A whole number written as a float: rounded, then clamped.
int entryWhole(double v, int lo, int hi) { return clampedInt(std::round(v), lo, hi); }

}  // namespace

PovPhotonSettings readPhotonSettings(const sdl::Item& block) {
    PovPhotonSettings p;
    p.enabled = true;
    for (const Entry& e : block.entries) {
        if (e.positional()) continue;
        switch (e.kw()) {
            case Kw::spacing: p.spacing = entryNumber(e); break;
            case Kw::count: p.count = entryNumber(e); break;
            case Kw::gather:
                p.gatherMin = entryWhole(entryNumber(e, 0, 20), 1, kMaxPhotonGather);
                p.gatherMax = entryWhole(entryNumber(e, 1, 100), 1, kMaxPhotonGather);
                break;
            case Kw::jitter: p.jitter = std::clamp(entryNumber(e), 0.0, 1.0); break;
            case Kw::max_trace_level: p.maxTraceLevel = entryWhole(entryNumber(e), 1, 256); break;
            case Kw::adc_bailout: p.adcBailout = std::max(0.0, entryNumber(e)); break;
            case Kw::radius: p.radius = std::max(0.0, entryNumber(e, 0, 0)); break;
            case Kw::expand_thresholds:
                p.expandPercent = std::max(0.0, entryNumber(e, 0, 0.2));
                p.expandMin = entryWhole(entryNumber(e, 1, 40), 0, kMaxPhotonGather);
                break;
            case Kw::media:
                p.mediaMaxSteps = entryWhole(entryNumber(e, 0, 0), 0, kMaxMediaPhotonSteps);
                p.mediaFactor = std::max(1e-3, entryNumber(e, 1, 1.0));
                break;
            default: break;  // autostop, save_file, load_file: nothing to change in the picture
        }
    }
    // Neither given: POV-Ray then shoots a handful (measured: 7 photons at a sphere of radius 0.7
    // at distance 7.8, 37 at one of radius 2); a coarse spacing does the same.
    if (!(p.spacing > 0) && !(p.count > 0)) p.spacing = 0.5;
    p.gatherMin = std::min(p.gatherMin, p.gatherMax);
    return p;
}

PovPhotonFlags readPhotonFlags(const sdl::Item& block, PovPhotonFlags flags) {
    for (const Entry& e : block.entries) {
        if (e.positional()) continue;
        switch (e.kw()) {
            case Kw::target:
                flags.target = true;
                flags.spacingScale = e.args.empty() ? 1.0 : toFloat(e.args[0]);
                if (!(flags.spacingScale > 0)) flags.target = false;  // target 0: no photons (POV-Ray: none shot)
                break;
            case Kw::refraction: flags.refraction = isOn(e); break;
            case Kw::reflection: flags.reflection = isOn(e); break;
            case Kw::collect: flags.collect = isOn(e); break;
            case Kw::pass_through: flags.passThrough = isOn(e); break;
            default: break;  // split_union
        }
    }
    return flags;
}

void readLightPhotons(const sdl::Item& block, Light& light) {
    light.photonBlock = true;
    light.photonRefraction = light.photonReflection = false;
    for (const Entry& e : block.entries) {
        if (e.positional()) continue;
        switch (e.kw()) {
            case Kw::refraction: light.photonRefraction = isOn(e); break;
            case Kw::reflection: light.photonReflection = isOn(e); break;
            default: break;  // area_light: photons leave an area light's centre
        }
    }
}

}  // namespace rays::pov
