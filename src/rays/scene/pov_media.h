// POV-Ray's participating media (POV-Ray 3.7 reference, "Media", "Media Types", "Sampling
// Parameters & Methods", "Density"): absorption, emission and scattering per unit of world length,
// scaled point by point by the product of the media's densities. Interior media fill an object
// (PovInterior::mediaFirst/mediaCount, entries of Scene::povMedia); atmospheric media fill the
// space outside objects and inside hollow ones (PovGlobals::media). render/pov_media.h samples them.
#pragma once
#include <cstdint>

#include "rays/math/vec3.h"

namespace rays {

struct PovMedia {
    /// scattering's type: 1 isotropic, 2 Mie hazy, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein.
    enum class Scattering : uint8_t { None, Isotropic, MieHazy, MieMurky, Rayleigh, HenyeyGreenstein };
    Vec3 absorption;  ///< light absorbed per unit length (colour)
    Vec3 emission;    ///< light emitted per unit length (colour)
    Vec3 scattering;  ///< light of the lights scattered per unit length (colour)
    Scattering type = Scattering::None;
    double eccentricity = 0;  ///< Henyey-Greenstein's g, −1 < g < 1
    double extinction = 1;    ///< the share of the scattering colour also taken out of the ray
    /// Sampling (the manual's defaults for 3.7, samples measured: a media without `samples` looks
    /// as with `samples 10`). Methods 1 and 2 are drawn by method 3's scheme: `samples` equal
    /// steps per interval (its maximum), aaLevel 0, method 1 with jitter 1.
    int method = 3;
    int intervals = 1;
    int samples = 10;
    int aaLevel = 3;
    double aaThreshold = 0.1;
    double jitter = 0;
    /// The densities multiplied together: roots [densityFirst, densityFirst + densityCount) of
    /// Scene::pigments (world → density space, then the density's node); none: density 1.
    int densityFirst = 0, densityCount = 0;

    /// Light taken out of a ray per unit length at density 1: absorption + extinction·scattering.
    Vec3 extinctionColor() const { return absorption + extinction * scattering; }
    bool scatters() const { return type != Scattering::None && !(scattering == Vec3{}); }

    bool operator==(const PovMedia&) const = default;
};

}  // namespace rays
