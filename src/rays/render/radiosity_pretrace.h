// POV-Ray's radiosity pretrace (POV-Ray 3.7 reference, "Radiosity": pretrace_start, pretrace_end):
// coarse passes over the image before the final render that fill the irradiance cache, so that the
// final pass finds records nearly everywhere and only reads the cache.
#pragma once
#include "rays/render/irradiance_cache.h"
#include "rays/render/settings.h"
#include "rays/render/tracer.h"
#include "rays/scene/scene.h"

namespace rays {

struct ViewSetup;

/// Traces camera rays through the centres of square blocks pretrace_start × the image width wide,
/// then blocks half as wide, down to pretrace_end; the records each pass makes are added to cache
/// after the pass in pixel order (each block's rays draw from their own random numbers and see the
/// cache as the passes before left it), so the cache is the same for any number of threads. Then
/// points tracer at the cache. Does nothing for scenes without radiosity.
void pretraceRadiosity(Tracer& tracer, const Scene& scene, const ViewSetup& view, const RenderSettings& s,
                       IrradianceCache& cache);

}  // namespace rays
