// POV-Ray 3.7's radiosity in the POV-Ray tracer: the light gathered from the surroundings replaces
// the ambient term (docs/povray-lighting.md, "Radiosity", the rules measured with povray 3.7), found
// with Ward's irradiance cache (Ward, Rubinstein & Clear 1988; render/irradiance_cache.h): records
// made by the pretrace (render/radiosity_pretrace.h) and read-only during the final pass, where a
// point no record covers gathers its own light, reusable only within its camera sample.
#include <algorithm>
#include <cmath>

#include "rays/math/sampling.h"
#include "rays/render/pov_lighting.h"
#include "rays/render/pov_pigment.h"
#include "rays/render/pov_radiosity.h"
#include "rays/render/tracer.h"
#include "rays/util/stack_room.h"

namespace rays {
namespace {

/// The base-2 radical inverse of i (van der Corput): the second coordinate of the gathering
/// directions, a Hammersley set over [0,1)² with the first coordinate (i + ½)/n.
double radicalInverse2(uint32_t i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
    i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
    i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
    i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
    return double(i) * 0x1.0p-32;
}

double wrapUnit(double v) { return v - std::floor(v); }

}  // namespace

Vec3 Tracer::povAmbientTerm(const PovFinish& f, Vec3 C, Vec3 P, Vec3 N, const PovRay& r, TraceContext& ctx,
                            PovGathered& g) const {
    const PovRadiosity& rad = scene_.pov.radiosity;
    if (!rad.enabled) return povAmbient(f, C, scene_.pov.ambientLight);
    if (!g.done && f.diffuse != 0 && r.radLevel < rad.recursionLimit && !stackNearlyFull()) {
        g.light = rad.brightness * povGrayThreshold(povIrradiance(P, N, r, ctx), rad.grayThreshold);
        g.done = true;
    }
    return povRadiosityAmbient(f, C, scene_.pov.ambientLight, g.light, scene_.pov.version);
}

Vec3 Tracer::povIrradiance(Vec3 P, Vec3 N, const PovRay& r, TraceContext& ctx) const {
    const PovRadiosity& rad = scene_.pov.radiosity;
    // The pretrace lowers the error bound so that the final pass finds more records than it needs
    // (the manual, "low_error_factor").
    const double a = rad.errorBound * (ctx.radPretrace ? rad.lowErrorFactor : 1.0) * levelErrorScale(r.radLevel);
    IrradianceBlend blend(P, N, r.radLevel, a, rad.nearestCount);
    if (radCache_) radCache_->gather(P, blend);
    for (const IrradianceRecord& rec : ctx.radLocal) blend.consider(rec);
    Vec3 E;
    if (blend.result(E)) return E;
    const IrradianceRecord rec = povGatherRecord(P, N, r, ctx);
    ctx.radLocal.push_back(rec);
    return rec.E;
}

IrradianceRecord Tracer::povGatherRecord(Vec3 P, Vec3 N, const PovRay& r, TraceContext& ctx) const {
    const PovRadiosity& rad = scene_.pov.radiosity;
    const int n = rad.count;
    PovRay child{.level = r.level + 1,
                 .weight = r.weight,
                 .interior = r.interior,
                 .interiorSurface = r.interiorSurface,
                 .reflected = r.reflected,
                 .radLevel = r.radLevel + 1,
                 .gathering = true};
    child.copyInside(r);
    const CosineHemisphere hemisphere(N);
    const Vec3 origin = P + kSurfaceOffset * N;
    // A Hammersley set shifted by one random offset per record (Cranley–Patterson rotation): every
    // record's directions cover the hemisphere evenly, without a pattern shared by all records.
    const double shiftA = ctx.rng.next(), shiftB = ctx.rng.next();
    Vec3 sum;
    double inverseDistances = 0;
    for (int i = 0; i < n; ++i) {
        const Vec3 d = hemisphere(wrapUnit((i + 0.5) / n + shiftA), wrapUnit(radicalInverse2(uint32_t(i)) + shiftB));
        const Ray ray{origin, d};
        ++ctx.stats.secondaryRays;
        const Hit hit = povFirstHit(ray, r.reflected, true);
        Vec3 seen = hit.valid() ? shadePov(ray, hit, child, Vec3(1.0), ctx, nullptr) : povSky(scene_, d);
        if (!scene_.pov.fogs.empty() && povInAtmosphere(child)) seen = povFog(scene_.pov.fogs, seen, ray, hit.t);
        if (hit.valid()) inverseDistances += 1.0 / std::max(hit.t, kMinHitT);
        sum += seen;
    }
    IrradianceRecord rec;
    rec.P = P;
    rec.N = N;
    rec.E = sum / double(n);
    rec.level = r.radLevel;
    // The radius of reuse: the harmonic mean distance, kept between minimum_reuse and maximum_reuse
    // times the distance from the eye (the manual, "minimum_reuse").
    const Camera& cam = scene_.cameras[size_t(std::clamp(settings_.cameraIndex, 0, int(scene_.cameras.size()) - 1))];
    const double eye = std::max(length(P - cam.location), 1e-9);
    const double harmonic = inverseDistances > 0 ? double(n) / inverseDistances : kInfinity;
    rec.R = std::clamp(harmonic, std::max(rad.minimumReuse * eye, 1e-9), std::max(rad.maximumReuse * eye, 1e-9));
    return rec;
}

}  // namespace rays
