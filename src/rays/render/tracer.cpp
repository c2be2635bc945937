#include "rays/render/tracer.h"

#include <cmath>

#include "rays/render/shading.h"

namespace rays {
namespace {

constexpr double kSurfaceOffset = 0.001;  // new rays start this far along their direction
constexpr double kTMin = 1e-6;            // hits closer than this are ignored

// Refraction of unit d through unit normal n facing d's origin side (dot(d, n) < 0) with
// relative index eta = n1/n2. Returns false on total internal reflection.
bool refractDir(Vec3 d, Vec3 n, double eta, Vec3& out) {
    const double cosi = -dot(d, n);
    const double k = 1.0 - eta * eta * (1.0 - cosi * cosi);
    if (k < 0) return false;
    out = normalize(eta * d + (eta * cosi - std::sqrt(k)) * n);
    return true;
}

// Beer's law tint exp(−(1 − C)·0.15·d); an infinite distance absorbs every channel below 1.
Vec3 beerTint(Vec3 c, double d) {
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
        const double a = (1.0 - c[i]) * 0.15;
        out[i] = a == 0 ? 1.0 : (std::isinf(d) ? 0.0 : std::exp(-a * d));
    }
    return out;
}

}  // namespace

Hit Tracer::firstHit(const Ray& ray) const { return bvh_.closest(scene_.objects, ray, kTMin, kInfinity); }

Vec3 Tracer::tracePrimary(const Ray& ray, TraceContext& ctx, std::vector<TraceRecord>* log) const {
    ++ctx.stats.primaryRays;
    return trace(ray, 0, TraceRecord::Kind::Primary, false, ctx, log).color;
}

bool Tracer::shadowed(const Ray& shadow, double tMax, size_t light, TraceContext& ctx) const {
    ++ctx.stats.shadowRays;
    const bool cached = light < size_t(TraceContext::kCachedLights);
    if (cached && ctx.lastBlocker[light] >= 0 &&
        occludes(scene_.objects[size_t(ctx.lastBlocker[light])], shadow, kTMin, tMax))
        return true;
    if (!cached) return bvh_.any(scene_.objects, shadow, kTMin, tMax);
    const int blocker = bvh_.anyBlocker(scene_.objects, shadow, kTMin, tMax);
    if (blocker >= 0) ctx.lastBlocker[light] = blocker;
    return blocker >= 0;
}

void Tracer::localShading(const Object& o, Vec3 P, Vec3 N, Vec3 V, TraceContext& ctx, Vec3& diffuse,
                          Vec3& specular) const {
    for (size_t li = 0; li < scene_.lights.size(); ++li) {
        const PointLight& light = scene_.lights[li];
        const Vec3 toLight = light.position - P;
        const double dist = length(toLight);
        if (dist == 0) continue;
        const Vec3 L = toLight / dist;
        const Ray shadow{P + kSurfaceOffset * N, L};
        if (shadowed(shadow, dist - kSurfaceOffset, li, ctx)) continue;
        const LightTerms terms = settings_.shading == ShadingModel::CookTorrance
                                     ? cookTorrance(o.material, N, L, V, light.color)
                                     : blinnPhong(o.material, N, L, V, light.color);
        diffuse += terms.diffuse;
        specular += terms.specular;
    }
}

Tracer::Result Tracer::trace(const Ray& ray, int depth, TraceRecord::Kind kind, bool inside,
                             TraceContext& ctx, std::vector<TraceRecord>* log) const {
    size_t rec = 0;
    if (log) {
        rec = log->size();
        log->push_back(TraceRecord{});
        (*log)[rec].kind = kind;
        (*log)[rec].ray = ray;
        (*log)[rec].intoObject = inside;
    }
    const Hit hit = firstHit(ray);
    if (!hit.valid()) return {};

    const Object& o = scene_.objects[size_t(hit.object)];
    const Material& m = o.material;
    const Vec3 P = ray.at(hit.t);
    const Vec3 V = -ray.dir;
    const bool entering = dot(ray.dir, hit.geomNormal) < 0;
    const Vec3 N = entering ? hit.normal : -hit.normal;  // faces the viewer

    Result res;
    res.t = hit.t;
    if (settings_.shading == ShadingModel::Flat) {
        res.color = m.color;
    } else if (settings_.shading == ShadingModel::Normals) {
        res.color = 0.5 * (N + Vec3(1.0));
    }
    if (settings_.shading == ShadingModel::Flat || settings_.shading == ShadingModel::Normals) {
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

    // Weights (course): local (1−f)(1−r), reflection (1−f)·r + f·F, transmission f·(1−F).
    const double f = m.filter, refl = m.reflection;
    const double F = settings_.fresnel ? schlickFresnel(m.ior, dot(N, V)) : 0.0;
    double wLocal = (1 - f) * (1 - refl);
    double wRefl = (1 - f) * refl + f * F;
    double wTrans = f * (1 - F);

    Vec3 ambient, diffuse, specular;
    if (wLocal > 0) {
        ambient = m.ambient * m.color;
        localShading(o, P, N, V, ctx, diffuse, specular);
    }

    Vec3 reflColor, transColor;
    const bool recurse = depth < settings_.maxDepth;
    Vec3 T;
    if (wTrans > 0) {
        const double eta = entering ? 1.0 / m.ior : m.ior;
        if (!refractDir(ray.dir, N, eta, T)) {  // total internal reflection
            wRefl += wTrans;
            wTrans = 0;
        }
    }
    if (recurse && wRefl > 0) {
        const Vec3 R = normalize(reflect(ray.dir, N));
        ++ctx.stats.secondaryRays;
        reflColor = trace(Ray{P + kSurfaceOffset * R, R}, depth + 1, TraceRecord::Kind::Reflection, inside,
                          ctx, log).color * m.color;
    }
    if (recurse && wTrans > 0) {
        ++ctx.stats.secondaryRays;
        const Result child = trace(Ray{P + kSurfaceOffset * T, T}, depth + 1, TraceRecord::Kind::Refraction,
                                   entering, ctx, log);
        if (entering) {
            transColor = child.color * (settings_.beers ? beerTint(m.color, child.t) : m.color);
        } else {
            transColor = child.color;
        }
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
