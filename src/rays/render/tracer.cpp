#include "rays/render/tracer.h"

#include <cmath>
#include <optional>

#include "rays/geometry/refract.h"
#include "rays/image/parallel.h"
#include "rays/math/sampling.h"
#include "rays/render/absorption.h"
#include "rays/render/area_light.h"
#include "rays/render/shading.h"
#include "rays/render/texturing.h"
#include "rays/util/stack_room.h"

namespace rays {
namespace {

constexpr double kSurfaceOffset = Tracer::kSurfaceOffset;
constexpr double kTMin = Tracer::kMinHitT;

// Beer's law tint exp(−(1 − C)·0.15·d); an infinite distance absorbs every channel below 1.
Vec3 beerTint(Vec3 c, double d) { return beerAbsorption((Vec3(1.0) - c) * 0.15, d); }

// Course weights of a hit: local (1−f)(1−r), reflection (1−f)·r + f·F, transmission f·(1−F);
// under total internal reflection the transmitted weight goes to the reflection. T is the
// refracted direction when wTrans > 0.
struct SecondaryWeights {
    double wLocal, wRefl, wTrans;
    Vec3 T;
};

SecondaryWeights secondaryWeights(const Material& m, Vec3 dir, Vec3 N, bool entering, bool fresnel) {
    const double F = fresnel ? schlickFresnel(m.ior, dot(N, -dir)) : 0.0;
    SecondaryWeights w{(1 - m.filter) * (1 - m.reflection), (1 - m.filter) * m.reflection + m.filter * F,
                       m.filter * (1 - F), Vec3{}};
    if (w.wTrans > 0 && !refractDir(dir, N, entering ? 1.0 / m.ior : m.ior, w.T)) {
        w.wRefl += w.wTrans;
        w.wTrans = 0;
    }
    return w;
}

}  // namespace

// Below this many objects in the object BVH, building origin buffers costs more than they save.
constexpr size_t kSharedOriginsMin = 256;

SharedOrigins Tracer::buildSharedOrigins(const Scene& scene, const Bvh& bvh, const Vec3* eye, double primarySamples,
                                         int threads, double memoryBudget) {
    SharedOrigins out;
    const double objects = double(bvh.boundedCount());
    // A buffer costs ~150 ns per object to build and saves some tens of ns per query.
    if (objects < double(kSharedOriginsMin) || objects > primarySamples / 4) return out;
    const size_t room = size_t(memoryBudget / (kSharedOriginsBytesPerObject * objects));
    out.lights.resize(scene.lights.size());
    struct Job {
        OriginBuffer* buffer;
        Vec3 origin;
        double dilation;
    };
    std::vector<Job> jobs;
    // Shadow rays leave P + kSurfaceOffset N (N unit): within kSurfaceOffset of the segment from
    // the light to P, with room for the rounding of N.
    for (size_t i = 0; i < scene.lights.size() && jobs.size() < room; ++i)
        if (!scene.lights[i].parallel && !scene.lights[i].area)
            jobs.push_back({&out.lights[i], scene.lights[i].position, kSurfaceOffset * 1.01});
    // The eye's buffer is the biggest (its lists cover the whole view): built first, the others
    // share the remaining threads.
    if (eye && jobs.size() < room) jobs.insert(jobs.begin(), {&out.eye, *eye, 0.0});
    if (jobs.empty()) return out;
    const std::vector<OriginBuffer::Bound> bounds = bvh.originBounds(scene.objects);
    parallelFor(int(jobs.size()), threads, [&](int j) {
        const Job& job = jobs[size_t(j)];
        job.buffer->build(bounds, job.origin, job.dilation);
    });
    return out;
}

Hit Tracer::firstHit(const Ray& ray) const {
    if (origins_ && !origins_->eye.empty() && ray.origin == origins_->eye.origin())
        return bvh_.closestFrom(origins_->eye.cells(ray.dir), scene_.objects, ray, kTMin, kInfinity);
    return bvh_.closest(scene_.objects, ray, kTMin, kInfinity);
}

Vec3 Tracer::tracePrimary(const Ray& ray, TraceContext& ctx, std::vector<TraceRecord>* log, PathInfo* info) const {
    ++ctx.stats.primaryRays;
    if (povPath_) return tracePovPrimary(ray, ctx, info);
    return trace(ray, Frame{}, ctx, log, info).color;
}

bool Tracer::shadowed(const Ray& shadow, double tMax, size_t light, TraceContext& ctx, bool intoSurface,
                      const FromLight* fromLight, int* blocker) const {
    ++ctx.stats.shadowRays;
    // The light's buffer cells first: their loads overlap the tests below.
    OriginBuffer::Cells cells;
    if (fromLight && origins_ && light < origins_->lights.size()) {
        cells = origins_->lights[light].cells(fromLight->toPoint);
        __builtin_prefetch(cells.fine.first);
    }
    const bool cached = light < size_t(TraceContext::kCachedLights);
    // Any-hit: testing a likely blocker first changes the cost, never the answer.
    if (intoSurface && ctx.surfaceObject >= 0 &&
        bvh_.occludesObject(scene_.objects, uint32_t(ctx.surfaceObject), shadow, kTMin, tMax)) {
        if (cached) ctx.lastBlocker[light] = ctx.surfaceObject;
        if (blocker) *blocker = ctx.surfaceObject;
        return true;
    }
    if (cached && ctx.lastBlocker[light] >= 0) {
        if (bvh_.occludesObject(scene_.objects, uint32_t(ctx.lastBlocker[light]), shadow, kTMin, tMax)) {
            if (blocker) *blocker = ctx.lastBlocker[light];
            return true;
        }
        ctx.lastBlocker[light] = -1;  // a miss: no longer worth testing first (the walk re-finds it)
    }
    const int found = cells.valid ? bvh_.anyBlockerFrom(cells, scene_.objects, shadow, kTMin, tMax, fromLight->dist)
                                  : bvh_.anyBlocker(scene_.objects, shadow, kTMin, tMax);
    if (blocker) *blocker = found;
    if (cached && found >= 0) ctx.lastBlocker[light] = found;
    return found != Bvh::kNoBlocker;
}

ShadingModel Tracer::modelFor(const Material& m) const {
    if (settings_.shading == ShadingModel::Flat || settings_.shading == ShadingModel::Normals || m.shading < 0)
        return settings_.shading;
    return ShadingModel(m.shading);
}

double Tracer::shadeLight(const Light& light, size_t index, const Material& m, ShadingModel model, Vec3 P, Vec3 N,
                          Vec3 V, TraceContext& ctx, Vec3& diffuse, Vec3& specular, bool skipFacingAway) const {
    const Vec3 origin = P + kSurfaceOffset * N;
    auto addSample = [&](Vec3 L, Vec3 color) {
        LightTerms t;
        switch (model) {
            case ShadingModel::CookTorrance: t = cookTorrance(m, N, L, V, color); break;
            case ShadingModel::OrenNayar: t = orenNayar(m, N, L, V, color); break;
            case ShadingModel::Lambert: t = lambert(m, N, L, color); break;
            default: t = blinnPhong(m, N, L, V, color);
        }
        diffuse += t.diffuse;
        specular += t.specular;
    };
    // Whether a point pos of a light at toLight = pos − P from P (dist = |toLight| > 0) lights P;
    // L receives the unit direction from P towards it. The shadow ray is aimed at pos from the
    // offset point and blocked by any hit before pos (course convention).
    auto litFrom = [&](Vec3 pos, Vec3 toLight, double dist, Vec3& L, bool useBuffer) {
        L = toLight / dist;
        const double nl = dot(L, N);
        if (skipFacingAway && nl <= 0) return false;
        const Vec3 s = pos - origin;
        const double sd = length(s);
        if (sd == 0) return true;
        const FromLight fromLight{-s, sd};
        return !shadowed(Ray{origin, s / sd}, sd, index, ctx, nl < 0, useBuffer ? &fromLight : nullptr);
    };
    if (light.parallel) {
        const Vec3 L = -light.direction;
        const double nl = dot(L, N);
        if (skipFacingAway && nl <= 0) return 0.0;
        if (shadowed(Ray{origin, L}, kInfinity, index, ctx, nl < 0)) return 0.0;
        addSample(L, light.color);
        return 1.0;
    }
    if (!light.area) {
        const Vec3 toLight = light.position - P;
        if (skipFacingAway && clearlyFacingAway(toLight, N)) return 0.0;  // no sqrt, no division
        const double dist = length(toLight);
        if (dist == 0) return 1.0;
        Vec3 L;
        if (!litFrom(light.position, toLight, dist, L, true)) return 0.0;
        addSample(L, light.color);
        return 1.0;
    }

    // Area light: n1 × n2 point lights, each with 1/(n1·n2) of the colour.
    const AreaGrid grid = areaGrid(light, settings_.areaSamples, P);
    const int n1 = grid.n1, n2 = grid.n2;
    auto samplePos = [&](int u, int v) { return areaSample(light, grid, u, v, ctx.rng); };
    const Vec3 color = light.color / double(n1 * n2);
    auto visible = [&](Vec3 pos, Vec3& L) {
        const Vec3 toLight = pos - P;
        const double dist = length(toLight);
        if (dist == 0) {
            L = N;
            return true;
        }
        return litFrom(pos, toLight, dist, L, false);
    };
    // adaptive: when the four corners agree, their verdict holds for the whole light.
    int cornerVerdict = -1;  // −1 undecided, 0 all blocked, 1 all visible
    if (light.adaptive >= 0 && n1 > 1 && n2 > 1 && !light.jitter) {
        int lit = 0;
        Vec3 L;
        for (int c = 0; c < 4; ++c) lit += visible(samplePos((c & 1) ? n1 - 1 : 0, (c & 2) ? n2 - 1 : 0), L);
        if (lit == 0) return 0.0;
        if (lit == 4) cornerVerdict = 1;
    }
    int lit = 0;
    for (int v = 0; v < n2; ++v) {
        for (int u = 0; u < n1; ++u) {
            const Vec3 pos = samplePos(u, v);
            Vec3 L;
            if (cornerVerdict == 1) {
                const Vec3 toLight = pos - P;
                const double dist = length(toLight);
                L = dist > 0 ? toLight / dist : N;
            } else if (!visible(pos, L)) {
                continue;
            }
            ++lit;
            addSample(L, color);
        }
    }
    return double(lit) / double(n1 * n2);
}

void Tracer::probe(const Ray& ray, bool countShadows, bool followSecondary, TraceContext& ctx, PathInfo& out) const {
    out = PathInfo{};
    ++ctx.stats.primaryRays;
    probeRec(ray, 0, countShadows, followSecondary, ctx, out);
}

int Tracer::blockedLightsAt(Vec3 P, Vec3 N, TraceContext& ctx) const {
    const Vec3 origin = P + kSurfaceOffset * N;
    int blocked = 0;
    for (size_t li = 0; li < scene_.lights.size(); ++li) {
        const Light& L = scene_.lights[li];
        // As shadeLight: aimed at the light from the offset point.
        const Vec3 toLight = L.parallel ? -L.direction : L.position - origin;
        const double dist = length(toLight);
        if (dist == 0) continue;
        const FromLight fromLight{-toLight, dist};
        if (shadowed(Ray{origin, toLight / dist}, L.parallel ? kInfinity : dist, li, ctx, false,
                     L.parallel || L.area ? nullptr : &fromLight))
            ++blocked;
    }
    return blocked;
}

void Tracer::probeRec(const Ray& ray, int depth, bool countShadows, bool followSecondary, TraceContext& ctx,
                      PathInfo& out) const {
    const Hit hit = firstHit(ray);
    out.push(hit.object);
    if (!hit.valid()) return;
    const Object& o = shadedObject(scene_.objects, hit);
    const Vec3 P = ray.at(hit.t);
    const bool entering = dot(ray.dir, hit.geomNormal) < 0;
    const Vec3 N = entering ? hit.normal : -hit.normal;
    if (depth == 0) {
        out.setHit(hit.t, P, N);
        if (countShadows) out.blockedLights = int16_t(blockedLightsAt(P, N, ctx));
    }
    if (!followSecondary || depth >= settings_.maxDepth || out.count >= PathInfo::kMaxIds || stackNearlyFull()) return;
    const SecondaryWeights w = secondaryWeights(o.material, ray.dir, N, entering, settings_.fresnel);
    // As trace(): refraction first, origins offset along the normal.
    if (w.wTrans > 0) {
        ++ctx.stats.secondaryRays;
        probeRec(Ray{P - kSurfaceOffset * N, w.T}, depth + 1, false, true, ctx, out);
    }
    if (w.wRefl > 0) {
        const Vec3 R = normalize(reflect(ray.dir, N));
        ++ctx.stats.secondaryRays;
        probeRec(Ray{P + kSurfaceOffset * N, R}, depth + 1, false, true, ctx, out);
    }
}

int Tracer::localShading(const Material& m, ShadingModel model, Vec3 P, Vec3 N, Vec3 V, TraceContext& ctx,
                         Vec3& diffuse, Vec3& specular, bool countBlocked) const {
    // Such a light adds nothing lit or not; only the count could tell the difference.
    const bool skipFacingAway = !countBlocked && darkFacingAway(m, model);
    int blocked = 0;
    for (size_t li = 0; li < scene_.lights.size(); ++li)
        if (shadeLight(scene_.lights[li], li, m, model, P, N, V, ctx, diffuse, specular, skipFacingAway) < 0.5)
            ++blocked;
    return blocked;
}

Vec3 Tracer::gatherIndirect(Vec3 P, Vec3 N, const Frame& f, TraceContext& ctx) const {
    const int n = settings_.giSamples[f.giLevel == 0 ? 0 : 1];
    if (n <= 0) return {};
    const int k = std::max(1, int(std::lround(std::sqrt(double(n)))));
    const bool strata = k * k == n;
    Vec3 sum;
    Frame child = f;
    child.giLevel = f.giLevel + 1;
    child.depth = f.depth + 1;
    child.kind = TraceRecord::Kind::Reflection;
    const CosineHemisphere hemisphere(N);
    const Vec3 origin = P + kSurfaceOffset * N;
    // Directions are made a chunk at a time before their rays are traced: each one is a long
    // chain of dependent operations (a division, a polynomial, a square root), and made together
    // they overlap instead of stalling every trace that waits for its direction.
    constexpr int kChunk = 16;
    Vec3 dirs[kChunk];
    for (int first = 0; first < n; first += kChunk) {
        const int count = std::min(kChunk, n - first);
        for (int j = 0; j < count; ++j) {
            const int i = first + j;
            double a = ctx.rng.next(), b = ctx.rng.next();
            if (strata) {  // stratified: one jittered sample per cell of a k×k grid
                a = (i % k + a) / k;
                b = (i / k + b) / k;
            }
            dirs[j] = hemisphere(a, b);
        }
        for (int j = 0; j < count; ++j) {
            ++ctx.stats.secondaryRays;
            sum += trace(Ray{origin, dirs[j]}, child, ctx, nullptr, nullptr).color;
        }
    }
    return sum / double(n);
}

Vec3 Tracer::ambientTerm(const Material& m, Vec3 P, Vec3 N, const Frame& f, TraceContext& ctx) const {
    if (!settings_.gi) return m.ambient * m.color;
    // The last level has no ambient light at all; so has a level that would run past the stack's end.
    if (f.giLevel >= settings_.giBounces || stackNearlyFull()) return {};
    const Vec3 E = gatherIndirect(P, N, f, ctx);
    return settings_.giPhysical ? m.diffuse * m.color * E : E;
}

Tracer::Result Tracer::trace(const Ray& ray, const Frame& f, TraceContext& ctx, std::vector<TraceRecord>* log,
                             PathInfo* info) const {
    size_t rec = 0;
    if (log) {
        rec = log->size();
        log->push_back(TraceRecord{});
        (*log)[rec].kind = f.kind;
        (*log)[rec].ray = ray;
        (*log)[rec].intoObject = f.inside;
        (*log)[rec].depth = f.depth;
    }
    const Hit hit = firstHit(ray);
    if (info) info->push(hit.object);
    if (!hit.valid()) return {};

    const Object& o = shadedObject(scene_.objects, hit);
    const Vec3 P = ray.at(hit.t);
    const Vec3 V = -ray.dir;
    const bool entering = dot(ray.dir, hit.geomNormal) < 0;
    Vec3 N = entering ? hit.normal : -hit.normal;  // faces the viewer
    // Image maps change the pigment, normal and bump maps the shading normal.
    std::optional<Material> mapped;  // constructed only for mapped objects (a Material is ~200 bytes)
    const Material* mp = &o.material;
    if (o.material.pigmentMap >= 0 || o.material.normalMap >= 0 || o.material.bumpMap >= 0) {
        mapped.emplace(o.material);
        const SurfaceUV uv{hit.hasUV, hit.u, hit.v, hit.dpdu};
        applyMaps(scene_, o, P, uv, mapped->color, N);
        mp = &*mapped;
    }
    const Material& m = *mp;
    const ShadingModel model = modelFor(m);

    Result res;
    res.t = hit.t;
    if (model == ShadingModel::Flat) {
        res.color = m.color;
    } else if (model == ShadingModel::Normals) {
        res.color = 0.5 * (N + Vec3(1.0));
    }
    if (model == ShadingModel::Flat || model == ShadingModel::Normals) {
        if (log) {
            TraceRecord& r = (*log)[rec];
            r.hit = true;
            r.object = hit.object;
            r.t = hit.t;
            r.point = P;
            r.normal = hit.normal;
            r.color = res.color;
            r.wLocal = 1;
        }
        return res;
    }

    const SecondaryWeights w = secondaryWeights(m, ray.dir, N, entering, settings_.fresnel);
    const double wLocal = w.wLocal, wRefl = w.wRefl, wTrans = w.wTrans;
    const Vec3& T = w.T;

    Vec3 ambient, diffuse, specular;
    int blocked = 0;
    if (wLocal > 0 || info) {
        ctx.surfaceObject = hit.object;
        const bool countBlocked = info && f.kind == TraceRecord::Kind::Primary;
        blocked = localShading(m, model, P, N, V, ctx, diffuse, specular, countBlocked);
        ctx.surfaceObject = -1;
        ambient = ambientTerm(m, P, N, f, ctx);
    }
    if (info && f.kind == TraceRecord::Kind::Primary) {
        info->blockedLights = int16_t(blocked);
        info->setHit(hit.t, P, N);
    }

    Vec3 reflColor, transColor;
    const bool recurse = f.depth < settings_.maxDepth && !stackNearlyFull();  // never past the stack's end
    Frame child = f;
    child.depth = f.depth + 1;
    // Refraction first, as the course traces (and printrays prints) them. Both rays leave P
    // kSurfaceOffset along N (which faces the viewer): refraction rays to the far side,
    // reflection rays to the viewer's side.
    if (recurse && wTrans > 0) {
        ++ctx.stats.secondaryRays;
        child.kind = TraceRecord::Kind::Refraction;
        child.inside = entering;
        const Result c = trace(Ray{P - kSurfaceOffset * N, T}, child, ctx, log, info);
        transColor = entering ? c.color * (settings_.beers ? beerTint(m.color, c.t) : m.color) : c.color;
    }
    if (recurse && wRefl > 0) {
        const Vec3 R = normalize(reflect(ray.dir, N));
        ++ctx.stats.secondaryRays;
        child.kind = TraceRecord::Kind::Reflection;
        child.inside = f.inside;
        child.giLevel = 0;  // the course's GI restarts its levels on a reflection ray
        reflColor = trace(Ray{P + kSurfaceOffset * N, R}, child, ctx, log, info).color * m.color;
    }

    if (log) {
        TraceRecord& r = (*log)[rec];
        r.hit = true;
        r.object = hit.object;
        r.t = hit.t;
        r.point = P;
        r.normal = hit.normal;
        if (o.transformed) r.objectRay = Ray{o.toObject.point(ray.origin), o.toObject.vector(ray.dir)};
        r.ambient = wLocal * ambient;
        r.diffuse = wLocal * diffuse;
        r.specular = wLocal * specular;
        r.reflection = wRefl * reflColor;
        r.refraction = wTrans * transColor;
        r.wLocal = wLocal;
        r.wReflection = wRefl;
        r.wTransmission = wTrans;
    }
    res.color = wLocal * (ambient + diffuse + specular) + wRefl * reflColor + wTrans * transColor;
    if (log) (*log)[rec].color = res.color;
    return res;
}

}  // namespace rays
