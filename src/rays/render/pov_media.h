// POV-Ray media along a ray (POV-Ray 3.7 reference, "Media", "Media Types", "Sampling Parameters
// & Methods", "Density"): the pieces the tracer's integration uses (tracer_media.cpp), kept free
// of the tracer so that tests can check them. docs/povray-lighting.md, "Media", says what was
// measured and what is approximated.
#pragma once
#include <cstdint>

#include "rays/scene/pov_media.h"
#include "rays/scene/scene.h"

namespace rays {

/// Length given to a ray that meets nothing: atmospheric media fill it that far (measured:
/// emission 1e-11 over a miss shows as 0.2).
constexpr double kPovMediaMissDistance = 2e10;

/// The share of a light's light a medium scatters towards the viewer, per unit of its scattering
/// colour; cosAngle is the cosine of the angle between the light's direction of travel and the
/// direction to the viewer (1: the light comes from straight behind the medium). Published
/// formulas, scaled as POV-Ray 3.7 draws them (measured): isotropic 1; Mie hazy and Mie murky
/// Nishita et al.'s approximations (1996, "Display method of the sky color taking into account
/// multiple scattering") k·(1 + 9·((1 + cos)/2)^8) and k·(1 + 50·((1 + cos)/2)^32); Rayleigh
/// k·(1 + cos²); Henyey-Greenstein (1941) (1 − g²)/(1 + g² − 2g·cos)^1.5 with g the eccentricity.
double povMediaPhase(const PovMedia& m, double cosAngle);

/// The media's density at the world point P: the product of its densities' colours (1 without
/// densities).
Vec3 povMediaDensity(const Scene& scene, const PovMedia& m, Vec3 P);

/// Equal steps method 3 takes across each interval before refining: ⌊max(samples, 3)/2⌋ + 1
/// (measured: an absorbing and emitting medium of constant density looks exactly as these steps
/// summed, each step's light dimmed by the steps before it).
int povMediaSteps(int samples);
/// The equal steps per interval of a media: method 3's as above, methods 1 and 2 one per sample.
int povMediaSteps(const PovMedia& m);

/// The media a stretch of a ray travels in: an interior's media and, outside objects or inside
/// hollow ones, the atmospheric media. Merged sampling settings: the most steps, intervals and
/// aa_level, the lowest aa_threshold, the most jitter.
struct PovMediaSet {
    struct Span {
        const PovMedia* first = nullptr;
        int count = 0;
    };
    static constexpr int kMaxSpans = 6;
    Span spans[kMaxSpans];
    int spanCount = 0;
    bool scatters = false;  ///< some medium scatters light
    /// The lights that may light the media along the stretch (scene light indices), when known:
    /// lights with media_interaction whose beam the stretch meets. Null: every light.
    const uint16_t* lights = nullptr;
    int lightCount = 0;
    int steps = 1, intervals = 1, aaLevel = 0;  ///< steps: equal steps per interval (povMediaSteps)
    bool midpoints = false;  ///< methods 1 and 2 (the first media's method decides): steps sampled in their middles
    double aaThreshold = 1e300, jitter = 0;

    void add(const PovMedia* first, int count);
    bool empty() const { return spanCount == 0; }
};

/// Where the ray crosses the edges of the light's beam (a spotlight's radius and falloff cones, a
/// cylindrical light's radius and falloff cylinders), strictly between t0 and t1, appended to
/// out (at most `room` more); returns how many. Other lights have no edges.
int povLightBeamEdges(const Light& light, const Ray& ray, double t0, double t1, double* out, int room);

/// How much light a straight path through the set's media lets through (exp of minus the optical
/// depth, the depth summed over each interval's equal steps).
Vec3 povMediaTransmittance(const Scene& scene, const PovMediaSet& set, const Ray& ray, double t0, double t1);

}  // namespace rays
