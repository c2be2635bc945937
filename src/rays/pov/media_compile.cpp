#include "rays/pov/media_compile.h"

#include <algorithm>
#include <cmath>

namespace rays::pov {

using sdl::VType;

namespace {

constexpr int kMaxMediaDepth = 64;

int mediaCount(double v, int lo, int hi) { return std::isnan(v) ? lo : int(std::clamp(v, double(lo), double(hi))); }

// scattering { TYPE, COLOR [eccentricity E] [extinction X] }; types outside 1..5 scatter nothing.
void readScattering(const Item& s, PovMedia& m) {
    int bare = 0;
    for (const Entry& e : s.entries) {
        if (e.positional()) {
            for (const Value& v : e.args) {
                if (bare == 0) {
                    const int type = mediaCount(toFloat(v), 0, 6);
                    m.type = type >= 1 && type <= 5 ? PovMedia::Scattering(type) : PovMedia::Scattering::None;
                } else if (bare == 1) {
                    m.scattering = toColor(v).rgb;
                }
                ++bare;
            }
            continue;
        }
        if (e.args.empty()) continue;
        if (e.kw() == Kw::eccentricity) m.eccentricity = std::clamp(toFloat(e.args[0]), -0.999, 0.999);
        if (e.kw() == Kw::extinction) m.extinction = toFloat(e.args[0]);
    }
}

}  // namespace

void readMedia(const Item& media, MediaLook& out, PigmentCompiler* pigments, NotRendered& notes, int depth) {
    PovMedia& m = out.media;
    for (const Entry& e : media.entries) {
        if (e.positional()) {
            for (const Value& v : e.args)
                if (v.type == VType::Item && v.item().kind == Kw::media && depth < kMaxMediaDepth)
                    readMedia(v.item(), out, pigments, notes, depth + 1);
            continue;
        }
        if (isTransformEntry(e)) {  // moves the densities given so far
            Transform t;
            applyTransform(e, t);
            for (DensityLook& d : out.densities) d.toObject = t * d.toObject;
            continue;
        }
        if (e.args.empty()) continue;
        const Value& a = e.args[0];
        switch (e.kw()) {
            case Kw::method: m.method = mediaCount(toFloat(a), 1, 3); break;
            case Kw::intervals: m.intervals = mediaCount(toFloat(a), 1, 64); break;
            case Kw::samples:  // method 3 ignores the maximum
                out.samplesMin = mediaCount(toFloat(a), 1, 1024);
                out.samplesMax = e.args.size() > 1 ? mediaCount(toFloat(e.args[1]), 1, 1024) : out.samplesMin;
                break;
            case Kw::aa_level: m.aaLevel = mediaCount(toFloat(a), 0, 8); break;
            case Kw::aa_threshold: m.aaThreshold = std::max(0.0, toFloat(a)); break;
            case Kw::jitter: m.jitter = std::clamp(toFloat(a), 0.0, 1.0); break;
            case Kw::absorption: m.absorption = toColor(a).rgb; break;
            case Kw::emission: m.emission = toColor(a).rgb; break;
            case Kw::scattering:
                if (a.type == VType::Item) readScattering(a.item(), m);
                break;
            case Kw::density:
                if (pigments && a.type == VType::Item) out.densities.push_back(DensityLook{pigments->compileDensity(a.item()), {}});
                break;
            case Kw::collect: case Kw::confidence: case Kw::variance: case Kw::ratio: break;  // methods 1 and 2's statistics
            default: break;
        }
    }
    (void)notes;
    if (depth > 0) return;  // the outermost block decides
    if (m.method == 3) {
        m.samples = out.samplesMin;
    } else {
        // Methods 1 and 2 (the manual: samples spread evenly, or at random for method 1) as equal
        // steps: as many as the most samples, none refined.
        m.samples = std::max(out.samplesMin, out.samplesMax);
        m.aaLevel = 0;
        if (m.method == 1) m.jitter = 1;
    }
}

void moveMedia(MediaLook& m, const Transform& outer) {
    for (DensityLook& d : m.densities) d.toObject = outer * d.toObject;
}

}  // namespace rays::pov
