// POV-Ray's surface model for objects of POV-Ray scenes (POV-Ray 3.7 reference, "Finish",
// "Interior"): finish and interior values, and the colour's transmit, kept apart from the course
// Material (which stays small for the course's big scenes) and referenced by Material::pov.
#pragma once
#include <cstdint>
#include <vector>

#include "rays/math/vec3.h"
#include "rays/scene/pov_media.h"
#include "rays/pattern/color_map.h"
#include "rays/pattern/noise.h"
#include "rays/scene/pov_photons.h"
#include "rays/scene/pov_radiosity.h"
#include "rays/scene/pov_subsurface.h"

namespace rays {

struct PovFinish {
    Vec3 ambient{0.1, 0.1, 0.1};  ///< ambient colour, multiplied by the scene's ambient_light
    Vec3 emission{0, 0, 0};       ///< emission colour (not multiplied by ambient_light)
    double diffuse = 0.6;         ///< diffuse amount: C·Lc·diffuse·(N·L)^brilliance
    double diffuseBack = 0;       ///< diffuse's second value: light from behind the surface
    double brilliance = 1;
    double phong = 0, phongSize = 40;       ///< phong·Lc·(R·V)^phong_size
    double specular = 0, roughness = 0.05;  ///< specular·Lc·(N·H)^(1/roughness)
    double metallic = 0;                    ///< highlights tinted by the pigment (0..1)
    Vec3 reflectionMin{0, 0, 0};  ///< reflection seen along the normal (variable reflection)
    Vec3 reflectionMax{0, 0, 0};  ///< reflection at grazing angles; both equal for plain `reflection C`
    bool reflectionFresnel = false;
    double reflectionFalloff = 1, reflectionExponent = 1, reflectionMetallic = 0;
    bool conserveEnergy = false;
    /// Graininess: each light's diffuse term times 1 − crand·U, U uniform in [0, 1) drawn per light
    /// and pixel sample (the manual, "Crand Graininess"; the distribution measured).
    double crand = 0;
    /// irid { amount thickness T turbulence U }: thin-film interference tinting each light
    /// (render/pov_lighting.h, povIridTint); amount 0: none.
    double irid = 0, iridThickness = 0, iridTurbulence = 0;
    /// subsurface { translucency C }: each channel's mean free path below the surface in
    /// millimetres (render/pov_subsurface.h); subsurface false: none given.
    bool subsurface = false;
    Vec3 translucency{0, 0, 0};

    bool operator==(const PovFinish&) const = default;
};

struct PovInterior {
    double ior = 1;             ///< 1: transparent surfaces let rays through unbent
    double fadeDistance = 0;    ///< 0: no fading inside
    double fadePower = 0;
    Vec3 fadeColor{0, 0, 0};
    /// The interior's media: entries [mediaFirst, mediaFirst + mediaCount) of Scene::povMedia.
    int mediaFirst = 0, mediaCount = 0;
    double caustics = 0;        ///< fake caustics' power (0: none): render/pov_lighting.h, povCausticGain
    /// `dispersion` (the ratio of violet's index to red's; 1: none) and `dispersion_samples`
    /// (the rays a refraction into it splits into): render/pov_dispersion.h.
    double dispersion = 1;
    int dispersionSamples = 7;
    /// Which `interior { }` block it came from (0: none, the default interior): only compared, so
    /// that the children of one CSG with blocks of their own stay apart even when the blocks read
    /// alike, as POV-Ray keeps them apart (a ray going from one into the other leaves the first).
    /// Copies of one declared object share their block.
    uint64_t block = 0;

    bool operator==(const PovInterior&) const = default;
};

struct PovSurface {
    PovFinish finish;
    PovInterior interior;
    double transmit = 0;        ///< the pigment's transmit (its filter is Material::filter)
    bool doubleIlluminate = false;
    bool noShadow = false;      ///< the object casts no shadow (POV-Ray's no_shadow; looks_like objects)
    bool noImage = false;       ///< not seen by camera rays nor rays transmitted from them (no_image)
    bool noReflection = false;  ///< not seen by rays after a reflection (no_reflection)
    bool noRadiosity = false;   ///< not seen by radiosity's gathering rays (no_radiosity)
    bool hollow = false;        ///< atmospheric media fill the object (POV-Ray's hollow)
    /// The light_group the object is in (-1: none): lit by that group's lights, and by the scene's
    /// lights only with the group's global_lights (POV-Ray 3.7 reference, "Light Groups"; measured).
    int lightGroup = -1;
    bool globalLights = true;
    /// The pigment pattern: a root of Scene::pigments, or -1 for the flat colour (Material::color,
    /// Material::filter and transmit above; with a pattern those hold its mean colour).
    int pigment = -1;
    bool pigmentTransparent = false;  ///< some colour of the pattern filters or transmits
    int normal = -1;  ///< the normal pattern: a root of Scene::normals, or -1 (the surface's own normal)
    /// A layered or patterned texture: a node of Scene::povTextures, lit layer by layer (the fields
    /// above then hold the layers' mix, for shading paths that know one look only); -1: plain.
    int texture = -1;
    /// interior_texture: a node of Scene::povTextures drawing the inner side (rays arriving from
    /// inside, shadow rays leaving); -1: both sides look alike.
    int interiorTexture = -1;
    PovPhotonFlags photons;  ///< the object's photons block (render/photon_map.h)

    bool operator==(const PovSurface&) const = default;
};

/// A fog layer (POV-Ray 3.7 reference, "Fog"; the details measured, docs/povray-lighting.md).
/// A ray segment of length d keeps a = max(exp(−D/distance), transmit) of the colour behind,
/// filtered by 1 − filter + filter·color, and adds (1 − a)·color, where D is d (constant fog) or,
/// for ground fog, the integral along the segment of the density 1 below offset and
/// 1/(1 + ((h − offset)/alt)²) above it, h the height along up. Turbulence thins D (povFog).
struct PovFog {
    bool ground = false;  ///< fog_type 2
    double distance = 0;
    Vec3 color;
    double filter = 0, transmit = 0;
    double offset = 0, alt = 0;
    Vec3 up{0, 1, 0};  ///< unit
    pattern::Turbulence turbulence;  ///< turbulence (amount off: none), octaves, omega, lambda
    double turbDepth = 0.5;          ///< where along the segment the turbulence is read (0 eye, 1 hit)
};

/// A rainbow (POV-Ray 3.7 reference, "Rainbow"): a fog-like arc of colours by the angle between
/// the ray and `direction` (render/pov_rainbow.h).
struct PovRainbow {
    Vec3 direction{0, 0, 1};  ///< unit
    double angle = 0, width = 0;
    double distance = 1e7;  ///< as a fog's
    double jitter = 0;
    Vec3 up{0, 1, 0};
    double arcAngle = 360, falloffAngle = 360;  ///< degrees (measured: the full circle by default)
    std::vector<pattern::MapEntry> map;         ///< colours (flat entries)
};

/// Scene-wide settings of POV-Ray scenes (global_settings, background).
struct PovGlobals {
    bool enabled = false;            ///< the scene follows POV-Ray's rules (objects use PovSurface)
    /// Working gamma: output = sRGB(c^assumedGamma). 0: the colour is written as it is (legacy
    /// scenes without assumed_gamma, and `assumed_gamma srgb`; measured, docs/povray-lighting.md).
    double assumedGamma = 1.0;
    /// The scene's #version (below 3.7, also no #version at all: the surface's own colour keeps
    /// 1 − (filter·max(r,g,b) + transmit) of its weight instead of 1 − filter − transmit).
    double version = 3.7;
    Vec3 ambientLight{1, 1, 1};
    int maxTraceLevel = 5;
    double adcBailout = 1.0 / 255.0;
    Vec3 background{0, 0, 0};
    /// irid_wavelength: the film's wavelengths per channel. The default is POV-Ray 3.7's as
    /// measured (<0.70, 0.52, 0.48>; the manual still gives 3.6's <0.25, 0.18, 0.14>).
    Vec3 iridWavelength{0.70, 0.52, 0.48};
    int noiseGenerator = 2;    ///< global_settings' noise_generator (patterns without their own)
    int numberOfWaves = 10;    ///< global_settings' number_of_waves (1 to 10: pattern/ripples.h)
    std::vector<PovFog> fogs;  ///< applied together to every ray outside objects
    /// Atmospheric media (top-level `media` blocks): outside objects and inside hollow ones.
    std::vector<PovMedia> media;
    std::vector<PovRainbow> rainbows;  ///< applied, before the fogs, to every ray outside objects
    /// sky_sphere: its pigments, bottom layer first, as roots [skyFirst, skyFirst + skyCount) of
    /// Scene::pigments looked up by ray direction; none: the background colour.
    int skyFirst = -1, skyCount = 0;
    Vec3 skyEmission{1, 1, 1};  ///< sky_sphere's emission: the sky's colour is multiplied by it
    /// A sky_sphere of #version 3.7 or later composes its layers as a layered texture does (each
    /// over the ones below, the bottom one over the background); an older one as POV-Ray 3.6 did
    /// (render/pov_pigment.h, povSky).
    bool skyLayersAsTexture = true;
    PovRadiosity radiosity;     ///< global_settings' radiosity block (render/tracer_radiosity.cpp)
    PovPhotonSettings photons;  ///< global_settings' photons block (render/tracer_photons.cpp)
    PovSubsurfaceSettings subsurface;  ///< global_settings' subsurface block and mm_per_unit (render/pov_subsurface.h)
};

}  // namespace rays
