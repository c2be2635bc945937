// Whitted-style recursive ray tracer following the course conventions: local shading with hard
// shadows, mirror reflection, refraction with optional Schlick Fresnel and Beer's law.
#pragma once
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/accel/origin_buffer.h"
#include "rays/render/irradiance_cache.h"
#include "rays/render/photon_map.h"
#include "rays/render/pov_media.h"
#include "rays/render/sampler.h"
#include "rays/render/settings.h"
#include "rays/scene/scene.h"

namespace rays {

/// One node of the ray tree, as printed by `printrays`.
struct TraceRecord {
    enum class Kind { Primary, Reflection, Refraction };
    Kind kind = Kind::Primary;
    Ray ray;
    bool hit = false;
    int object = -1;            ///< index into scene.objects
    double t = 0;
    Vec3 point, normal;         ///< normal: outward geometric normal
    Ray objectRay;              ///< the ray in object space (meaningful when the object is transformed)
    Vec3 color;                 ///< final colour of this node
    Vec3 ambient, diffuse, specular, reflection, refraction;  ///< weighted contributions
    double wLocal = 0, wReflection = 0, wTransmission = 0;
    bool intoObject = false;    ///< refraction records: the ray travels inside an object
    int depth = 0;              ///< bounces after the primary ray (0: the primary ray)
};

/// Per-thread counters.
struct TraceStats {
    uint64_t primaryRays = 0, secondaryRays = 0, shadowRays = 0;
    void add(const TraceStats& o) {
        primaryRays += o.primaryRays;
        secondaryRays += o.secondaryRays;
        shadowRays += o.shadowRays;
    }
    uint64_t total() const { return primaryRays + secondaryRays + shadowRays; }
};

/// What a pixel sample saw, for edge detection and edge-guided anti-aliasing: the object ids of
/// the ray tree in depth-first order (primary hit first; −1 for a miss) and how many lights were
/// blocked at the primary hit (an area light counts when most of its samples are blocked).
struct PathInfo {
    static constexpr int kMaxIds = 4;
    int32_t ids[kMaxIds];
    int16_t count = 0;
    int16_t blockedLights = 0;
    float t = 0;            ///< primary hit distance
    float point[3];         ///< primary hit point
    float normal[3];        ///< primary shading normal facing the viewer
    void push(int id) {
        if (count < kMaxIds) ids[count++] = id;
    }
    void setHit(double dist, Vec3 p, Vec3 n) {
        t = float(dist);
        for (int k = 0; k < 3; ++k) {
            point[k] = float(p[k]);
            normal[k] = float(n[k]);
        }
    }
    Vec3 hitPoint() const { return {point[0], point[1], point[2]}; }
    Vec3 hitNormal() const { return {normal[0], normal[1], normal[2]}; }
    bool operator==(const PathInfo& o) const {
        if (count != o.count || blockedLights != o.blockedLights) return false;
        for (int i = 0; i < count; ++i)
            if (ids[i] != o.ids[i]) return false;
        return true;
    }
};

/// Per-thread mutable state of a trace: counters, the random numbers of the current pixel sample
/// and the shadow cache (the object that last blocked each light). The cache only changes which
/// object is tested first, never a result. Cache-line aligned: the contexts of the render threads
/// sit side by side in a vector and are written on every ray, so sharing a line would make the
/// threads wait on each other (gnarly.pov rendered 20 % slower on 2 threads that way).
struct alignas(64) TraceContext {
    static constexpr int kCachedLights = 16;
    TraceStats stats;
    SampleRng rng{0, 0, 0, 0};
    int lastBlocker[kCachedLights];  ///< per light: the object that blocked its last shadow ray (-1 after a miss)
    int surfaceObject = -1;  ///< the object being shaded (its shadow rays test it first when they go into it)
    /// Radiosity: the irradiance records this camera sample made (cleared for each camera ray; the
    /// pretrace collects them, the final pass only reuses them within the sample), and whether the
    /// pretrace is running (its error bound is lower).
    std::vector<IrradianceRecord> radLocal;
    bool radPretrace = false;
    TraceContext() { std::fill(std::begin(lastBlocker), std::end(lastBlocker), -1); }
};

/// Origin buffers (accel/origin_buffer.h) for the rays of a render that share an origin: the
/// primary rays of a pinhole camera and the shadow rays towards point lights. Optional: without
/// them the tracer walks the BVH for every ray, with the same results.
struct SharedOrigins {
    OriginBuffer eye;                  ///< empty when not built
    std::vector<OriginBuffer> lights;  ///< per scene light; empty for area and parallel lights
};

class Tracer {
public:
    /// Secondary rays leave a surface this far: course scenes along the normal (reflection and
    /// shadow rays on the viewer's side, refraction rays on the far side), POV-Ray scenes along
    /// the new ray (shadow rays: along the normal).
    static constexpr double kSurfaceOffset = 0.001;

    /// Hits closer than this along a ray are ignored.
    static constexpr double kMinHitT = 1e-6;

    /// Scenes with Scene::pov.enabled are traced by POV-Ray's rules (tracer_povray.cpp) unless the
    /// settings ask for the flat or normals views.
    Tracer(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, const SharedOrigins* origins = nullptr)
        : scene_(scene), bvh_(bvh), settings_(settings), origins_(origins), povPath_(usesPovPath(scene, settings)),
          povOpaque_(povPath_ ? povOpaqueObjects() : std::vector<uint8_t>{}),
          povShadowsWalk_(std::find(povOpaque_.begin(), povOpaque_.end(), uint8_t(0)) != povOpaque_.end()),
          povHides_(povPath_ && povHides()),
          povMedia_(povPath_ && povHasMedia()), povMediaHolders_(povMedia_ ? povMediaHolders() : std::vector<PovMediaHolder>{}),
          povCameraInside_(povPath_ ? povCameraInside() : std::vector<PovRay::Inside>{}),
          primaryReach_(primaryReach(scene, settings)) {}

    /// Buffers for the scene's point lights and, when eye is given, for primary rays from it.
    /// primarySamples: the render's camera samples (each buffer is queried about that often).
    /// None for scenes with few objects, where the BVH alone is as fast, or with more objects than
    /// a quarter of the samples, where the build would cost more than it saves; at most as many
    /// buffers as fit in memoryBudget bytes (lights first, in scene order). threads: for the build.
    static SharedOrigins buildSharedOrigins(const Scene& scene, const Bvh& bvh, const Vec3* eye, double primarySamples,
                                            int threads, double memoryBudget = kSharedOriginsBytes);
    /// Memory the buffers of one render may take, estimated at kSharedOriginsBytesPerObject per
    /// object and buffer (balls2.pov: 27 for a light's buffer, 86 for the eye's).
    static constexpr double kSharedOriginsBytes = 64.0 * 1024 * 1024;
    static constexpr double kSharedOriginsBytesPerObject = 64.0;

    /// Colour seen along a primary ray. When log is non-null the ray tree is appended to it in
    /// depth-first order (each node before its children, the refraction subtree before the
    /// reflection one, as the course traces them; course scenes only); when info is non-null
    /// it receives the ids along the tree and the primary hit's blocked lights. Random decisions
    /// (area-light jitter, global illumination) draw from ctx.rng. POV-Ray scenes give the colour
    /// in the scene's working space (render() encodes it for output: render/pov_output.h).
    Vec3 tracePrimary(const Ray& ray, TraceContext& ctx, std::vector<TraceRecord>* log = nullptr,
                      PathInfo* info = nullptr) const;

    /// Nearest hit along ray (t > small epsilon).
    Hit firstHit(const Ray& ray) const;

    /// What a ray sees without shading it, for feature lines: ids along the ray tree (only the
    /// primary hit unless followSecondary), the primary hit's t and facing normal, and (when
    /// countShadows) how many lights are blocked there (area lights tested at their centre).
    void probe(const Ray& ray, bool countShadows, bool followSecondary, TraceContext& ctx, PathInfo& out) const;

    /// Number of lights blocked at P (normal N facing the viewer); area lights are tested at their centre.
    int blockedLightsAt(Vec3 P, Vec3 N, TraceContext& ctx) const;

    /// POV-Ray radiosity's irradiance cache (render/radiosity_pretrace.h fills it before the final
    /// pass); null: every point gathers its own light.
    void setRadiosityCache(const IrradianceCache* cache) { radCache_ = cache; }

    /// POV-Ray's photons (tracer_photons.cpp): every light's photons shot at every target, those
    /// left on surfaces after a reflection or refraction, and with `media` in the photons block
    /// those left in scattering media on the way (POV-Ray scenes with photons).
    struct PovShotPhotons {
        std::vector<Photon> surface, media;
    };
    PovShotPhotons povShootPhotons(int threads) const;
    /// The photon map shading reads (render/photon_shooting.h builds it); null: no photons.
    void setPhotonMap(const PhotonMap* map, const PhotonGather& gather) {
        photonMap_ = map;
        photonGather_ = gather;
    }
    /// The photons left in media, which the media's samples read; null: none.
    void setMediaPhotonMap(const PhotonMap* map, const PhotonGather& gather) {
        mediaPhotonMap_ = map;
        mediaPhotonGather_ = gather;
    }

private:
    struct Result {
        Vec3 color;
        double t = kInfinity;  ///< distance to the hit (for Beer's law)
    };
    struct Frame {  // per-ray arguments of the recursion
        int depth = 0;
        int giLevel = 0;
        TraceRecord::Kind kind = TraceRecord::Kind::Primary;
        bool inside = false;
    };
    Result trace(const Ray& ray, const Frame& f, TraceContext& ctx, std::vector<TraceRecord>* log,
                 PathInfo* info) const;
    /// The shading model for a material: the render's flat/normals modes win, then the object's own.
    ShadingModel modelFor(const Material& m) const;
    /// Direct light at P; returns the number of lights counted as blocked. Without countBlocked
    /// the count is not wanted (only the shading), and lights behind the surface (N·L ≤ 0) whose
    /// light the model ignores anyway get no shadow ray (and count as blocked).
    int localShading(const Material& m, ShadingModel model, Vec3 P, Vec3 N, Vec3 V, TraceContext& ctx,
                     Vec3& diffuse, Vec3& specular, bool countBlocked) const;
    /// Visible fraction and shading of one light (all its samples) at P. skipFacingAway: samples
    /// with N·L ≤ 0 count as blocked without a shadow ray.
    double shadeLight(const Light& light, size_t index, const Material& m, ShadingModel model, Vec3 P, Vec3 N,
                      Vec3 V, TraceContext& ctx, Vec3& diffuse, Vec3& specular, bool skipFacingAway) const;
    void probeRec(const Ray& ray, int depth, bool countShadows, bool followSecondary, TraceContext& ctx,
                  PathInfo& out) const;
    /// The ambient term at P. Without GI ka·C. With GI (course part 6) below the last GI level
    /// E, the plain mean of what the cosine-weighted sample rays bring back (giPhysical: the
    /// Lambertian estimate kd·C·E), and nothing at the last level.
    Vec3 ambientTerm(const Material& m, Vec3 P, Vec3 N, const Frame& f, TraceContext& ctx) const;
    /// Cosine-weighted average of the light arriving at P (global illumination).
    Vec3 gatherIndirect(Vec3 P, Vec3 N, const Frame& f, TraceContext& ctx) const;
    /// intoSurface: the ray leaves towards the inside of the surface being shaded, which then
    /// most likely blocks it (tested first).
    /// For a point light: the vector from the light to the shadow ray's origin and its length.
    struct FromLight {
        Vec3 toPoint;
        double dist;
    };
    /// fromLight (point lights) lets the light's origin buffer answer. When shadowed, *blocker (if
    /// given) gets the object found in the way, or Bvh::kSomeTriangle.
    bool shadowed(const Ray& shadow, double tMax, size_t light, TraceContext& ctx, bool intoSurface = false,
                  const FromLight* fromLight = nullptr, int* blocker = nullptr) const;

    // POV-Ray's lighting model (tracer_povray.cpp; docs/povray-lighting.md).
    /// Per-ray arguments of POV-Ray's recursion: the trace level (the camera ray is 1; reflected
    /// and refracted rays add one, rays passing straight through a surface keep it), the weight
    /// adc_bailout compares, the object whose interior the ray travels in (−1: none), whether that
    /// interior fades the ray (transmitted rays only, measured), and how much the rays before it
    /// inside that interior faded (what the colour it brings back will go through there).
    struct PovRay {
        int level = 1;
        double weight = 1;
        int interior = -1;
        /// The Material::pov of the (leaf) surface the ray entered that interior by (−1: the
        /// object's own): each child of a CSG keeps its own interior.
        int interiorSurface = -1;
        bool fades = false;
        Vec3 faded{1, 1, 1};
        bool primary = false;
        bool reflected = false;  ///< a reflection is on the ray's way from the camera
        int radLevel = 0;        ///< radiosity bounces on the ray's way from the camera
        bool gathering = false;  ///< a radiosity gathering ray (or one of its children): no highlights
        double reach = kInfinity;  ///< objects farther along the ray are not met (a mesh camera's max_distance)
        /// A ray split by dispersion (render/pov_dispersion.h) carries its band of the spectrum:
        /// every interior's index is then ior·dispersion^spectral for it.
        bool dispersed = false;
        double spectral = 0;
        /// The objects the ray is inside (entered and not left), innermost last, each with the
        /// Material::pov of the (leaf) surface it entered by (−1: any of the object's surfaces, for
        /// a CSG the camera starts in): for media, and for whether a hit enters or leaves an
        /// interior (PovPoint::intoInterior). Nested ones beyond kMaxInside are not kept.
        struct Inside {
            int object = -1, surface = -1;
            bool is(int o, int s) const { return object == o && (surface == s || surface < 0 || s < 0); }
        };
        static constexpr int kMaxInside = 8;
        Inside inside[kMaxInside]{};
        int insideCount = 0;
        bool isInside(int object, int surface) const {
            for (int i = 0; i < insideCount; ++i)
                if (inside[i].is(object, surface)) return true;
            return false;
        }
        void enter(int object, int surface) {
            if (!isInside(object, surface) && insideCount < kMaxInside) inside[insideCount++] = Inside{object, surface};
        }
        void leave(int object, int surface) {
            for (int i = insideCount - 1; i >= 0; --i)
                if (inside[i].is(object, surface)) {
                    for (int k = i + 1; k < insideCount; ++k) inside[k - 1] = inside[k];
                    --insideCount;
                    return;
                }
        }
        void copyInside(const PovRay& o) {
            insideCount = o.insideCount;
            for (int i = 0; i < insideCount; ++i) inside[i] = o.inside[i];
        }
    };
    /// How far camera rays reach: the render's mesh camera's max_distance, else infinity.
    static double primaryReach(const Scene& scene, const RenderSettings& settings);
    /// True when the scene is traced by POV-Ray's rules: pov.enabled, and not the flat or normals view.
    static bool usesPovPath(const Scene& scene, const RenderSettings& settings);
    /// povOpaque_'s flags: per object, whether each of its surfaces (a CSG's leaves too) blocks
    /// light and casts shadows.
    std::vector<uint8_t> povOpaqueObjects() const;
    /// True when some object is hidden from camera or reflection rays (no_image, no_reflection).
    bool povHides() const;
    /// firstHit, passing the objects hidden from this kind of ray (no_image: camera rays and
    /// their transmitted rays; no_reflection: rays after a reflection).
    /// gathering: a radiosity gathering ray, which also passes no_radiosity objects.
    Hit povFirstHit(const Ray& ray, bool reflected, bool gathering = false) const;
    /// tracePrimary of POV-Ray scenes (a camera ray at level 1, weight 1, in no interior).
    Vec3 tracePovPrimary(const Ray& ray, TraceContext& ctx, PathInfo* info) const;
    /// Colour along a ray (the background when it misses), faded by the interior it travels in or
    /// seen through the scene's fogs outside objects.
    Vec3 tracePov(const Ray& ray, const PovRay& r, TraceContext& ctx, PathInfo* info) const;
    /// A surface point being shaded: the object and its surface, position, normal facing the
    /// viewer (maps applied), pigment colour, which side the ray came from, the interior the point
    /// lies in (−1: none) and how much the viewing rays faded in it on the way to the point.
    /// POV-Ray 3.7 divides the light reaching the point by that fade, so that direct light there
    /// is faded over the shadow ray's path only (measured, docs/povray-lighting.md).
    struct PovPoint {
        int object = -1;
        const Material* material = nullptr;
        const PovSurface* surface = nullptr;
        Vec3 P, N, C;
        Vec3 Nfacing;        ///< the shape's normal facing the viewer, before any normal pattern
        Vec3 uv;             ///< the surface's (u, v, 0) when hasUV (uv-mapped patterns)
        bool hasUV = false;
        const Vec3* uvPoint() const { return hasUV ? &uv : nullptr; }
        double filter = 0, transmit = 0;  ///< the pigment's at P
        bool entering = true;  ///< the ray meets the surface's outer side (the geometric normal's)
        /// The ray goes into the object's interior here rather than out of it: decided, as POV-Ray
        /// does, by whether the ray is already inside the object (PovRay::inside), not by the side
        /// it meets (measured with POV-Ray 3.7: a glass height field under a mirroring scale, whose
        /// open underside a ray crosses without a hit, is entered through its top surface).
        bool intoInterior = true;
        int interior = -1;
        Vec3 viewFade{1, 1, 1};
        bool highlights = true;  ///< false for points seen by radiosity's gathering rays (measured)
    };
    /// The point hit on o as every POV-Ray shading path starts it: object, material, surface, P,
    /// side, the ray's interior and the fade up to the hit (N, C, filter and transmit not yet set).
    PovPoint povPointOf(const Ray& ray, const Hit& hit, const Object& o, const PovRay& r, Vec3 segmentFade) const;
    /// A cut of cutaway_textures inside two or more textured leaves: shadePov with each of their
    /// textures, averaged (hit.cutawayBlend).
    Vec3 shadePovCutaway(const Ray& ray, const Hit& hit, const PovRay& r, Vec3 segmentFade, TraceContext& ctx,
                         PathInfo* info) const;
    /// A mesh face textured per vertex: shadePov with each corner's texture, blended (hit.blend).
    Vec3 shadePovCorners(const Ray& ray, const Hit& hit, const PovRay& r, Vec3 segmentFade, TraceContext& ctx,
                         PathInfo* info) const;
    /// Colour of the surface hit: local light, reflection and transmission. segmentFade: how much
    /// the interior fades this ray up to the hit (1 when it does not).
    Vec3 shadePov(const Ray& ray, const Hit& hit, const PovRay& r, Vec3 segmentFade, TraceContext& ctx,
                  PathInfo* info) const;
    /// What the reflected and transmitted rays from a point bring (total internal reflection
    /// included), within max_trace_level and adc_bailout.
    Vec3 povSecondary(const Ray& ray, const PovPoint& pt, const PovRay& r, TraceContext& ctx, PathInfo* info) const;
    /// The recursion arguments of a ray reflected at pt (its weight still r's).
    PovRay povReflectedRay(const PovPoint& pt, const PovRay& r) const;
    /// Adds to color what the ray transmitted at pt brings, weighted by T (bent about pt.N by the
    /// index ratio eta, povEta's); false, adding nothing, under total internal reflection.
    bool povTransmitted(const Ray& ray, const PovPoint& pt, const PovRay& r, double eta, Vec3 T, TraceContext& ctx,
                        PathInfo* info, Vec3& color) const;
    // Layered and patterned textures (tracer_pov_texture.cpp).
    /// One layer at the point being shaded: its surface, pigment, normal (facing the viewer),
    /// opacity, reflectivity, and what the layers above let through to it.
    struct PovLayerAt {
        const PovSurface* surface = nullptr;
        Vec3 C, N, R;
        double filter = 0, transmit = 0, opacity = 0;
        Vec3 through{1, 1, 1};
    };
    /// shadePov for a surface with a layered or patterned texture (node `texture` of
    /// Scene::povTextures, the side's: povTextureSeen): the textures the pattern shows
    /// at the hit, each lit in full, blended by their weights (POV-Ray 3.7 reference, "Texture Maps").
    Vec3 shadePovTextured(const Ray& ray, const Hit& hit, const PovRay& r, Vec3 segmentFade, TraceContext& ctx,
                          PathInfo* info, int texture) const;
    /// One run of layers at pt (POV-Ray 3.7 reference, "Layered Textures"; measured): each layer's
    /// own colour and highlights lit with its own finish and normal and filtered by the layers
    /// above it, each layer's reflection unfiltered, what all the layers let through transmitted.
    Vec3 shadePovLayers(const Ray& ray, const Hit& hit, PovPoint pt, int begin, int count, const PovRay& r,
                        TraceContext& ctx, PathInfo* info) const;
    /// povLights for layers: each light's arrival found once (from the top layer's side), each
    /// layer's diffuse (weighted by its opacity) and highlights added, filtered by what lies above it.
    int povLayerLights(const PovPoint& pt, const PovLayerAt* layers, int count, Vec3 V, TraceContext& ctx,
                       Vec3& color, bool countBlocked) const;
    /// Adds every light's diffuse (weighted by opacity) and highlights at the point (seen from V)
    /// to color; returns the number of lights of which less than half reaches it (counted only
    /// when countBlocked).
    int povLights(const PovPoint& pt, double opacity, Vec3 V, TraceContext& ctx, Vec3& color,
                  bool countBlocked) const;
    /// Whether the diffuse light of surface s at pt comes from subsurface light transport (a
    /// finish with subsurface, global_settings' subsurface block, not a radiosity gathering point).
    bool povSubsurfaceLit(const PovSurface& s, const PovPoint& pt) const;
    /// The diffuse light of s (pigment C) at pt seen from V by subsurface light transport
    /// (render/tracer_subsurface.cpp): it replaces every light's diffuse term there.
    Vec3 povSubsurfaceDiffuse(const PovPoint& pt, const PovSurface& s, Vec3 C, Vec3 V, TraceContext& ctx) const;
    /// projected_through: the distance from P towards the light to the first of the light's
    /// objects, or negative when the way crosses none of them.
    double povProjectorDistance(const Light& light, Vec3 P) const;
    /// The light of one light that reaches P: its colour dimmed by a spotlight's cone and light
    /// fading (shadowless lights: nothing more), tinted by transparent objects on the way, times the
    /// visible share of an area light's samples; shadow rays leave P on side Nl, aimed at the light
    /// (each sample) from there. centreOnly: an area light as a point
    /// light at its centre (the points radiosity gathers from: measured, docs/povray-lighting.md).
    /// The light's colour at P before anything blocks it (spotlight cone, cylinder, fading), and
    /// where its shadow rays end (a projected_through projector; infinite without one); false
    /// when a projector keeps the light from P altogether.
    bool povLightDimmed(const Light& light, Vec3 P, Vec3& color, double& shadowEnd) const;
    Vec3 povLightReaching(const Light& light, size_t index, Vec3 P, Vec3 Nl, bool intoSurface,
                          TraceContext& ctx, bool centreOnly = false) const;
    /// An area light with area_illumination at pt: the plain mean over its samples of the diffuse
    /// and highlight each gives from its own place, unshadowed, times the share of the light that
    /// arrives (its samples' shadow rays weighed as povAreaMean weighs them); the light's colour
    /// dimmed at its centre as povLightReaching dims it.
    Vec3 povAreaIlluminated(const Light& light, size_t index, const PovPoint& pt, Vec3 V, Vec3 scale,
                            double weight, bool highlights, TraceContext& ctx) const;
    /// 1 when nothing lies on the shadow ray before tMax, else what the objects on it let through.
    Vec3 povShadowTint(const Ray& shadow, double tMax, size_t light, TraceContext& ctx, bool intoSurface,
                       const FromLight* fromLight) const;
    /// Walks the surfaces on the shadow ray before tMax, passing no_shadow objects: each tints by
    /// filter·C + transmit, interiors with fading fade over the length inside (from the ray's start
    /// for one it began in, none for one it does not leave); an opaque surface (or too many) blocks.
    /// photonsRefract: the light shoots refraction photons, so refracting photon targets block it.
    Vec3 povTransmittance(const Ray& shadow, double tMax, bool photonsRefract) const;
    /// What the surface hit at h lets through along the ray: filter·C + transmit of its pigment
    /// there (each layer's of a layered texture).
    Vec3 povSurfaceTint(const Ray& ray, const Hit& h, const Object& o, const PovSurface& s) const;
    /// The surface whose interior ray r travels in (r.interior ≥ 0).
    const PovSurface& povInteriorOf(const PovRay& r) const;
    const PovSurface& povSurfaceOf(const Material& m) const;
    // POV-Ray's photons (tracer_photons.cpp; docs/povray-lighting.md, "Photons").
    /// Follows one photon from the light along start: it must meet target first (objects with
    /// pass_through or no_shadow let it by), then reflects and refracts as the objects' and the
    /// light's photons blocks allow, up to maxLevel and down to bailout, and is left (power: its
    /// light times the area it stands for, solid·distance² or, for parallel lights, solid) on each
    /// collecting surface after the first reflection or refraction.
    /// With media (not null), photons are also left in scattering media along its way once it has
    /// met its target (povLeaveInMedia).
    void povTracePhoton(const Light& light, int target, const Ray& start, double solid, int maxLevel, double bailout,
                        std::vector<Photon>& stored, std::vector<Photon>* media) const;
    /// Leaves photons along the stretch [0, length] of ray in scattering media (tracer_photons.cpp):
    /// color is the light the photon carries there (dimmed by the media's extinction on the way),
    /// area(d) the area it stands for at distance d from the light, travelled the distance at the
    /// ray's origin.
    template <class Area>
    void povLeaveInMedia(const Ray& ray, double length, double travelled, Vec3& color, const Area& area,
                         std::vector<Photon>& media) const;
    /// The photons' irradiance at P on the side N faces (0 without a photon map).
    Vec3 povPhotonLight(Vec3 P, Vec3 N) const;
    // POV-Ray's media (tracer_media.cpp; docs/povray-lighting.md, "Media").
    /// True when some object's interior or the atmosphere holds media.
    bool povHasMedia() const;
    /// The media the stretch of ray r travels in: those of the interiors it is inside, and the
    /// atmosphere's outside objects and inside hollow ones.
    PovMediaSet povMediaOf(const PovRay& r) const;
    /// True when the ray runs outside objects or inside hollow ones only: where fog and rainbows are.
    bool povInAtmosphere(const PovRay& r) const;
    /// The iridescence tint of a reflection off N of a ray along dir (1 without irid).
    Vec3 povReflectionIrid(const PovFinish& f, Vec3 N, Vec3 dir, Vec3 P) const;
    /// `behind` (what the ray sees at t) seen through the media of the stretch [0, t] (a miss: as
    /// far as kPovMediaMissDistance): dimmed, plus the light the media emit and scatter towards
    /// the viewer (method 3: equal steps refined where neighbouring samples differ).
    Vec3 povMediaAlong(const Ray& ray, double t, const PovRay& r, Vec3 behind, TraceContext& ctx) const;
    /// What the media do at a point: light taken out per unit length (extinction) and light
    /// added per unit length towards the viewer looking along dir (emission plus scattering).
    struct PovMediaPoint {
        Vec3 extinction, source;
    };
    PovMediaPoint povMediaPoint(const PovMediaSet& set, Vec3 P, Vec3 dir, TraceContext& ctx) const;
    /// Running sums of the integration: the light added so far and the share still let through.
    struct PovMediaSum {
        Vec3 added, through{1, 1, 1};
    };
    /// Adds the step [a, b] (a's sample pa, b's pb) to sum, halving it while the samples differ
    /// by more than aa_threshold, up to aa_level halvings.
    void povMediaStep(const PovMediaSet& set, const Ray& ray, double a, const PovMediaPoint& pa, double b,
                      const PovMediaPoint& pb, int level, TraceContext& ctx, PovMediaSum& sum) const;
    /// The objects whose interior holds media: their index and Material::pov (for a CSG, its
    /// first leaf with media).
    struct PovMediaHolder {
        int object, surface;
        Bounds bounds;  ///< the object's world box
    };
    std::vector<PovMediaHolder> povMediaHolders() const;
    /// A camera ray starting inside an object with media travels in its interior (the last such
    /// object in the scene's order holding the origin).
    void povStartInside(Vec3 origin, PovRay& r) const;
    /// Whether p is inside o (a CSG's inside, or the shape's).
    static bool povHolds(const Object& o, Vec3 p);
    /// Surfaces nearer to each other than kTouching·max(1, t) along a ray touch (povTouching).
    static constexpr double kTouching = 1e-9;
    /// hit, or where the ray leaves an object there, another object's surface touching it (povTouching's comment).
    Hit povTouching(const Ray& ray, const Hit& hit, const PovRay& r) const;
    /// The objects whose inside holds the camera's location (POV-Ray scenes): camera rays start in them.
    std::vector<PovRay::Inside> povCameraInside() const;
    /// The index ratio the fresnel reflection at pt uses: the refraction's, except where the ray
    /// leaves an object while inside another (a glass in a sky sphere, or the camera inside a
    /// plane's half-space): there POV-Ray reflects nothing by fresnel (measured), as for ratio 1.
    static double povFresnelEta(const PovPoint& pt, const PovRay& r, double eta);
    /// The ratio n_from/n_to of the indices on the two sides of pt, as POV-Ray 3.7 takes them: the
    /// interior the ray is in (the one it entered last, air when none) and the one it enters, or
    /// the one it leaves and the one it is then in (measured: nested half-spaces of ior 1.5 and
    /// 1.2 or 1, and a cavity cut out of glass by a difference).
    double povEta(const PovPoint& pt, const PovRay& r) const;
    /// The ior of the interior the ray entered by `in` (its surface's; the object's own for −1),
    /// for the ray's band of the spectrum when it is dispersed.
    double povIorOf(const PovRay::Inside& in, const PovRay& r) const;
    /// An interior's ior for ray r (its dispersion applied to a dispersed ray).
    static double povIorFor(const PovInterior& in, const PovRay& r);
    /// The transmission at pt split into the dispersion samples of the interior crossed there
    /// (each band refracted by its own index, weighted by its colour); false when pt's interior
    /// does not disperse r.
    bool povDispersed(const Ray& ray, const PovPoint& pt, const PovRay& r, Vec3 T, TraceContext& ctx, PathInfo* info,
                      Vec3& color) const;
    /// Methods 1 and 2: adds [a, b] in `steps` equal steps sampled in their middles.
    void povMediaMidpoints(const PovMediaSet& set, const Ray& ray, double a, double b, int steps, TraceContext& ctx,
                           PovMediaSum& sum) const;
    /// Light of the light `index` reaching P inside a medium (spot, fading, shadows, media on the
    /// way); toLight becomes the unit direction towards the light. Area lights from their centre.
    Vec3 povMediaLight(size_t index, Vec3 P, Vec3& toLight, TraceContext& ctx) const;
    // POV-Ray's radiosity (tracer_radiosity.cpp; docs/povray-lighting.md, "Radiosity").
    /// The light radiosity brings at a point once: brightness and gray_threshold applied, nothing at
    /// recursion_limit.
    struct PovGathered {
        bool done = false;
        Vec3 light;
    };
    /// (ambient·ambient_light + emission)·C, or with radiosity povRadiosityAmbient with the light
    /// gathered at P about the unperturbed normal N facing the viewer (found once per point in g).
    Vec3 povAmbientTerm(const PovFinish& f, Vec3 C, Vec3 P, Vec3 N, const PovRay& r, TraceContext& ctx,
                        PovGathered& g) const;
    /// The irradiance at P: blended from the cache's and this sample's records, or gathered anew
    /// (and kept in ctx.radLocal).
    Vec3 povIrradiance(Vec3 P, Vec3 N, const PovRay& r, TraceContext& ctx) const;
    /// A new record: `count` cosine-distributed rays about N, their hits shaded one radiosity level
    /// deeper without highlights; R their harmonic mean distance clamped by minimum/maximum_reuse.
    IrradianceRecord povGatherRecord(Vec3 P, Vec3 N, const PovRay& r, TraceContext& ctx) const;

    const Scene& scene_;
    const Bvh& bvh_;
    const RenderSettings& settings_;
    const SharedOrigins* origins_;
    bool povPath_;         ///< the scene is traced by POV-Ray's rules
    /// POV-Ray scenes: per object, 1 when each of its surfaces blocks light and casts shadows (a
    /// shadow ray it is found in the way of needs no walk).
    std::vector<uint8_t> povOpaque_;
    /// Some object is not opaque (lets light through: filter, transmit; or casts no shadow):
    /// blocked shadow rays then walk the surfaces on their way.
    bool povShadowsWalk_;
    bool povHides_;        ///< and some are hidden from camera or reflection rays
    bool povMedia_;        ///< and some interiors or the atmosphere hold media
    std::vector<PovMediaHolder> povMediaHolders_;
    std::vector<PovRay::Inside> povCameraInside_;  ///< povCameraInside(), found once
    const IrradianceCache* radCache_ = nullptr;
    const PhotonMap* photonMap_ = nullptr;
    PhotonGather photonGather_;
    const PhotonMap* mediaPhotonMap_ = nullptr;
    PhotonGather mediaPhotonGather_;
    double primaryReach_;  ///< POV-Ray camera rays meet nothing farther (primaryReach)
};

}  // namespace rays
