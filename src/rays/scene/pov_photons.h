// POV-Ray 3.7's photons (the reference manual's "Photons" section: global_settings { photons { } },
// an object's and a light's photons blocks). What the photons do to the picture was measured with
// povray 3.7 (docs/povray-lighting.md, "Photons").
#pragma once

namespace rays {

/// The most photons one estimate gathers (gather's and expand_thresholds' numbers are clamped to it).
inline constexpr int kMaxPhotonGather = 1000;
/// The most photons a stretch of a photon's way through media leaves (media's max_steps is clamped to it).
inline constexpr int kMaxMediaPhotonSteps = 1000;

/// global_settings { photons { ... } }.
struct PovPhotonSettings {
    bool enabled = false;
    /// Photons leave a light this far apart where they meet a target (at the distance of the
    /// target's bounding sphere's centre); 0: derived from count (0.5 when neither is given).
    double spacing = 0;
    double count = 0;          ///< about this many photons shot in all (when spacing is not given)
    int gatherMin = 20;        ///< gather min, max: photons used for an estimate
    int gatherMax = 100;
    double jitter = 0.4;       ///< each photon's direction moves up to ± jitter/2 of the spacing
    int maxTraceLevel = -1;    ///< −1: the scene's max_trace_level
    double adcBailout = -1;    ///< −1: the scene's adc_bailout
    double radius = 0;         ///< the gather radius; 0: found from the photons
    double expandPercent = 0.2;  ///< expand_thresholds: the radius grows by this share ...
    int expandMin = 40;          ///< ... where fewer photons than this lie within it
    /// media max_steps, factor: photons are also left in scattering media along their way, at
    /// most mediaMaxSteps per stretch, spacing·mediaFactor apart (0: none).
    int mediaMaxSteps = 0;
    double mediaFactor = 1;
};

/// An object's photons block; nested objects take their parent's.
struct PovPhotonFlags {
    bool target = false;        ///< lights shoot photons at the object
    double spacingScale = 1;    ///< target's number: the spacing for this object is spacing·this
    bool refraction = false;    ///< photons refract through the object's transparent surfaces
    bool reflection = false;    ///< photons reflect off its reflecting surfaces
    bool collect = true;        ///< photons landing on it are kept (caustics show on it)
    bool passThrough = false;   ///< photons on their way to a target go through it untouched

    bool operator==(const PovPhotonFlags&) const = default;
};

}  // namespace rays
