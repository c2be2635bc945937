// POV-Ray's photons (POV-Ray 3.7 reference, "Photons"; what they do to the picture measured with
// povray 3.7, docs/povray-lighting.md "Photons"). Each light shoots photons at each target object:
// directions spaced so that neighbouring photons are `spacing`·the target's scale apart at the
// distance of the target's bounding sphere's centre, in rings about the direction to that centre
// (Jensen, "Realistic Image Synthesis Using Photon Mapping", 2001, ch. 5: photons aimed at the
// specular objects only). A photon that reflects or refracts off the target (and then off any
// object whose photons block allows it) is left on each surface it meets afterwards that
// collects photons. Its power makes the light it brings equal to what the light's colour brings
// directly (POV-Ray's lights do not dim with distance: measured, a mirror's reflection gives
// colour·cos θ at any distance); render/photon_map.h estimates it at shading.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <numbers>

#include "rays/geometry/refract.h"
#include "rays/render/photon_shooting.h"
#include "rays/render/pov_lighting.h"
#include "rays/render/pov_media.h"
#include "rays/render/pov_normal.h"
#include "rays/render/renderer.h"
#include "rays/render/tracer.h"
#include "rays/scene/shapes/box_clip.h"

namespace rays {
namespace {

// A photon's random numbers (jitter) from its place in the shooting order alone (splitmix64).
double unitHash(uint64_t a, uint64_t b) {
    uint64_t z = a * 0x9E3779B97F4A7C15ull + b + 0x632BE59BD9B4E5Bull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return double(z >> 11) * 0x1.0p-53;
}

void basisAbout(Vec3 w, Vec3& u, Vec3& v) {
    const Vec3 a = std::fabs(w.x) > 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    u = normalize(cross(a, w));
    v = cross(w, u);
}

// A photon target: a top-level object whose (or some of whose CSG children's) photons block says target.
struct Target {
    int object;
    Vec3 centre;
    double radius, scale;
    bool optic;  ///< its photons block turns refraction or reflection on
};

// A photon on its way: its ray, the light it carries (before the area factor), the distance
// travelled so far, the trace level and how many reflections and refractions it went through.
struct InFlight {
    Ray ray;
    Vec3 color;
    double travelled = 0;
    int level = 1;
    int bounces = 0;
    bool reached = false;  ///< it has met its target
    int inSolid = 0;       ///< how deep it is inside objects that are not hollow (it refracted into)
};

constexpr int kMaxInFlight = 64;

}  // namespace

Tracer::PovShotPhotons Tracer::povShootPhotons(int threads) const {
    const PovPhotonSettings& ps = scene_.pov.photons;
    PovShotPhotons shot;
    std::vector<Photon>& stored = shot.surface;
    if (!ps.enabled) return shot;
    std::vector<Target> targets;
    for (size_t i = 0; i < scene_.objects.size(); ++i) {
        const Object& o = scene_.objects[i];
        const PovPhotonFlags* flags = &povSurfaceOf(o.material).photons;
        if (o.type == ShapeType::Csg)
            for (const Object& leaf : o.csg->leaves)
                if (povSurfaceOf(leaf.material).photons.target) flags = &povSurfaceOf(leaf.material).photons;
        if (!flags->target) continue;
        Target t{int(i), {}, 0, flags->spacingScale, flags->refraction || flags->reflection};
        if (worldBoundingSphere(o, t.centre, t.radius) && t.radius > 0) targets.push_back(t);
    }
    if (targets.empty()) return shot;
    // Which lights shoot at which targets (measured with POV-Ray 3.7): a light without a photons
    // block at the targets that refract or reflect photons; one with a block that turns
    // refraction or reflection on at every target (a clear target without either lets the
    // photons through to what lies inside: advanced/optics' media box).
    const auto shoots = [](const Light& l, const Target& t) {
        return l.photonBlock ? l.photonRefraction || l.photonReflection : t.optic;
    };
    // The cone a point light sees a target's sphere under: the distance to its centre and the
    // half-angle. A light inside the sphere shoots all round, its photons spaced as at the
    // sphere's radius.
    const auto cone = [](const Light& l, const Target& t, double& dist, double& thetaMax) {
        dist = length(t.centre - l.position);
        thetaMax = dist > t.radius ? std::asin(t.radius / dist) : std::numbers::pi;
        dist = std::max(dist, t.radius);
    };
    // Σ over lights and targets of the area the photons cover at the target's distance over the
    // square of the target's spacing scale: photons shot = this / spacing².
    double covered = 0;
    for (const Light& l : scene_.lights) {
        for (const Target& t : targets) {
            if (!shoots(l, t)) continue;
            double d, th;
            cone(l, t, d, th);
            const double area = l.parallel ? std::numbers::pi * t.radius * t.radius
                                           : 2 * std::numbers::pi * (1 - std::cos(th)) * d * d;
            covered += area / (t.scale * t.scale);
        }
    }
    double spacing = ps.spacing > 0 ? ps.spacing : std::sqrt(covered / std::max(1.0, ps.count));
    // Bounded: at most kMaxPhotonsShot photons leave the lights (the spacing widens to keep it).
    const double shots = covered / (spacing * spacing);
    if (shots > double(kMaxPhotonsShot)) spacing *= std::sqrt(shots / double(kMaxPhotonsShot));
    const int maxLevel = ps.maxTraceLevel > 0 ? ps.maxTraceLevel : scene_.pov.maxTraceLevel;
    const double bailout = ps.adcBailout >= 0 ? ps.adcBailout : scene_.pov.adcBailout;

    // The photons go out in strips (a ring of directions about a target from a point light, a
    // row of the grid across a parallel light's beam), traced in parallel, each strip's photons
    // kept apart and joined in strip order: the map is the same for any number of threads.
    struct Strip {
        int light, target, index;
    };
    std::vector<Strip> strips;
    for (size_t li = 0; li < scene_.lights.size(); ++li) {
        for (size_t ti = 0; ti < targets.size(); ++ti) {
            const Target& t = targets[ti];
            if (!shoots(scene_.lights[li], t)) continue;
            const double s = spacing * t.scale;
            double d, thetaMax;
            cone(scene_.lights[li], t, d, thetaMax);
            const int count = scene_.lights[li].parallel ? 2 * int(std::ceil(t.radius / s)) + 1
                                                         : int(std::ceil(thetaMax / (s / d))) + 1;
            for (int i = 0; i < count; ++i) strips.push_back(Strip{int(li), int(ti), i});
        }
    }
    std::vector<std::vector<Photon>> left(strips.size()), leftInMedia(strips.size());
    const bool inMedia = ps.mediaMaxSteps > 0 && povMedia_;
    // The strips finished keep at most kMaxPhotonsStored together, each running strip at most
    // that many more (which ones are kept then depends on the threads' timing: only a map that
    // reaches the limit). Counted once per strip: the threads share no counter per photon.
    std::atomic<size_t> kept{0};
    std::atomic<size_t> keptInMedia{0};
    const auto full = [&](const std::vector<Photon>& out, const std::vector<Photon>* media) {
        return kept.load(std::memory_order_relaxed) + out.size() >= kMaxPhotonsStored ||
               (media && keptInMedia.load(std::memory_order_relaxed) + media->size() >= kMaxPhotonsStored);
    };
    const auto strip = [&](int index) {
        const Strip& strip = strips[size_t(index)];
        const Light& light = scene_.lights[size_t(strip.light)];
        const Target& t = targets[size_t(strip.target)];
        std::vector<Photon>& out = left[size_t(index)];
        std::vector<Photon>* media = inMedia ? &leftInMedia[size_t(index)] : nullptr;
        const double s = spacing * t.scale;
        double d, thetaMax;
        cone(light, t, d, thetaMax);
        const uint64_t stream = (uint64_t(strip.light) << 40) ^ (uint64_t(strip.target) << 20) ^ uint64_t(strip.index);
        if (light.parallel) {
            // A row of the square grid across the beam, over the disc the target's sphere covers.
            Vec3 u, v;
            basisAbout(light.direction, u, v);
            const double back = dot(t.centre - light.position, light.direction);
            const int half = int(std::ceil(t.radius / s));
            const int i = strip.index - half;
            for (int j = -half; j <= half; ++j) {
                const uint64_t n = uint64_t(j + half);
                const double a = (i + ps.jitter * (unitHash(stream, 2 * n) - 0.5)) * s;
                const double b = (j + ps.jitter * (unitHash(stream, 2 * n + 1) - 0.5)) * s;
                if (a * a + b * b > t.radius * t.radius) continue;
                const Vec3 origin = t.centre + a * u + b * v - back * light.direction;
                povTracePhoton(light, t.object, Ray{origin, light.direction}, s * s, maxLevel, bailout, out, media);
                if (full(out, media)) return;
            }
            return;
        }
        // A ring about the direction to the target's centre, dθ = s/d from the previous one, with
        // photons dθ apart along it.
        const Vec3 toCentre = t.centre - light.position;
        const Vec3 w = length(toCentre) > 0 ? normalize(toCentre) : Vec3{0, 0, 1};
        Vec3 u, v;
        basisAbout(w, u, v);
        const double step = s / d;
        const double solid = step * step;  // the solid angle each photon stands for
        const double theta0 = strip.index * step;
        const int around =
            strip.index == 0 ? 1 : std::max(1, int(std::lround(2 * std::numbers::pi * std::sin(theta0) / step)));
        for (int k = 0; k < around; ++k) {
            const uint64_t n = uint64_t(k);
            const double theta = std::clamp(theta0 + ps.jitter * (unitHash(stream, 2 * n) - 0.5) * step, 0.0, thetaMax);
            const double phi = (k + 0.5 + ps.jitter * (unitHash(stream, 2 * n + 1) - 0.5)) * 2 * std::numbers::pi / around;
            const Vec3 dir = std::cos(theta) * w + std::sin(theta) * (std::cos(phi) * u + std::sin(phi) * v);
            povTracePhoton(light, t.object, Ray{light.position, dir}, solid, maxLevel, bailout, out, media);
            if (full(out, media)) return;
        }
    };
    const std::function<void(int, int)> shoot = [&](int index, int) {
        strip(index);
        kept.fetch_add(left[size_t(index)].size(), std::memory_order_relaxed);
        keptInMedia.fetch_add(leftInMedia[size_t(index)].size(), std::memory_order_relaxed);
    };
    rays::parallelFor(int(strips.size()), threads, shoot);
    const auto join = [](const std::vector<std::vector<Photon>>& parts, std::vector<Photon>& into) {
        size_t total = 0;
        for (const std::vector<Photon>& l : parts) total += l.size();
        into.reserve(std::min(total, kMaxPhotonsStored));
        for (const std::vector<Photon>& l : parts) {
            const size_t room = kMaxPhotonsStored - into.size();
            into.insert(into.end(), l.begin(), l.begin() + long(std::min(room, l.size())));
            if (into.size() >= kMaxPhotonsStored) break;
        }
    };
    join(left, stored);
    join(leftInMedia, shot.media);
    return shot;
}

// Photons in media (the reference manual, "Photons" > "Photons and Media": `media max_steps,
// factor` leaves photons along their way through media; Jensen 2001, ch. 10, the volume photon
// map). Along the stretch, steps of the photon spacing there times factor, at most max_steps of
// them: at the middle of each step inside a scattering medium a photon is left, carrying the
// light times the area it stands for times the step's length (so that the volume estimate gives
// the light the beam brings, as the lights' own in-scattering does), and the light is dimmed by
// the media's extinction over the step. The media are those of the objects holding the point (the
// innermost is not sought: any holder's scattering media count) or, outside them all, the
// atmosphere's.
template <class Area>
void Tracer::povLeaveInMedia(const Ray& ray, double length, double travelled, Vec3& color, const Area& area,
                             std::vector<Photon>& media) const {
    const PovPhotonSettings& ps = scene_.pov.photons;
    if (!(length > 0) || !std::isfinite(length)) return;
    // Without atmospheric media only the part of the stretch within the holders' boxes is stepped.
    double from = 0, to = length;
    if (scene_.pov.media.empty()) {
        from = kInfinity, to = -kInfinity;
        for (const PovMediaHolder& holder : povMediaHolders_) {
            double a = 0, b = length;
            if (!clipRayToBox(holder.bounds, ray, a, b)) continue;
            from = std::min(from, a);
            to = std::max(to, b);
        }
        if (!(from < to)) return;
    }
    const double spacing = std::sqrt(area(travelled + from)) * ps.mediaFactor;
    const int steps = int(std::clamp(std::ceil((to - from) / std::max(spacing, 1e-9)), 1.0, double(ps.mediaMaxSteps)));
    const double h = (to - from) / steps;
    for (int k = 0; k < steps; ++k) {
        const double x = from + (k + 0.5) * h;
        const Vec3 P = ray.at(x);
        Vec3 extinction;
        bool scatters = false, held = false;
        const auto add = [&](const PovMedia* first, int count) {
            for (int i = 0; i < count; ++i) {
                const PovMedia& m = first[i];
                const Vec3 d = povMediaDensity(scene_, m, P);
                if (d == Vec3{}) continue;
                extinction += m.extinctionColor() * d;
                scatters = scatters || m.scatters();
            }
        };
        for (const PovMediaHolder& holder : povMediaHolders_) {
            const Object& o = scene_.objects[size_t(holder.object)];
            if (!povHolds(o, P)) continue;
            held = true;
            const PovInterior& in = scene_.povSurfaces[size_t(holder.surface)].interior;
            add(&scene_.povMedia[size_t(in.mediaFirst)], in.mediaCount);
        }
        if (!held && !scene_.pov.media.empty()) add(scene_.pov.media.data(), int(scene_.pov.media.size()));
        if (scatters && maxComponent(color) > 0) {
            const Vec3 power = color * area(travelled + x) * h;
            Photon ph;
            for (int a = 0; a < 3; ++a) {
                ph.position[a] = float(P[a]);
                ph.power[a] = float(power[a]);
                ph.dir[a] = float(ray.dir[a]);
            }
            media.push_back(ph);
            if (media.size() >= kMaxPhotonsStored) return;
        }
        for (int c = 0; c < 3; ++c)
            if (extinction[c] > 0) color[c] *= std::exp(-extinction[c] * h);
    }
}

void Tracer::povTracePhoton(const Light& light, int target, const Ray& start, double solid, int maxLevel,
                            double bailout, std::vector<Photon>& stored, std::vector<Photon>* media) const {
    std::array<InFlight, kMaxInFlight> todo;
    int count = 0;
    todo[count++] = InFlight{start, light.color};
    // The area a photon stands for where it lands: solid·travelled² from a point light (its light
    // then falls off as 1/travelled², which the area makes up for), s² from a parallel one.
    const auto area = [&](double travelled) { return light.parallel ? solid : solid * travelled * travelled; };
    while (count > 0) {
        InFlight f = todo[--count];
        for (;;) {
            const Hit h = bvh_.closest(scene_.objects, f.ray, kMinHitT, kInfinity);
            // Once it has met its target it lights the media it goes through (outside objects it
            // refracted into that are not hollow), as the light itself does: POV-Ray adds both (measured: advanced/optics' beam before its first mirror, in
            // the media box that is the target, is the light's and the photons'; a spotlight's
            // beam through a media box towards a glass target keeps its direct light).
            if (media && f.reached && f.inSolid == 0 && (h.valid() || !scene_.pov.media.empty()))
                povLeaveInMedia(f.ray, h.valid() ? h.t : kPovMediaMissDistance, f.travelled, f.color, area, *media);
            if (!h.valid()) break;
            const Object& o = shadedObject(scene_.objects, h);
            const PovSurface& s = povSurfaceOf(o.material);
            const Vec3 P = f.ray.at(h.t);
            f.travelled += h.t;
            // What the surface lets through here (zero for a layered texture over an opaque layer).
            const Vec3 T = povLetsLightThrough(o.material, s) ? povSurfaceTint(f.ray, h, o, s) : Vec3{};
            const bool clear = maxComponent(T) > 0;
            // At its target a photon reflects and refracts as the target's photons block says;
            // after it, off every object as its finish says (measured with POV-Ray 3.7: a mirror
            // without a photons block reflects the photons that passed a clear target).
            const bool atTarget = !f.reached;
            const bool reflects = light.photonReflection && (!atTarget || s.photons.reflection);
            const bool refracts = light.photonRefraction && clear && (!atTarget || s.photons.refraction);
            if (atTarget) {
                // On its way to the target other objects block it, unless they let photons pass.
                if (h.object != target) {
                    if (!(s.photons.passThrough || s.noShadow)) break;
                    f.ray = Ray{P + kSurfaceOffset * f.ray.dir, f.ray.dir};
                    continue;
                }
                double shadowEnd;
                Vec3 dimmed;
                if (!povLightDimmed(light, P, dimmed, shadowEnd)) break;  // spotlight cone, cylinder, fading
                f.color = dimmed;
                f.reached = true;
                if (!reflects && !refracts) {
                    // A clear target that neither reflects nor refracts photons lets them through
                    // unchanged (advanced/optics' media box); an opaque one stops them.
                    if (!clear) break;
                    f.ray = Ray{P + kSurfaceOffset * f.ray.dir, f.ray.dir};
                    continue;
                }
            } else if (f.bounces > 0 && s.photons.collect && s.finish.diffuse != 0 && !refracts) {
                // Not kept on a surface it refracts through: POV-Ray keeps about one photon per
                // photon shot through a glass holding a drink (measured, grenadine.pov), and a
                // photon caught by total internal reflection in a thin glass wall would be kept
                // at every bounce.
                const Vec3 power = f.color * area(f.travelled);
                Photon ph;
                for (int a = 0; a < 3; ++a) {
                    ph.position[a] = float(P[a]);
                    ph.power[a] = float(power[a]);
                    ph.dir[a] = float(f.ray.dir[a]);
                }
                stored.push_back(ph);
                if (stored.size() >= kMaxPhotonsStored) return;
            }
            if (f.level >= maxLevel || (!reflects && !refracts)) break;
            // The normal facing the photon, tilted by the surface's normal pattern (a bumpy
            // mirror scatters its caustic).
            const Vec3 Nfacing = dot(f.ray.dir, h.normal) < 0 ? h.normal : -h.normal;
            const Vec3 N = s.normal >= 0 ? povNormalAt(scene_, s, P, Nfacing) : Nfacing;
            const bool entering = dot(f.ray.dir, h.geomNormal) < 0;
            const double ior = s.interior.ior > 0 ? s.interior.ior : 1.0;
            const double eta = entering ? 1.0 / ior : ior;
            const double cosIn = -dot(f.ray.dir, N);
            const Vec3 mirror = povMirrorDirection(f.ray.dir, N, Nfacing);
            // Leaving an interior that fades light: faded over the stretch just crossed inside.
            if (!entering && povFades(s.interior)) f.color *= povFade(s.interior, h.t);
            const Vec3 R = reflects || s.finish.conserveEnergy ? povReflectivity(s, o.material.color, cosIn, eta) : Vec3{};
            InFlight next = f;
            next.level = f.level + 1;
            next.bounces = f.bounces + 1;
            // Total internal reflection sends everything the way a reflection would go: once.
            Vec3 through = f.ray.dir;
            const bool bends = refracts && (eta == 1 || refractDir(f.ray.dir, N, eta, through));
            if (reflects && (bends || !refracts)) {
                if (maxComponent(f.color * R) > bailout && count < kMaxInFlight) {
                    InFlight r = next;
                    r.ray = Ray{P + kSurfaceOffset * mirror, mirror};
                    r.color = f.color * R;
                    todo[count++] = r;
                }
            }
            if (refracts) {
                const Vec3 passed = bends && s.finish.conserveEnergy ? T * (Vec3(1.0) - R) : T;  // as camera rays (povSecondary)
                const Vec3 dir = bends ? through : mirror;
                if (maxComponent(f.color * passed) > bailout) {
                    // Straight through a surface of index 1 it keeps its level and stays as it
                    // was (a photon that only passed clear surfaces is direct light: not kept).
                    if (eta != 1) f = next;
                    // Inside an object that is not hollow the media around it are not (POV-Ray's
                    // media leave such objects out: measured, advanced/optics' lenses show no beam).
                    if (bends && !s.hollow && s.interior.mediaCount == 0) f.inSolid = std::max(0, f.inSolid + (entering ? 1 : -1));
                    f.ray = Ray{P + kSurfaceOffset * dir, dir};
                    f.color = next.color * passed;
                    continue;
                }
            }
            break;
        }
    }
}

Vec3 Tracer::povPhotonLight(Vec3 P, Vec3 N) const {
    return photonMap_ ? photonMap_->irradiance(P, N, photonGather_) : Vec3{};
}

void preparePhotons(Tracer& tracer, const Scene& scene, int threads, PhotonMap& map, PhotonMap& mediaMap) {
    const PovPhotonSettings& ps = scene.pov.photons;
    if (!scene.pov.enabled || !ps.enabled) return;
    Tracer::PovShotPhotons shot = tracer.povShootPhotons(threads);
    map = PhotonMap(std::move(shot.surface));
    mediaMap = PhotonMap(std::move(shot.media));
    PhotonGather g;
    g.max = ps.gatherMax;
    g.expandPercent = ps.expandPercent;
    g.expandMin = ps.expandMin;
    if (!map.empty()) {
        g.radius = ps.radius > 0 ? ps.radius : map.typicalRadius(ps.gatherMax);
        tracer.setPhotonMap(&map, g);
    }
    if (!mediaMap.empty()) {
        PhotonGather m = g;
        // Twice the surface photons' rule (measured on advanced/optics: SSIM 0.919 with the
        // surface rule, 0.927 with twice it, 0.927 with three times).
        m.radius = 2 * mediaMap.typicalRadius(ps.gatherMax);
        tracer.setMediaPhotonMap(&mediaMap, m);
    }
}

}  // namespace rays
