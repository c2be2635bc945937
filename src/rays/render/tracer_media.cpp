// POV-Ray's media along the rays of POV-Ray scenes (POV-Ray 3.7 reference, "Media", "Sampling
// Parameters & Methods"): each stretch of a ray inside an interior with media, or in atmospheric
// media, is cut into intervals and equal steps, refined where neighbouring samples differ by more
// than aa_threshold (method 3, the 3.7 default; methods 1 and 2 are drawn the same way). At each
// sample the media add their emission and the light they scatter from the lights (phase functions
// in pov_media.cpp), weighted by the product of their densities, and the ray beyond is dimmed by
// exp(−extinction·step). docs/povray-lighting.md, "Media".
#include <algorithm>
#include <cmath>

#include "rays/render/pov_lighting.h"
#include "rays/render/tracer.h"

namespace rays {

namespace {

/// Beam edges of spot and cylindrical lights a stretch of ray is cut at, at most.
constexpr int kMaxMediaCuts = 128;
/// Scattering media of one stretch lit at a point, at most (more are not lit).
constexpr int kMaxScatterers = 16;
/// Scenes with more lights sample every light at every point of a stretch.
constexpr size_t kMaxMediaLights = 256;

double mediaDifference(Vec3 a, Vec3 b) {
    return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

}  // namespace

bool Tracer::povHasMedia() const {
    if (!scene_.pov.media.empty()) return true;
    for (const PovSurface& s : scene_.povSurfaces)
        if (s.interior.mediaCount > 0) return true;
    return false;
}

std::vector<Tracer::PovMediaHolder> Tracer::povMediaHolders() const {
    std::vector<PovMediaHolder> out;
    auto holds = [&](const Material& m) { return povSurfaceOf(m).interior.mediaCount > 0; };
    for (size_t i = 0; i < scene_.objects.size(); ++i) {
        const Object& o = scene_.objects[i];
        if (o.type == ShapeType::Csg) {
            for (const Object& leaf : o.csg->leaves)
                if (holds(leaf.material)) {
                    out.push_back(PovMediaHolder{int(i), leaf.material.pov, worldBounds(o)});
                    break;
                }
        } else if (holds(o.material)) {
            out.push_back(PovMediaHolder{int(i), o.material.pov, worldBounds(o)});
        }
    }
    return out;
}

void Tracer::povStartInside(Vec3 origin, PovRay& r) const {
    for (const PovMediaHolder& h : povMediaHolders_) {
        const Object& o = scene_.objects[size_t(h.object)];
        if (povHolds(o, origin)) r.enter(h.object, h.surface);
    }
}

// Fog fills the space outside objects and inside hollow ones (measured with POV-Ray 3.7: a clear
// sphere round part of a fogged view keeps the fog inside it with `hollow on` only; screen.inc's
// screen plane in front of the camera is hollow for this reason).
bool Tracer::povInAtmosphere(const PovRay& r) const {
    if (r.interior < 0) return true;
    if (!povInteriorOf(r).hollow) return false;
    for (int i = 0; i < r.insideCount; ++i) {
        const int surface = r.inside[i].surface;
        const PovSurface& s = surface >= 0 && size_t(surface) < scene_.povSurfaces.size()
                                  ? scene_.povSurfaces[size_t(surface)]
                                  : povSurfaceOf(scene_.objects[size_t(r.inside[i].object)].material);
        if (!s.hollow) return false;
    }
    return true;
}

PovMediaSet Tracer::povMediaOf(const PovRay& r) const {
    PovMediaSet set;
    // An object's media fill it where the ray is in no object inside it that is not hollow
    // (measured with POV-Ray 3.7, interior/media/hollow2.pov: a sphere inside a media-filled one
    // keeps the media out unless it is `hollow`). The innermost object is the last entered.
    bool hollow = true;
    for (int i = r.insideCount - 1; i >= 0; --i) {
        const int surface = r.inside[i].surface;
        const PovSurface& s = surface >= 0 && size_t(surface) < scene_.povSurfaces.size()
                                  ? scene_.povSurfaces[size_t(surface)]
                                  : povSurfaceOf(scene_.objects[size_t(r.inside[i].object)].material);
        const PovInterior& in = s.interior;
        if (hollow && in.mediaCount > 0) set.add(&scene_.povMedia[size_t(in.mediaFirst)], in.mediaCount);
        hollow = hollow && s.hollow;
    }
    // Atmospheric media fill the space outside objects and hollow objects only (the manual, "Hollow").
    if (hollow && !scene_.pov.media.empty()) set.add(scene_.pov.media.data(), int(scene_.pov.media.size()));
    return set;
}

Vec3 Tracer::povMediaLight(size_t index, Vec3 P, Vec3& toLight, TraceContext& ctx) const {
    const Light& light = scene_.lights[index];
    Vec3 color = light.color;
    Vec3 L = light.parallel ? -light.direction : light.position - P;
    const double dist = length(L);
    if (dist == 0) return {};
    toLight = L / dist;
    if (light.spot != Light::Spot::None) color *= povSpotFactor(light, P - light.position);
    if (light.fadeDistance > 0) color *= povLightFade(light, length(P - light.position));
    if (light.shadowless || color == Vec3{}) return color;
    if (light.parallel) {
        const double tMax = dot(light.position - P, -light.direction);
        if (tMax <= 0) return color;
        return color * povShadowTint(Ray{P, toLight}, tMax, index, ctx, false, nullptr);
    }
    return color * povShadowTint(Ray{P, toLight}, dist, index, ctx, false, nullptr);
}

Tracer::PovMediaPoint Tracer::povMediaPoint(const PovMediaSet& set, Vec3 P, Vec3 dir, TraceContext& ctx) const {
    PovMediaPoint out;
    // Each scattering medium's scattering colour times its density here, found once.
    struct Scatterer {
        const PovMedia* media;
        Vec3 color;
    };
    Scatterer scatterers[kMaxScatterers];
    int scattererCount = 0;
    for (int s = 0; s < set.spanCount; ++s)
        for (int i = 0; i < set.spans[s].count; ++i) {
            const PovMedia& m = set.spans[s].first[i];
            const Vec3 d = povMediaDensity(scene_, m, P);
            if (d == Vec3{}) continue;
            out.extinction += m.extinctionColor() * d;
            out.source += m.emission * d;
            if (m.scatters() && scattererCount < kMaxScatterers) scatterers[scattererCount++] = Scatterer{&m, m.scattering * d};
        }
    if (scattererCount == 0) return out;
    const size_t lightCount = set.lights ? size_t(set.lightCount) : scene_.lights.size();
    for (size_t n = 0; n < lightCount; ++n) {
        const size_t li = set.lights ? set.lights[n] : n;
        if (!scene_.lights[li].mediaInteraction) continue;
        Vec3 toLight;
        const Vec3 light = povMediaLight(li, P, toLight, ctx);
        if (light == Vec3{}) continue;
        // The light travels along −toLight; the viewer lies along −dir: cos = toLight·dir.
        const double c = dot(toLight, dir);
        for (int k = 0; k < scattererCount; ++k)
            out.source += povMediaPhase(*scatterers[k].media, c) * scatterers[k].color * light;
    }
    // The light the photons left in media bring (tracer_photons.cpp povLeaveInMedia), scattered
    // towards the viewer as a light's is: a photon travelling along d comes from −d.
    if (mediaPhotonMap_)
        out.source += mediaPhotonMap_->inScattered(P, mediaPhotonGather_, [&](Vec3 d) {
            const double c = -dot(d, dir);
            Vec3 w;
            for (int k = 0; k < scattererCount; ++k) w += povMediaPhase(*scatterers[k].media, c) * scatterers[k].color;
            return w;
        });
    return out;
}

void Tracer::povMediaStep(const PovMediaSet& set, const Ray& ray, double a, const PovMediaPoint& pa, double b,
                          const PovMediaPoint& pb, int level, TraceContext& ctx, PovMediaSum& sum) const {
    // The samples compared are the light each would add over the step (and the share it takes out).
    const double h = b - a;
    if (level < set.aaLevel && (mediaDifference(pa.source, pb.source) * h > set.aaThreshold ||
                                mediaDifference(pa.extinction, pb.extinction) * h > set.aaThreshold)) {
        const double mid = 0.5 * (a + b);
        const PovMediaPoint pm = povMediaPoint(set, ray.at(mid), ray.dir, ctx);
        povMediaStep(set, ray, a, pa, mid, pm, level + 1, ctx, sum);
        povMediaStep(set, ray, mid, pm, b, pb, level + 1, ctx, sum);
        return;
    }
    // The step's light comes from its first sample, dimmed by the steps before it only (measured).
    sum.added += sum.through * pa.source * h;
    for (int c = 0; c < 3; ++c)
        if (pa.extinction[c] > 0) sum.through[c] *= std::exp(-pa.extinction[c] * h);
}

// Methods 1 and 2 (measured: emission 1 and absorption 1 over depth 1 give .62921 with samples 3,
// .63186 with 10, method 2): one sample in the middle of each step (moved by up to ±jitter/2 of
// a step), its light dimmed by the media up to it.
void Tracer::povMediaMidpoints(const PovMediaSet& set, const Ray& ray, double a, double b, int steps,
                               TraceContext& ctx, PovMediaSum& sum) const {
    const double h = (b - a) / steps;
    for (int k = 0; k < steps; ++k) {
        double x = a + (k + 0.5) * h;
        if (set.jitter > 0) x += set.jitter * h * (ctx.rng.next() - 0.5);
        const PovMediaPoint p = povMediaPoint(set, ray.at(x), ray.dir, ctx);
        Vec3 half(1.0), step(1.0);
        for (int c = 0; c < 3; ++c)
            if (p.extinction[c] > 0) {
                half[c] = std::exp(-0.5 * p.extinction[c] * h);
                step[c] = half[c] * half[c];
            }
        sum.added += sum.through * half * p.source * h;
        sum.through *= step;
    }
}

Vec3 Tracer::povMediaAlong(const Ray& ray, double t, const PovRay& r, Vec3 behind, TraceContext& ctx) const {
    PovMediaSet set = povMediaOf(r);
    if (set.empty()) return behind;
    // Secondary rays start kSurfaceOffset past their surface: the stretch starts at the surface.
    const double start = r.primary ? 0.0 : -kSurfaceOffset;
    const double end = std::isfinite(t) ? t : kPovMediaMissDistance;
    if (!(end > start)) return behind;
    // The stretch is cut where it enters and leaves the beams of spotlights and cylindrical lights
    // that light scattering media, each piece sampled in full (the manual: lit and unlit
    // intervals are sampled apart, method 3 "will create more intervals if it needs them").
    // Lights whose beam the stretch does not meet are left out of its samples.
    double cuts[kMaxMediaCuts + 2];
    int cutCount = 0;
    cuts[cutCount++] = start;
    uint16_t lit[kMaxMediaLights];
    int litCount = 0;
    if (set.scatters && scene_.lights.size() <= kMaxMediaLights) {
        for (size_t li = 0; li < scene_.lights.size(); ++li) {
            const Light& light = scene_.lights[li];
            if (!light.mediaInteraction) continue;
            const int edges = povLightBeamEdges(light, ray, start, end, cuts + cutCount, kMaxMediaCuts + 1 - cutCount);
            cutCount += edges;
            const bool meets = light.spot == Light::Spot::None || edges > 0 ||
                               povSpotFactor(light, ray.at(0.5 * (start + end)) - light.position) > 0;
            if (meets) lit[litCount++] = uint16_t(li);
        }
        set.lights = lit;
        set.lightCount = litCount;
    }
    std::sort(cuts + 1, cuts + cutCount);
    cuts[cutCount++] = end;
    const int steps = set.steps;
    const int pieces = (cutCount - 1) * set.intervals;
    PovMediaSum sum;
    for (int iv = 0; iv < pieces; ++iv) {
        const int cut = iv / set.intervals, part = iv % set.intervals;
        const double from = cuts[cut], to = cuts[cut + 1];
        if (!(to > from)) continue;
        const double a = from + (to - from) * part / set.intervals;
        const double b = from + (to - from) * (part + 1) / set.intervals;
        const double h = (b - a) / steps;
        if (set.midpoints) {  // methods 1 and 2
            povMediaMidpoints(set, ray, a, b, steps, ctx, sum);
            continue;
        }
        // Sample k at the start of step k, moved by up to ±jitter/2 of a step (not the ends);
        // the ends are sampled just inside the piece, which a beam's edge may bound.
        const double inset = 1e-6 * (b - a);
        auto at = [&](int k) {
            double x = a + k * h;
            if (set.jitter > 0 && k > 0 && k < steps) x += set.jitter * h * (ctx.rng.next() - 0.5);
            return x;
        };
        auto sample = [&](double x) {
            return povMediaPoint(set, ray.at(std::clamp(x, a + inset, b - inset)), ray.dir, ctx);
        };
        double x0 = a;
        PovMediaPoint p0 = sample(a);
        for (int k = 1; k <= steps; ++k) {
            const double x1 = k == steps ? b : at(k);
            const PovMediaPoint p1 = sample(x1);
            povMediaStep(set, ray, x0, p0, x1, p1, 0, ctx, sum);
            x0 = x1;
            p0 = p1;
        }
    }
    return behind * sum.through + sum.added;
}

}  // namespace rays
