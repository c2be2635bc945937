// The limits of the render settings (docs/errors.md "Limits"), decided here once: the command-line
// options check their values against these constants, and every form of the command line (render,
// raycast, the positional form, POV-Ray's switches and INI files, animation frames, the pixel
// commands) passes its finished RenderSettings through checkSettingsLimits before any work.
#pragma once
#include "rays/render/settings.h"

namespace rays::cli {

/// Reflection and refraction levels: each is a stack frame of the tracer (and a factor of work).
inline constexpr int kMaxDepth = 1000;
/// Samples per pixel (--spp, the positional RAYS_PER_PIXEL, --dof-samples, blur_samples).
inline constexpr int kMaxSamplesPerPixel = 65536;
/// -ss=N (an N×N grid).
inline constexpr int kMaxSupersampleGrid = 64;
/// GI samples at a bounce.
inline constexpr int kMaxGiSamples = 65536;
/// GI bounces: each is a level of the tracer's recursion, as a reflection is.
inline constexpr int kMaxGiBounces = kMaxDepth;
/// --threads (0: all cores).
inline constexpr int kMaxThreads = 1024;
/// --area-samples per axis.
inline constexpr int kMaxAreaSamples = 1024;

/// Throws Error "rays: error: ..." when a setting lies outside the limits above or the image size
/// is not allowed (checkImageSize).
void checkSettingsLimits(const RenderSettings& s);

}  // namespace rays::cli
