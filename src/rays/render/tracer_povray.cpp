// POV-Ray 3.7's lighting model for the objects of POV-Ray scenes (Scene::pov.enabled): local light
// per light source, filter and transmit, reflection, refraction, interior fading, shadows through
// transparent objects, max_trace_level and adc_bailout. The formulas are in pov_lighting.h; how
// they combine was settled by black-box measurements of povray 3.7 (docs/povray-lighting.md).
#include <algorithm>
#include <cmath>

#include "rays/geometry/refract.h"
#include "rays/render/area_light.h"
#include "rays/render/pov_area_mean.h"
#include "rays/render/pov_dispersion.h"
#include "rays/render/pov_lighting.h"
#include "rays/render/pov_normal.h"
#include "rays/render/pov_pigment.h"
#include "rays/render/pov_rainbow.h"
#include "rays/render/pov_texture.h"
#include "rays/render/texturing.h"
#include "rays/scene/shapes/shape_data.h"
#include "rays/util/stack_room.h"
#include "rays/render/tracer.h"

namespace rays {
namespace {

constexpr double kSurfaceOffset = Tracer::kSurfaceOffset;
constexpr double kTMin = Tracer::kMinHitT;
/// A shadow ray passing more surfaces than this counts as blocked (bounds the walk).
constexpr int kMaxShadowSurfaces = 64;
/// Interiors with fading a shadow ray can be inside at once (more are not faded).
constexpr int kMaxOpenInteriors = 8;

/// The surface of objects without one (Material::pov < 0): POV-Ray's default finish.
const PovSurface kDefaultSurface{};

double maxAbsComponent(Vec3 v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

}  // namespace

bool Tracer::usesPovPath(const Scene& scene, const RenderSettings& settings) {
    return scene.pov.enabled && settings.shading != ShadingModel::Flat && settings.shading != ShadingModel::Normals;
}

std::vector<uint8_t> Tracer::povOpaqueObjects() const {
    auto blocks = [&](const Material& m) {
        const PovSurface& s = povSurfaceOf(m);
        return !povLetsLightThrough(m, s) && !s.noShadow;
    };
    std::vector<uint8_t> opaque(scene_.objects.size());
    for (size_t i = 0; i < scene_.objects.size(); ++i) {
        const Object& o = scene_.objects[i];
        bool all = blocks(o.material);
        if (o.type == ShapeType::Csg)  // each child of a CSG keeps its own material
            for (const Object& leaf : o.csg->leaves) all = all && blocks(leaf.material);
        opaque[i] = all;
    }
    return opaque;
}

const PovSurface& Tracer::povInteriorOf(const PovRay& r) const {
    const int s = r.interiorSurface;
    if (s >= 0 && size_t(s) < scene_.povSurfaces.size()) return scene_.povSurfaces[size_t(s)];
    return povSurfaceOf(scene_.objects[size_t(r.interior)].material);
}

const PovSurface& Tracer::povSurfaceOf(const Material& m) const {
    return m.pov >= 0 && size_t(m.pov) < scene_.povSurfaces.size() ? scene_.povSurfaces[size_t(m.pov)]
                                                                   : kDefaultSurface;
}

bool Tracer::povHides() const {
    for (const PovSurface& s : scene_.povSurfaces)
        if (s.noImage || s.noReflection || s.noRadiosity) return true;
    return false;
}

Hit Tracer::povFirstHit(const Ray& ray, bool reflected, bool gathering) const {
    Hit hit = firstHit(ray);
    if (!povHides_) return hit;
    // The hidden objects are passed by looking further along the same ray.
    while (hit.valid()) {
        const PovSurface& s = povSurfaceOf(shadedObject(scene_.objects, hit).material);
        if (!((reflected ? s.noReflection : s.noImage) || (gathering && s.noRadiosity))) break;
        hit = bvh_.closest(scene_.objects, ray, hit.t + kMinHitT * std::max(1.0, hit.t), kInfinity);
    }
    return hit;
}

// Two surfaces at the same place (a glass standing on a floor: its bottom and the floor's top) meet
// a ray at distances that differ by rounding only. Where the nearer one is a surface the ray
// leaves, the other is taken: POV-Ray 3.7 shows the floor through the glass's bottom, never what
// lies past the floor, which the ray leaving the glass would find as it starts kSurfaceOffset on
// (measured: a glass box on a checkered plane, seen from above through its top).
Hit Tracer::povTouching(const Ray& ray, const Hit& hit, const PovRay& r) const {
    if (!r.isInside(hit.object, shadedObject(scene_.objects, hit).material.pov)) return hit;
    const Hit other = bvh_.closest(scene_.objects, ray, hit.t, hit.t + kTouching * std::max(1.0, hit.t));
    if (!other.valid() || other.object == hit.object) return hit;
    const PovSurface& s = povSurfaceOf(shadedObject(scene_.objects, other).material);
    return (r.reflected ? s.noReflection : s.noImage) ? hit : other;  // not one this ray passes by
}

bool Tracer::povHolds(const Object& o, Vec3 p) {
    return o.type == ShapeType::Csg ? insideCsg(*o.csg, 0, p) : insideShape(o, p) == 1;
}

std::vector<Tracer::PovRay::Inside> Tracer::povCameraInside() const {
    std::vector<PovRay::Inside> out;
    const int i = settings_.cameraIndex;
    if (i < 0 || size_t(i) >= scene_.cameras.size()) return out;
    const Vec3 eye = scene_.cameras[size_t(i)].location;
    for (size_t k = 0; k < scene_.objects.size() && out.size() < size_t(PovRay::kMaxInside); ++k) {
        const Object& o = scene_.objects[k];
        if (povHolds(o, eye)) out.push_back(PovRay::Inside{int(k), o.type == ShapeType::Csg ? -1 : o.material.pov});
    }
    return out;
}

double Tracer::povIorFor(const PovInterior& in, const PovRay& r) {
    if (!r.dispersed || in.dispersion == 1 || !(in.dispersion > 0)) return in.ior;
    return in.ior * std::pow(in.dispersion, r.spectral);
}

double Tracer::povIorOf(const PovRay::Inside& in, const PovRay& r) const {
    const bool own = in.surface >= 0 && size_t(in.surface) < scene_.povSurfaces.size();
    return povIorFor(
        (own ? scene_.povSurfaces[size_t(in.surface)] : povSurfaceOf(scene_.objects[size_t(in.object)].material)).interior, r);
}

double Tracer::povEta(const PovPoint& pt, const PovRay& r) const {
    const double ior = povIorFor(pt.surface->interior, r);
    const int surface = pt.material->pov;
    if (pt.intoInterior) return (r.insideCount > 0 ? povIorOf(r.inside[r.insideCount - 1], r) : 1.0) / ior;
    for (int i = r.insideCount - 1; i >= 0; --i)  // the innermost interior other than the one left
        if (!r.inside[i].is(pt.object, surface)) return ior / povIorOf(r.inside[i], r);
    return ior;
}

double Tracer::povFresnelEta(const PovPoint& pt, const PovRay& r, double eta) {
    if (pt.intoInterior) return eta;
    for (int i = 0; i < r.insideCount; ++i)
        if (r.inside[i].object != pt.object) return 1.0;
    return eta;
}

Vec3 Tracer::tracePovPrimary(const Ray& ray, TraceContext& ctx, PathInfo* info) const {
    ctx.radLocal.clear();  // a camera sample reuses only its own radiosity records (and the cache's)
    PovRay r;
    r.primary = true;
    r.fades = true;  // a camera inside a fading object is faded where its ray leaves it (measured)
    r.reach = primaryReach_;
    if (!povMediaHolders_.empty()) povStartInside(ray.origin, r);  // the camera inside a media holder
    // Those holding the camera that hold this ray's start too: tested only where the ray starts
    // off the camera's location (an orthographic camera's rays, a lens's).
    if (!povCameraInside_.empty()) {
        const bool atEye = ray.origin == scene_.cameras[size_t(settings_.cameraIndex)].location;
        for (const PovRay::Inside& in : povCameraInside_)
            if (atEye || povHolds(scene_.objects[size_t(in.object)], ray.origin)) r.enter(in.object, in.surface);
    }
    return tracePov(ray, r, ctx, info);
}

double Tracer::primaryReach(const Scene& scene, const RenderSettings& settings) {
    const int i = settings.cameraIndex;
    if (i < 0 || size_t(i) >= scene.cameras.size() || !scene.cameras[size_t(i)].mesh) return kInfinity;
    return scene.cameras[size_t(i)].mesh->maxDistance;
}

Vec3 Tracer::tracePov(const Ray& ray, const PovRay& r, TraceContext& ctx, PathInfo* info) const {
    Hit hit = povFirstHit(ray, r.reflected);  // hit.t is infinite for a miss
    if (hit.valid() && r.insideCount > 0) hit = povTouching(ray, hit, r);
    if (hit.t > r.reach) hit = Hit{};  // past a mesh camera's max_distance: a miss (measured: the background)
    if (info) info->push(hit.object);
    // A transmitted ray's stretch fades where it ends on a surface it leaves: by that surface's
    // interior, over the stretch (measured with POV-Ray 3.7 on two overlapping glass boxes of
    // different fade_distance, crossed both ways: in a union the stretch ending where the ray
    // enters the second box does not fade, the overlap fades by the box left at its end; in a merge
    // the ray that went in through one box and out through the other's surface does not fade at
    // all, nor does one that meets nothing more).
    Vec3 fade(1.0);
    if (r.fades && hit.valid()) {
        const Material& m = shadedObject(scene_.objects, hit).material;
        if (r.isInside(hit.object, m.pov)) {
            const PovInterior& in = povSurfaceOf(m).interior;
            if (povFades(in)) fade = povFade(in, hit.t);
        }
    }
    Vec3 seen = fade * (hit.valid() ? shadePov(ray, hit, r, fade, ctx, info) : povSky(scene_, ray.dir));
    // Radiosity's gathering rays pass media by (radiosity's `media` is off by default; Rays does
    // not read it).
    if (povMedia_ && !r.gathering) seen = povMediaAlong(ray, hit.t, r, seen, ctx);
    // Fog fills the space outside objects and inside hollow ones (measured: on every ray,
    // reflected ones included), and rainbows lie in it as fogs do.
    if ((scene_.pov.fogs.empty() && scene_.pov.rainbows.empty()) || !povInAtmosphere(r)) return seen;
    const Vec3 bowed =
        scene_.pov.rainbows.empty() ? seen : povRainbows(scene_.pov.rainbows, seen, ray, hit.t, ctx.rng.next());
    return scene_.pov.fogs.empty() ? bowed : povFog(scene_.pov.fogs, bowed, ray, hit.t);
}

Tracer::PovPoint Tracer::povPointOf(const Ray& ray, const Hit& hit, const Object& o, const PovRay& r, Vec3 segmentFade) const {
    PovPoint pt;
    pt.object = hit.object;
    pt.material = &o.material;
    pt.surface = &povSurfaceOf(o.material);
    pt.P = ray.at(hit.t);
    pt.hasUV = hit.hasUV;
    pt.uv = Vec3{hit.u, hit.v, 0};
    const double facing = dot(ray.dir, hit.geomNormal);
    pt.entering = facing < 0;
    pt.Nfacing = pt.entering ? hit.normal : -hit.normal;
    // A ray touching the surface exactly tangentially (an orthographic camera's rays along a sphere's
    // rim) does not go in: it would not meet the surface again on its way out.
    pt.intoInterior = facing != 0 && !r.isInside(hit.object, o.material.pov);
    pt.interior = r.interior;
    pt.viewFade = r.faded * segmentFade;
    pt.highlights = !r.gathering;
    return pt;
}

// cutaway_textures where the cut lies in several textured leaves: the point shaded in full with
// each leaf's texture (reflection and refraction included) and the colours averaged, as POV-Ray's
// averaged textures are (measured: a cut inside a red box and a blue sphere shows (0.5, 0, 0.5)).
Vec3 Tracer::shadePovCutaway(const Ray& ray, const Hit& hit, const PovRay& r, Vec3 segmentFade, TraceContext& ctx,
                             PathInfo* info) const {
    const Object& o = scene_.objects[size_t(hit.object)];
    Hit plain = hit;
    plain.cutawayBlend = false;
    if (o.type != ShapeType::Csg || !o.csg) return shadePov(ray, plain, r, segmentFade, ctx, info);
    const Csg& c = *o.csg;
    const Vec3 P = ray.at(hit.t);
    const Object* parts[kMaxTextureChoices];
    int n = 0;
    for (size_t j = 0; j < c.leaves.size() && j < c.leafTextured.size() && n < kMaxTextureChoices; ++j)
        if (c.leafTextured[j] && insideShape(c.leaves[j], P) > 0) parts[n++] = &c.leaves[j];
    if (n == 0) return shadePov(ray, plain, r, segmentFade, ctx, info);
    Vec3 color;
    for (int i = 0; i < n; ++i) {
        plain.part = parts[i];
        PovRay part = r;
        part.weight = r.weight / n;
        color += shadePov(ray, plain, part, segmentFade, ctx, i == 0 ? info : nullptr);
    }
    return color / double(n);
}

// A mesh face textured per vertex: the point shaded in full with each corner's texture, reflection
// and refraction included, and the colours weighted by the point's barycentric weights (measured
// with POV-Ray 3.7 on a triangle whose corners have ambient-only textures of different colours and
// strengths: each pixel is their barycentric blend).
Vec3 Tracer::shadePovCorners(const Ray& ray, const Hit& hit, const PovRay& r, Vec3 segmentFade, TraceContext& ctx,
                             PathInfo* info) const {
    const Object& face = shadedObject(scene_.objects, hit);  // the face's part: a copy of the mesh
    if (!face.data || 3 * size_t(hit.blend.face) >= face.data->cornerParts.size()) {  // not expected: shade plainly
        Hit plain = hit;
        plain.blend.face = CornerBlend::kNone;
        return shadePov(ray, plain, r, segmentFade, ctx, info);
    }
    const ShapeData& data = *face.data;
    const int32_t* corners = &data.cornerParts[3 * size_t(hit.blend.face)];
    const double weights[3] = {1.0 - hit.blend.b1 - hit.blend.b2, hit.blend.b1, hit.blend.b2};
    Vec3 color;
    bool first = true;
    for (int k = 0; k < 3; ++k) {
        const double w = weights[k];
        if (!(w > 0)) continue;
        Hit corner = hit;
        corner.part = &data.parts[size_t(corners[k])];
        corner.blend.face = CornerBlend::kNone;
        PovRay part = r;
        part.weight = r.weight * w;
        color += w * shadePov(ray, corner, part, segmentFade, ctx, first ? info : nullptr);
        first = false;
    }
    return color;
}

namespace {

// Whether a ray along dir meets the outer side (texture, not interior_texture) of a surface whose
// geometric normal is n. Triangles and meshes show their outer side where their winding's normal
// points away from the ray (measured with POV-Ray 3.7: triangle { <-1,-1,0>, <1,-1,0>, <1,1,0> }
// seen from -z shows its texture and from +z its interior_texture; so do mesh, mesh2 and
// bicubic_patch); solids, discs and polygons where it points towards the ray.
bool povMeetsOuterSide(const Object& o, Vec3 dir, Vec3 n) {
    const bool flat = o.type == ShapeType::Triangle || o.type == ShapeType::Mesh;
    return flat ? dot(dir, n) > 0 : dot(dir, n) < 0;
}

}  // namespace

Vec3 Tracer::shadePov(const Ray& ray, const Hit& hit, const PovRay& r, Vec3 segmentFade, TraceContext& ctx,
                      PathInfo* info) const {
    if (hit.blend.on()) return shadePovCorners(ray, hit, r, segmentFade, ctx, info);
    if (hit.cutawayBlend) return shadePovCutaway(ray, hit, r, segmentFade, ctx, info);
    const Object& o = shadedObject(scene_.objects, hit);
    if (const PovSurface& s = povSurfaceOf(o.material); s.texture >= 0 || s.interiorTexture >= 0) {
        const int node = povTextureSeen(s, povMeetsOuterSide(o, ray.dir, hit.geomNormal));
        if (node >= 0) return shadePovTextured(ray, hit, r, segmentFade, ctx, info, node);
    }
    PovPoint pt = povPointOf(ray, hit, o, r, segmentFade);
    // The normal pattern tilts the shading normal (lighting, highlights, reflection, refraction);
    // inside or outside is still decided by the geometric normal. POV-Ray tilts the normal facing
    // the viewer (measured: a plane seen from its back tilts as one seen from its front).
    pt.N = pt.surface->normal >= 0 ? povNormalAt(scene_, *pt.surface, pt.P, pt.Nfacing) : pt.Nfacing;
    pt.C = o.material.color;
    pt.filter = o.material.filter;
    pt.transmit = pt.surface->transmit;
    if (pt.surface->pigment >= 0) {
        const PovPigmentSample c = povPigmentAt(scene_, *pt.surface, pt.P, pt.N, pt.uvPoint(), ray.dir);
        pt.C = c.color, pt.filter = c.filter, pt.transmit = c.transmit;
    }
    if (o.material.pigmentMap >= 0 || o.material.normalMap >= 0 || o.material.bumpMap >= 0)
        applyMaps(scene_, o, pt.P, SurfaceUV{hit.hasUV, hit.u, hit.v, hit.dpdu}, pt.C, pt.N);

    // The surface's own colour, weighted by its opacity; highlights are not (measured).
    const PovSurface& s = *pt.surface;
    const double opacity = povOpacity(pt.C, pt.filter, pt.transmit, scene_.pov.version);
    PovGathered gathered;
    Vec3 color = opacity * povAmbientTerm(s.finish, pt.C, pt.P, pt.Nfacing, r, ctx, gathered);
    ctx.surfaceObject = hit.object;
    const int blocked = povLights(pt, opacity, -ray.dir, ctx, color, info && r.primary);
    ctx.surfaceObject = -1;
    if (info && r.primary) {
        info->blockedLights = int16_t(blocked);
        info->setHit(hit.t, pt.P, pt.N);
    }
    // No further rays at the last level, nor where the thread's stack is nearly used up.
    if (r.level >= scene_.pov.maxTraceLevel || stackNearlyFull()) return color;
    return color + povSecondary(ray, pt, r, ctx, info);
}

Vec3 Tracer::povSecondary(const Ray& ray, const PovPoint& pt, const PovRay& r, TraceContext& ctx,
                          PathInfo* info) const {
    const PovSurface& s = *pt.surface;
    const double eta = povEta(pt, r);
    Vec3 R = povReflectivity(s, pt.C, std::max(0.0, -dot(pt.N, ray.dir)), povFresnelEta(pt, r, eta));
    Vec3 T = povFilterTint(pt.C, pt.filter, pt.transmit);
    if (s.finish.conserveEnergy) T *= Vec3(1.0) - R;
    R *= povReflectionIrid(s.finish, pt.N, ray.dir, pt.P);
    PovRay reflected = povReflectedRay(pt, r);
    auto trace = [&](Vec3 dir, const PovRay& child) {
        ++ctx.stats.secondaryRays;
        return tracePov(Ray{pt.P + kSurfaceOffset * dir, dir}, child, ctx, info);
    };

    Vec3 color;
    // Total internal reflection: one reflected ray with the full weight replaces both the
    // reflection and the transmission (measured).
    if (!povTransmitted(ray, pt, r, eta, T, ctx, info, color)) return trace(povMirrorDirection(ray.dir, pt.N, pt.Nfacing), reflected);
    reflected.weight = r.weight * maxComponent(R);
    if (maxComponent(R) > 0 && reflected.weight >= scene_.pov.adcBailout) {
        const Vec3 seen = trace(povMirrorDirection(ray.dir, pt.N, pt.Nfacing), reflected);
        color += R * povReflectionExponent(seen, s.finish.reflectionExponent);
    }
    return color;
}

// Iridescence tints the reflection too, as if the light came along the reflected ray (measured with
// POV-Ray 3.7: a black mirror of reflection 0.5 and irid 0.65, thickness 0.8 facing a white
// background, seen head-on and at 30° and 60°).
Vec3 Tracer::povReflectionIrid(const PovFinish& f, Vec3 N, Vec3 dir, Vec3 P) const {
    if (f.irid == 0) return Vec3(1.0);
    return povIridTint(f, scene_.pov.iridWavelength, N, normalize(reflect(dir, N)), -dir, P);
}

// A reflected ray stays on this side of the surface, a transmitted one crosses it. Only
// transmitted rays fade over their path inside an interior: reflected ones (total internal
// reflection included) do not, but the fade before them still counts for the light (measured).
Tracer::PovRay Tracer::povReflectedRay(const PovPoint& pt, const PovRay& r) const {
    PovRay reflected{.level = r.level + 1,
                     .weight = r.weight,
                     .interior = pt.intoInterior ? r.interior : pt.object,
                     .interiorSurface = pt.intoInterior ? r.interiorSurface : pt.material->pov,
                     .reflected = true,
                     .radLevel = r.radLevel,
                     .gathering = r.gathering,
                     .dispersed = r.dispersed,
                     .spectral = r.spectral};
    if (reflected.interior == r.interior) reflected.faded = pt.viewFade;
    reflected.copyInside(r);
    if (!pt.intoInterior) reflected.enter(pt.object, pt.material->pov);  // reflected inside: still in it
    return reflected;
}

bool Tracer::povTransmitted(const Ray& ray, const PovPoint& pt, const PovRay& r, double eta, Vec3 T, TraceContext& ctx,
                            PathInfo* info, Vec3& color) const {
    if (!(maxAbsComponent(T) > 0)) return true;
    if (povDispersed(ray, pt, r, T, ctx, info, color)) return true;
    Vec3 dir = ray.dir;
    int level = r.level;  // passing straight through (the same index on both sides) keeps the level (measured)
    if (eta != 1) {
        // A tilted normal that faces away from the ray is turned to face it, so that the ray
        // refracts back to the viewer's side (measured with POV-Ray 3.7: a glass plane with
        // `normal { gradient z }` seen at grazing angles; see povMirrorDirection).
        const Vec3 n = dot(ray.dir, pt.N) > 0 ? -pt.N : pt.N;
        if (!refractDir(ray.dir, n, eta, dir)) return false;
        ++level;
    }
    PovRay through{.level = level,
                   .weight = r.weight * maxAbsComponent(T),
                   .interior = pt.intoInterior ? pt.object : -1,
                   .interiorSurface = pt.intoInterior ? pt.material->pov : -1,
                   .fades = true,
                   .reflected = r.reflected,
                   .radLevel = r.radLevel,
                   .gathering = r.gathering,
                   .dispersed = r.dispersed,
                   .spectral = r.spectral};
    through.copyInside(r);
    if (pt.intoInterior) through.enter(pt.object, pt.material->pov);
    else through.leave(pt.object, pt.material->pov);
    if (through.weight >= scene_.pov.adcBailout) {
        ++ctx.stats.secondaryRays;
        color += T * tracePov(Ray{pt.P + kSurfaceOffset * dir, dir}, through, ctx, info);
    }
    return true;
}

bool Tracer::povDispersed(const Ray& ray, const PovPoint& pt, const PovRay& r, Vec3 T, TraceContext& ctx,
                          PathInfo* info, Vec3& color) const {
    const PovInterior& in = pt.surface->interior;
    if (r.dispersed || in.dispersion == 1 || !(in.dispersion > 0)) return false;
    const int n = in.dispersionSamples;
    auto bandOf = [&](int i) {
        PovRay band = r;
        band.dispersed = true;
        band.spectral = povDispersionExponent(i, n);
        return band;
    };
    // When every band is reflected whole (total internal reflection), so is the undispersed ray:
    // the caller's path takes it.
    const Vec3 facing = dot(ray.dir, pt.N) > 0 ? -pt.N : pt.N;
    bool anyThrough = false;
    for (int i = 0; i < n && !anyThrough; ++i) {
        Vec3 dir;
        anyThrough = refractDir(ray.dir, facing, povEta(pt, bandOf(i)), dir);
    }
    if (!anyThrough) return false;
    for (int i = 0; i < n; ++i) {
        const PovRay band = bandOf(i);
        const Vec3 share = povDispersionColor(i, n);
        Vec3 seen;
        if (povTransmitted(ray, pt, band, povEta(pt, band), T * share, ctx, info, seen)) {
            color += seen;
        } else {  // this band alone is reflected whole, with its share of the colour
            const PovRay mirrored = povReflectedRay(pt, band);
            const Vec3 dir = povMirrorDirection(ray.dir, pt.N, pt.Nfacing);
            ++ctx.stats.secondaryRays;
            color += share * tracePov(Ray{pt.P + kSurfaceOffset * dir, dir}, mirrored, ctx, info);
        }
    }
    return true;
}

int Tracer::povLights(const PovPoint& pt, double opacity, Vec3 V, TraceContext& ctx, Vec3& color,
                      bool countBlocked) const {
    const PovSurface& s = *pt.surface;
    const PovFinish& f = s.finish;
    const Vec3 P = pt.P, N = pt.N;
    // Which side's light can add anything: in front diffuse and highlights, behind the second
    // diffuse value, or everything with double_illuminate.
    const bool highlights = f.phong > 0 || f.specular > 0;
    const bool front = (f.diffuse != 0 && opacity != 0) || highlights;
    const bool back = s.doubleIlluminate ? front : (f.diffuseBack != 0 && opacity != 0);
    // The light at a point inside a fading interior is divided by the viewing rays' fade there
    // (measured; a channel faded to nothing is left alone).
    Vec3 scale(1.0);
    if (pt.interior >= 0)
        for (int i = 0; i < 3; ++i) scale[i] = pt.viewFade[i] > 0 ? 1.0 / pt.viewFade[i] : 1.0;
    // Subsurface light transport replaces each light's diffuse term by the light that entered
    // around the point (render/tracer_subsurface.cpp); the highlights stay.
    const bool subsurface = povSubsurfaceLit(s, pt);
    if (subsurface && opacity != 0) color += opacity * povSubsurfaceDiffuse(pt, s, pt.C, V, ctx);
    int blocked = 0;
    for (size_t li = 0; li < scene_.lights.size(); ++li) {
        const Light& light = scene_.lights[li];
        if (!povLightsSurface(light, s)) continue;
        Vec3 L;
        if (!povDirectionToLight(light, P, L)) continue;
        const double nl = dot(N, L);
        const bool useful = nl > 0 ? front : (nl < 0 && back);
        if (light.area && light.areaIllumination && pt.highlights && !countBlocked) {
            // Each sample decides its own side (the centre may lie behind the surface).
            const double grain = f.crand != 0 ? 1 - f.crand * ctx.rng.next() : 1.0;  // crand
            color += povAreaIlluminated(light, li, pt, V, scale, opacity * grain, !light.shadowless, ctx);
            continue;
        }
        if (!useful && !countBlocked) continue;
        const Vec3 arriving = povLightReaching(light, li, P, nl >= 0 ? N : -N, nl < 0, ctx, !pt.highlights);  // radiosity sees area lights as points (measured)
        if (countBlocked && maxComponent(arriving) < 0.5 * maxComponent(light.color)) ++blocked;
        const Vec3 reach = scale * arriving;
        if (!useful || reach == Vec3{}) continue;
        const PovLightTerms t = povLightTerms(s, pt.C, N, L, V, reach * povIridTint(f, scene_.pov.iridWavelength, N, L, V, P));
        const double grain = f.crand != 0 ? 1 - f.crand * ctx.rng.next() : 1.0;  // crand
        if (!subsurface) color += (opacity * grain) * t.diffuse;
        // Shadowless lights make no highlights (the manual; measured), nor do points radiosity gathers from.
        if (!light.shadowless && pt.highlights) color += t.highlight;
    }
    // Photons: their light lit as diffuse light arriving along the normal (measured: a mirror's
    // reflected light gives colour·cos θ, the cosine in the photons' density).
    if (photonMap_ && f.diffuse != 0 && opacity != 0 && povGathersPhotons(s, *pt.material))
        color += (opacity * f.diffuse) * scale * pt.C * povPhotonLight(P, N);
    return blocked;
}

// projected_through: how far from P, on the way to the light (its centre), the way first crosses
// one of the light's objects; negative when it crosses none (then the light does not reach P).
// Beyond that crossing nothing casts a shadow (measured with POV-Ray 3.7: the scene's own copy
// of the projector and objects between it and the light leave the projected light whole; objects
// between P and the projector shadow it).
double Tracer::povProjectorDistance(const Light& light, Vec3 P) const {
    const Vec3 toLight = light.parallel ? -light.direction : light.position - P;
    const double dist = length(toLight);
    if (dist == 0) return -1;
    const Ray ray{P, toLight / dist};
    double nearest = light.parallel ? kInfinity : dist;
    bool crossed = false;
    for (int i = 0; i < light.projectorCount; ++i) {
        ShapeHit hit;
        if (intersect(scene_.projectors[size_t(light.projectorBegin + i)], ray, kTMin, nearest, hit)) {
            nearest = hit.t;
            crossed = true;
        }
    }
    return crossed ? nearest : -1;
}

bool Tracer::povLightDimmed(const Light& light, Vec3 P, Vec3& color, double& shadowEnd) const {
    // Spotlights, cylindrical lights and fading dim the light before anything blocks it.
    color = light.color;
    if (light.spot != Light::Spot::None) color *= povSpotFactor(light, P - light.position);
    if (light.fadeDistance > 0) color *= povLightFade(light, length(P - light.position));
    shadowEnd = kInfinity;  // shadow rays stop at a projector (projected_through)
    if (light.projectorCount > 0) {
        shadowEnd = povProjectorDistance(light, P);
        if (shadowEnd < 0) return false;
    }
    return true;
}

Vec3 Tracer::povLightReaching(const Light& light, size_t index, Vec3 P, Vec3 Nl,
                              bool intoSurface, TraceContext& ctx, bool centreOnly) const {
    Vec3 color;
    double shadowEnd;
    if (!povLightDimmed(light, P, color, shadowEnd)) return {};
    if (light.shadowless || color == Vec3{}) return color;
    const Vec3 origin = P + kSurfaceOffset * Nl;
    if (light.parallel) {
        // Shadow rays end at the plane through the light's position across its direction; points
        // beyond that plane are lit unshadowed (the manual, "Parallel Lights"; measured).
        const double tMax = std::min(dot(light.position - origin, -light.direction), shadowEnd - kSurfaceOffset);
        if (tMax <= 0) return color;
        return color * povShadowTint(Ray{origin, -light.direction}, tMax, index, ctx, intoSurface, nullptr);
    }
    // Shadow rays are aimed at the light from their offset origin: aimed along L from P, they would
    // meet a surface through the light's position (radiosity/cornell.pov's lights sit in its
    // ceiling) before the light; povray lights such points (measured).
    if (!light.area || centreOnly) {
        const Vec3 toLight = light.position - origin;
        const double d = length(toLight);
        if (d == 0) return color;
        if (shadowEnd < d) {
            if (shadowEnd <= kSurfaceOffset) return color;
            return color * povShadowTint(Ray{origin, toLight / d}, shadowEnd - kSurfaceOffset, index, ctx, intoSurface, nullptr);
        }
        const FromLight fromLight{-toLight, d};
        return color * povShadowTint(Ray{origin, toLight / d}, d - kSurfaceOffset, index, ctx, intoSurface, &fromLight);
    }
    // Area light: the shading uses its centre (measured); its samples only decide how much of the
    // light arrives, each tinted by what lies on its shadow ray.
    const AreaGrid grid = areaGrid(light, settings_.areaSamples, P);
    auto sampleTint = [&](Vec3 pos) {
        const Vec3 toLight = pos - origin;
        const double d = length(toLight);
        const double end = std::min(d, shadowEnd) - kSurfaceOffset;
        if (d == 0 || end <= 0) return Vec3(1.0);
        return povShadowTint(Ray{origin, toLight / d}, end, index, ctx, intoSurface, nullptr);
    };
    // Weighed as POV-Ray weighs them (render/pov_area_mean.h); each sample, jittered or not, is
    // traced once.
    const size_t count = size_t(grid.n1) * size_t(grid.n2);
    thread_local std::vector<Vec3> tints;
    thread_local std::vector<uint8_t> known;
    if (tints.size() < count) tints.resize(count), known.resize(count);
    std::fill(known.begin(), known.begin() + std::ptrdiff_t(count), uint8_t(0));
    auto tintAt = [&](int u, int v) -> Vec3 {
        const size_t k = size_t(v) * size_t(grid.n1) + size_t(u);
        if (!known[k]) {
            known[k] = 1;
            tints[k] = sampleTint(areaSample(light, grid, u, v, ctx.rng));
        }
        return tints[k];
    };
    return color * povAreaMean(grid.n1, grid.n2, light.adaptive, tintAt);
}

// area_illumination (POV-Ray 3.7, "Area Illumination"): the shading is done for each sample, from
// its own direction, instead of once from the centre. Measured with POV-Ray 3.7 (16-bit linear, a
// sphere and a plane under grids of 1×2 to 5×5 samples): the result is the plain mean over the
// samples of their diffuse and highlight, unshadowed, times the share of the light that arrives,
// weighed as for any area light (povAreaMean) — where a sample lies behind the surface its shadow
// ray enters the object and counts as blocked (a sphere lit by a 3×3 grid with one column in front
// of it: the mean of the samples times 1/4, the weight of that column).
Vec3 Tracer::povAreaIlluminated(const Light& light, size_t index, const PovPoint& pt, Vec3 V, Vec3 scale,
                                double weight, bool highlights, TraceContext& ctx) const {
    const PovSurface& s = *pt.surface;
    Vec3 color;
    double shadowEnd;
    if (!povLightDimmed(light, pt.P, color, shadowEnd) || color == Vec3{}) return {};
    const AreaGrid grid = areaGrid(light, settings_.areaSamples, pt.P);
    const size_t count = size_t(grid.n1) * size_t(grid.n2);
    thread_local std::vector<Vec3> places, tints;
    thread_local std::vector<uint8_t> known;
    if (places.size() < count) places.resize(count), tints.resize(count), known.resize(count);
    std::fill(known.begin(), known.begin() + std::ptrdiff_t(count), uint8_t(0));
    Vec3 diffuse, highlight;
    for (int v = 0; v < grid.n2; ++v)
        for (int u = 0; u < grid.n1; ++u) {
            const size_t k = size_t(v) * size_t(grid.n1) + size_t(u);
            places[k] = areaSample(light, grid, u, v, ctx.rng);
            const Vec3 toSample = places[k] - pt.P;
            const double dist = length(toSample);
            if (dist == 0) continue;
            const Vec3 L = toSample / dist;
            const PovLightTerms t =
                povLightTerms(s, pt.C, pt.N, L, V, scale * color * povIridTint(s.finish, scene_.pov.iridWavelength, pt.N, L, V, pt.P));
            diffuse += t.diffuse;
            highlight += t.highlight;
        }
    // The share that arrives: each sample's shadow ray leaves on its own side of the surface.
    auto tintAt = [&](int u, int v) -> Vec3 {
        const size_t k = size_t(v) * size_t(grid.n1) + size_t(u);
        if (known[k]) return tints[k];
        known[k] = 1;
        tints[k] = Vec3(1.0);
        if (light.shadowless) return tints[k];
        const bool behind = dot(pt.N, places[k] - pt.P) < 0;
        const Vec3 origin = pt.P + kSurfaceOffset * (behind ? -pt.N : pt.N);
        const Vec3 toLight = places[k] - origin;
        const double d = length(toLight);
        const double end = std::min(d, shadowEnd) - kSurfaceOffset;
        if (d > 0 && end > 0) tints[k] = povShadowTint(Ray{origin, toLight / d}, end, index, ctx, behind, nullptr);
        return tints[k];
    };
    const Vec3 arriving = povAreaMean(grid.n1, grid.n2, light.adaptive, tintAt);
    return arriving * (weight * diffuse + (highlights ? highlight : Vec3{})) / double(count);
}

Vec3 Tracer::povShadowTint(const Ray& shadow, double tMax, size_t light, TraceContext& ctx, bool intoSurface,
                           const FromLight* fromLight) const {
    Vec3 tint(1.0);
    int blocker = Bvh::kNoBlocker;
    if (shadowed(shadow, tMax, light, ctx, intoSurface, fromLight, &blocker)) {
        // An opaque object in the way blocks the light whatever else lies there.
        if (!povShadowsWalk_ || (blocker >= 0 && povOpaque_[size_t(blocker)])) return {};
        // Only once photons were kept (on surfaces or in media): POV-Ray lights through refracting
        // targets as usual when none were (measured: a clear box around the glass that blocks
        // every photon).
        const bool photonsRefract = (photonMap_ || mediaPhotonMap_) && scene_.lights[light].photonRefraction;
        tint = povTransmittance(shadow, tMax, photonsRefract);
    }
    // Atmospheric media dim only the lights with media_attenuation on (the manual; measured).
    if (!scene_.pov.media.empty() && scene_.lights[light].mediaAttenuation && !(tint == Vec3{})) {
        PovMediaSet air;
        air.add(scene_.pov.media.data(), int(scene_.pov.media.size()));
        tint *= povMediaTransmittance(scene_, air, shadow, 0, std::min(tMax, kPovMediaMissDistance));
    }
    // So do fogs (measured).
    if (!scene_.pov.fogs.empty() && scene_.lights[light].mediaAttenuation && !(tint == Vec3{}))
        tint *= povFogLightTransmittance(scene_.pov.fogs, shadow, tMax);
    return tint;
}

Vec3 Tracer::povSurfaceTint(const Ray& ray, const Hit& h, const Object& o, const PovSurface& s) const {
    // The normal facing where the ray comes from (for the slope and aoi patterns).
    const Vec3 facing = dot(ray.dir, h.normal) < 0 ? h.normal : -h.normal;
    const Vec3 uv{h.u, h.v, 0};
    const Vec3* uvAt = h.hasUV ? &uv : nullptr;
    if (const int node = povTextureSeen(s, povMeetsOuterSide(o, ray.dir, h.geomNormal)); node >= 0)
        return povTextureTint(scene_, node, ray.at(h.t), facing, uvAt, ray.dir);  // a layered or patterned texture: each layer tints
    Vec3 C = o.material.color;
    double filter = o.material.filter, transmit = s.transmit;
    if (s.pigment >= 0) {
        const PovPigmentSample c = povPigmentAt(scene_, s, ray.at(h.t), facing, uvAt, ray.dir);
        C = c.color, filter = c.filter, transmit = c.transmit;
    }
    if (o.material.pigmentMap >= 0) {
        Vec3 N = h.normal;
        applyMaps(scene_, o, ray.at(h.t), SurfaceUV{h.hasUV, h.u, h.v, h.dpdu}, C, N);
    }
    return povFilterTint(C, filter, transmit);
}

Vec3 Tracer::povTransmittance(const Ray& shadow, double tMax, bool photonsRefract) const {
    // Fading interiors (object and surface) the ray went into and has not left, and those it has
    // met at all (only an interior not met yet can hold the start).
    struct Entry {
        int object, surface;
        bool is(int o, int s) const { return object == o && surface == s; }
    };
    Entry open[kMaxOpenInteriors], met[kMaxOpenInteriors];
    int openCount = 0, metCount = 0;
    double stretch = 0;  // where the stretch up to the next surface began: the start or the last surface
    struct MediaEntry {
        int object;
        double t;
        const PovInterior* interior;
    };
    MediaEntry inMedia[kMaxOpenInteriors];  // interiors with media entered and not yet left
    int inMediaCount = 0;
    Vec3 tint(1.0);
    // Interior media dim shadow rays over the length inside, with or without media_attenuation (measured).
    auto throughMedia = [&](const PovInterior& in, double from, double to) {
        if (in.mediaCount <= 0) return;
        PovMediaSet set;
        set.add(&scene_.povMedia[size_t(in.mediaFirst)], in.mediaCount);
        tint *= povMediaTransmittance(scene_, set, shadow, from, to);
    };
    double tMin = kTMin;
    for (int step = 0; step < kMaxShadowSurfaces; ++step) {
        const Hit h = bvh_.closest(scene_.objects, shadow, tMin, tMax);
        if (!h.valid()) {  // interiors not left before the light do not fade it (measured); media do
            for (int i = 0; i < inMediaCount; ++i) throughMedia(*inMedia[i].interior, inMedia[i].t, tMax);
            return tint;
        }
        const Object& o = shadedObject(scene_.objects, h);
        const PovSurface& s = povSurfaceOf(o.material);
        if (s.noShadow) {  // no_shadow: not there for shadow rays
            tMin = h.t + kTMin;
            continue;
        }
        if (!povLetsLightThrough(o.material, s)) return {};
        // A refracting photon target: its light arrives as photons (measured with POV-Ray 3.7: a
        // clear glass sphere then casts a full shadow, lit only by the photons it refracts).
        if (photonsRefract && s.photons.target && s.photons.refraction) return {};
        tint *= povSurfaceTint(shadow, h, o, s);
        if (s.interior.mediaCount > 0) {
            if (dot(shadow.dir, h.geomNormal) < 0) {
                if (inMediaCount < kMaxOpenInteriors) inMedia[inMediaCount++] = MediaEntry{h.object, h.t, &s.interior};
            } else {
                double from = 0;  // leaving an interior the ray started in: from its start
                for (int i = 0; i < inMediaCount; ++i)
                    if (inMedia[i].object == h.object) {
                        from = inMedia[i].t;
                        inMedia[i] = inMedia[--inMediaCount];
                        break;
                    }
                throughMedia(s.interior, from, h.t);
            }
        }
        if (s.interior.caustics > 0) {  // the surface's normal as its normal pattern tilts it (measured)
            const Vec3 facing = dot(shadow.dir, h.geomNormal) < 0 ? h.normal : -h.normal;
            const Vec3 N = s.normal >= 0 ? povNormalAt(scene_, s, shadow.at(h.t), facing) : facing;
            tint *= povCausticGain(s.interior.caustics, dot(N, shadow.dir));
        }
        // A stretch fades at its end, where the ray leaves a fading interior it went into, by
        // that interior, as viewing rays do (tracePov; measured with POV-Ray 3.7 on two
        // overlapping glass boxes between a light and a wall: the same figures as seen through).
        // Whether the ray leaves is decided by the interiors it went into, or, for one not met
        // yet, by whether it holds the start: a surface left without the start being inside (an
        // open object: a clipped cone over the floor it stands on) does not fade the light
        // (measured: a quadric cone clipped to a slab, fading, over a floor inside the cone's
        // infinite surface but outside the slab).
        if (povFades(s.interior)) {
            const int surface = o.material.pov;
            bool leaving = false;
            for (int i = 0; i < openCount && !leaving; ++i)
                if (open[i].is(h.object, surface)) {
                    open[i] = open[--openCount];
                    leaving = true;
                }
            bool seen = leaving;
            for (int i = 0; i < metCount && !seen; ++i) seen = met[i].is(h.object, surface);
            if (!seen) {
                if (metCount < kMaxOpenInteriors) met[metCount++] = Entry{h.object, surface};
                const Object& top = scene_.objects[size_t(h.object)];
                leaving = top.type == ShapeType::Csg ? insideCsg(*top.csg, 0, shadow.origin)
                                                     : insideShape(top, shadow.origin) != 0;
            }
            if (leaving) tint *= povFade(s.interior, h.t - stretch);
            else if (openCount < kMaxOpenInteriors) open[openCount++] = Entry{h.object, surface};
        }
        stretch = h.t;
        if (maxComponent(tint) <= 0) return {};
        tMin = h.t + kTMin;
    }
    return {};
}

}  // namespace rays
