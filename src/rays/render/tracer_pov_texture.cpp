// POV-Ray's layered and patterned textures in the POV-Ray tracer (POV-Ray 3.7 reference, "Layered
// Textures", "Texture Maps"; the composition measured with povray 3.7, docs/povray-lighting.md):
// every layer is lit with its own pigment, normal and finish; a pattern's textures are each shaded
// in full and blended. Surfaces with a plain texture never come here (shadePov).
#include <algorithm>
#include <cmath>

#include "rays/render/pov_lighting.h"
#include "rays/render/pov_normal.h"
#include "rays/render/pov_texture.h"
#include "rays/render/texturing.h"
#include "rays/render/tracer.h"

namespace rays {
namespace {

/// Layers of one run lit at a point (more are left out).
constexpr int kMaxLayers = 16;

/// The grey a layered texture's filtering counts as when POV-Ray decides whether a lower layer's
/// reflected ray is worth tracing: its weight is max(R)·grey(what the layers above let through),
/// compared with adc_bailout (measured: the blue share lies between 0.108 and 0.13, and the weights
/// below fit POV-Ray's classic grey).
double povGrey(Vec3 c) { return 0.297 * c.x + 0.589 * c.y + 0.114 * c.z; }

/// True when light from a direction with cosine nl to the layer's normal can add anything: in
/// front diffuse and highlights, behind the second diffuse value (or all with double_illuminate).
bool layerLit(const PovSurface& s, double opacity, double nl) {
    const PovFinish& f = s.finish;
    const bool front = (f.diffuse != 0 && opacity != 0) || f.phong > 0 || f.specular > 0;
    const bool back = s.doubleIlluminate ? front : (f.diffuseBack != 0 && opacity != 0);
    return nl > 0 ? front : (nl < 0 && back);
}

}  // namespace

Vec3 Tracer::shadePovTextured(const Ray& ray, const Hit& hit, const PovRay& r, Vec3 segmentFade, TraceContext& ctx,
                              PathInfo* info, int texture) const {
    const PovPoint pt = povPointOf(ray, hit, shadedObject(scene_.objects, hit), r, segmentFade);
    PovTextureChoice choices[kMaxTextureChoices];
    // A texture pattern's slope reads the surface's own normal (the textures' normals come after).
    const int n = povTextureChoices(scene_, texture, pt.P, pt.entering ? hit.normal : -hit.normal, choices,
                                      pt.uvPoint(), ray.dir);
    if (n == 1) return shadePovLayers(ray, hit, pt, choices[0].begin, choices[0].count, r, ctx, info);
    // Between two entries of a texture map both textures are shaded in full, reflection and
    // refraction included, and their colours blended (the manual, "Texture Maps"; measured).
    Vec3 color;
    for (int i = 0; i < n; ++i) {
        PovRay part = r;
        part.weight = r.weight * choices[i].weight;
        color += choices[i].weight *
                 shadePovLayers(ray, hit, pt, choices[i].begin, choices[i].count, part, ctx, i == 0 ? info : nullptr);
    }
    return color;
}

Vec3 Tracer::shadePovLayers(const Ray& ray, const Hit& hit, PovPoint pt, int begin, int count, const PovRay& r,
                            TraceContext& ctx, PathInfo* info) const {
    const Object& o = shadedObject(scene_.objects, hit);
    const double eta = povEta(pt, r);
    PovLayerAt layers[kMaxLayers];
    int n = 0;
    Vec3 through(1.0);  // what the layers above let through: it filters the light a layer sends back
    Vec3 color;
    PovGathered gathered;  // radiosity's light at the point, found once for all layers
    for (int i = 0; i < count && n < kMaxLayers && through != Vec3{}; ++i) {
        const PovLayer& l = scene_.povTextures.layers[size_t(begin + i)];
        PovLayerAt& a = layers[n++];
        a.surface = &l.surface;
        // The normal facing the viewer, tilted (as POV-Ray does, measured).
        a.N = l.surface.normal >= 0 ? povNormalAt(scene_, l.surface, pt.P, pt.Nfacing) : pt.Nfacing;
        const PovPigmentSample c = povLayerPigment(scene_, l, pt.P, a.N, pt.uvPoint(), ray.dir);  // slope and aoi read the tilted normal
        a.C = c.color, a.filter = c.filter, a.transmit = c.transmit;
        if (i == 0 && (o.material.pigmentMap >= 0 || o.material.normalMap >= 0 || o.material.bumpMap >= 0))
            applyMaps(scene_, o, pt.P, SurfaceUV{hit.hasUV, hit.u, hit.v, hit.dpdu}, a.C, a.N);
        a.opacity = povOpacity(a.C, a.filter, a.transmit, scene_.pov.version);
        a.R = povReflectivity(l.surface, a.C, std::max(0.0, -dot(a.N, ray.dir)), povFresnelEta(pt, r, eta));
        a.through = through;
        color += (a.opacity * through) * povAmbientTerm(l.surface.finish, a.C, pt.P, pt.Nfacing, r, ctx, gathered);
        Vec3 tint = povFilterTint(a.C, a.filter, a.transmit);
        if (l.surface.finish.conserveEnergy) tint *= Vec3(1.0) - a.R;
        a.R *= povReflectionIrid(l.surface.finish, a.N, ray.dir, pt.P);
        through *= tint;
    }
    if (n == 0) return color;
    // The top layer stands for the point: its side for shadow rays, its normal for refraction.
    pt.surface = layers[0].surface;
    pt.N = layers[0].N;
    pt.C = layers[0].C;
    pt.filter = layers[0].filter;
    pt.transmit = layers[0].transmit;

    ctx.surfaceObject = hit.object;
    const int blocked = povLayerLights(pt, layers, n, -ray.dir, ctx, color, info && r.primary);
    ctx.surfaceObject = -1;
    if (info && r.primary) {
        info->blockedLights = int16_t(blocked);
        info->setHit(hit.t, pt.P, pt.N);
    }
    if (r.level >= scene_.pov.maxTraceLevel) return color;  // no further rays at the last level

    auto trace = [&](Vec3 dir, const PovRay& child) {
        ++ctx.stats.secondaryRays;
        return tracePov(Ray{pt.P + kSurfaceOffset * dir, dir}, child, ctx, info);
    };
    const PovRay reflected = povReflectedRay(pt, r);
    // What all the layers let through goes on; total internal reflection replaces it and the
    // reflections by one reflected ray of full weight (as for a plain texture).
    if (!povTransmitted(ray, pt, r, eta, through, ctx, info, color))
        return color + trace(povMirrorDirection(ray.dir, pt.N, pt.Nfacing), reflected);
    // Each layer reflects with its own finish and normal, not filtered by the layers above
    // (measured); its ray's weight counts what they let through (see povGrey).
    Vec3 lastDir, lastSeen;
    bool traced = false;
    for (int k = 0; k < n; ++k) {
        const PovLayerAt& a = layers[k];
        if (!(maxComponent(a.R) > 0)) continue;
        PovRay child = reflected;
        child.weight = r.weight * maxComponent(a.R) * povGrey(a.through);
        if (child.weight < scene_.pov.adcBailout) continue;
        const Vec3 dir = povMirrorDirection(ray.dir, a.N, pt.Nfacing);
        if (!traced || !(dir == lastDir)) {  // layers sharing a normal share the reflected ray
            lastSeen = trace(dir, child);
            lastDir = dir;
            traced = true;
        }
        color += a.R * povReflectionExponent(lastSeen, a.surface->finish.reflectionExponent);
    }
    return color;
}

int Tracer::povLayerLights(const PovPoint& pt, const PovLayerAt* layers, int count, Vec3 V, TraceContext& ctx,
                           Vec3& color, bool countBlocked) const {
    // The light at a point inside a fading interior is divided by the viewing rays' fade there
    // (as povLights does).
    Vec3 scale(1.0);
    if (pt.interior >= 0)
        for (int i = 0; i < 3; ++i) scale[i] = pt.viewFade[i] > 0 ? 1.0 / pt.viewFade[i] : 1.0;
    // Layers lit by subsurface light transport: their diffuse light once, not per light (povLights).
    bool subsurface[kMaxLayers] = {};
    for (int k = 0; k < count; ++k) {
        const PovLayerAt& a = layers[k];
        subsurface[k] = povSubsurfaceLit(*a.surface, pt);
        if (subsurface[k] && a.opacity != 0) color += a.through * (a.opacity * povSubsurfaceDiffuse(pt, *a.surface, a.C, V, ctx));
    }
    int blocked = 0;
    for (size_t li = 0; li < scene_.lights.size(); ++li) {
        const Light& light = scene_.lights[li];
        if (!povLightsSurface(light, *pt.surface)) continue;
        Vec3 L;
        if (!povDirectionToLight(light, pt.P, L)) continue;
        bool useful = false;
        for (int k = 0; k < count && !useful; ++k) useful = layerLit(*layers[k].surface, layers[k].opacity, dot(layers[k].N, L));
        if (!useful && !countBlocked) continue;
        const double nl = dot(pt.N, L);
        const Vec3 arriving = povLightReaching(light, li, pt.P, nl >= 0 ? pt.N : -pt.N, nl < 0, ctx, !pt.highlights);  // radiosity: a point
        if (countBlocked && maxComponent(arriving) < 0.5 * maxComponent(light.color)) ++blocked;
        const Vec3 reach = scale * arriving;
        if (!useful || reach == Vec3{}) continue;
        for (int k = 0; k < count; ++k) {
            const PovLayerAt& a = layers[k];
            if (!layerLit(*a.surface, a.opacity, dot(a.N, L))) continue;
            const Vec3 irid = povIridTint(a.surface->finish, scene_.pov.iridWavelength, a.N, L, V, pt.P);
            const PovLightTerms t = povLightTerms(*a.surface, a.C, a.N, L, V, reach * irid);
            const double crand = a.surface->finish.crand;
            const double grain = crand != 0 ? 1 - crand * ctx.rng.next() : 1.0;
            Vec3 add = subsurface[k] ? Vec3{} : (a.opacity * grain) * t.diffuse;
            if (!light.shadowless && pt.highlights) add += t.highlight;  // none from shadowless lights or for radiosity
            color += a.through * add;
        }
    }
    // Photons (povLights' comment): each layer's diffuse, weighted and filtered as for a light.
    if (photonMap_ && povGathersPhotons(*pt.surface, *pt.material)) {
        const Vec3 E = povPhotonLight(pt.P, pt.N);
        if (!(E == Vec3{}))
            for (int k = 0; k < count; ++k) {
                const PovLayerAt& a = layers[k];
                if (a.surface->finish.diffuse != 0 && a.opacity != 0)
                    color += a.through * ((a.opacity * a.surface->finish.diffuse) * scale * a.C * E);
            }
    }
    return blocked;
}

}  // namespace rays
