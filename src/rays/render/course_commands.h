// The course's debugging commands (sceneinfo, pixelray, firsthit, pixelcolor, printrays), printing
// exactly the course reference's text: numbers fixed with 4 decimals, colours as round(c·255).
// A POV-Ray scene's pixel colours are those its image has (encoded as pov_output.h says) and its
// lighting model is named "POV-Ray 3.7".
#pragma once
#include <ostream>

#include "rays/accel/bvh.h"
#include "rays/render/settings.h"
#include "rays/scene/scene.h"

namespace rays {

/// Camera, lights and objects with their materials; objects numbered from 1 (as printrays numbers
/// them), each with its object-to-world transform when the file wrote one.
void printSceneInfo(std::ostream& out, const Scene& scene);

/// "Pixel: [x, y] Ray: {origin} -> {direction}" for pixel (x, y), y counted up from the bottom.
void printPixelRay(std::ostream& out, const Scene& scene, const RenderSettings& s, int x, int y);

/// The pixel ray plus t, object type and pigment colour of the first hit (or "No Hit").
void printFirstHit(std::ostream& out, const Scene& scene, const Bvh& bvh, const RenderSettings& s, int x, int y);

/// The first hit plus the shading model ("BRDF: ...") and the shaded colour as the image has it.
void printPixelColor(std::ostream& out, const Scene& scene, const Bvh& bvh, const RenderSettings& s, int x, int y);

/// Recursion limit of printrays: the course's expected ray trees stop 5 bounces after the primary ray.
inline constexpr int kPrintRaysDepth = 5;

/// The pixel's colour and the whole ray tree of its centre ray (traced to kPrintRaysDepth) with
/// per-term contributions (the tree in working-space colours), in the course's layout: per ray
/// its kind, the ray, the object-space ray (transformed objects), the hit and its terms;
/// refraction subtrees before reflection ones, misses as "No intersection.", a blank line after
/// every ray without children.
void printRays(std::ostream& out, const Scene& scene, const Bvh& bvh, const RenderSettings& s, int x, int y);

}  // namespace rays
