// Subsurface light transport for POV-Ray scenes: the dipole diffusion model of Jensen, Marschner,
// Levoy and Hanrahan, "A Practical Model for Subsurface Light Transport" (SIGGRAPH 2001), the
// material's reduced albedo found from the colour it should show as in Jensen and Buhler, "A Rapid
// Hierarchical Rendering Technique for Translucent Materials" (SIGGRAPH 2002), and the points below
// the surface reached by probe rays along three axes as in King, Kulla, Conty and Fajardo, "BSSRDF
// Importance Sampling" (SIGGRAPH 2013 talk). The tracer's side (which points, which lights):
// render/tracer_subsurface.cpp. Pure functions.
#pragma once
#include "rays/math/vec3.h"

namespace rays {

/// One colour channel's dipole: reduced albedo α′, reduced extinction σ′t (per scene unit), the
/// effective transport coefficient σtr = σ′t·√(3(1 − α′)), and the depths of the real and the
/// virtual source, zr = 1/σ′t and zv = zr(1 + 4A/3).
struct Dipole {
    double albedo = 0, sigmaT = 0, sigmaTr = 0, zr = 0, zv = 0;
};

/// The total diffuse reflectance of a half space of reduced albedo α′ (Jensen and Buhler 2002):
/// Rd = (α′/2)(1 + e^(−(4/3)A√(3(1 − α′))))·e^(−√(3(1 − α′))); rises from 0 at α′ = 0 to 1 at α′ = 1.
double dipoleTotalReflectance(double albedo, double A);

/// The reduced albedo α′ in [0, 1] whose total diffuse reflectance is Rd (clamped to [0, 1]), by
/// bisection (the total rises with α′).
double dipoleAlbedoFor(double Rd, double A);

/// The dipole of a channel that shows total diffuse reflectance Rd and whose mean free path
/// 1/σ′t is meanFreePath scene units (> 0).
Dipole makeDipole(double Rd, double meanFreePath, double A);
/// The dipole of a channel of reduced albedo α′ (in [0, 1]) and mean free path 1/σ′t (> 0).
Dipole dipoleOfAlbedo(double albedo, double meanFreePath, double A);

/// Rd(r): the light leaving the surface at distance r from where it entered, per unit of entering
/// flux and of area (Jensen et al. 2001, eq. 5): its integral over the plane is the total above.
double dipoleProfile(const Dipole& d, double r);

}  // namespace rays
