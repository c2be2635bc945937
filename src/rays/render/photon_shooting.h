// POV-Ray's photons before the render: the lights shoot them at the targets
// (render/tracer_photons.cpp), the map is built (render/photon_map.h), and the tracer reads it
// while rendering.
#pragma once
#include <cstddef>

#include "rays/render/photon_map.h"
#include "rays/scene/scene.h"

namespace rays {

class Tracer;

/// At most this many photons leave the lights (a finer spacing is widened to keep to it) ...
inline constexpr size_t kMaxPhotonsShot = 5'000'000;
/// ... and at most this many are kept on surfaces, and as many in media (40 bytes each; twice
/// that while they are joined).
inline constexpr size_t kMaxPhotonsStored = 5'000'000;

/// Shoots the photons of a POV-Ray scene with global photons into map and, with `media` in the
/// photons block, mediaMap (on `threads` threads, 0: all cores; the maps are the same for any
/// number) and points tracer at them; nothing for other scenes.
void preparePhotons(Tracer& tracer, const Scene& scene, int threads, PhotonMap& map, PhotonMap& mediaMap);

}  // namespace rays
