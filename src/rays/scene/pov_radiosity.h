// POV-Ray 3.7's radiosity settings (global_settings { radiosity { ... } }; the reference manual's
// "Radiosity" section, defaults as it lists them). How the gathered light enters the surface colour
// was measured with povray 3.7 (docs/povray-lighting.md, "Radiosity").
#pragma once

namespace rays {

struct PovRadiosity {
    bool enabled = false;
    int count = 35;               ///< gathering rays per irradiance record
    double errorBound = 1.8;      ///< Ward's a: a record serves points within ε = d/R + √(1 − N·Nᵢ) < a
    double lowErrorFactor = 0.5;  ///< the pretrace uses errorBound·lowErrorFactor
    double minimumReuse = 0.015;  ///< a record's radius R at least this fraction of its distance from the eye
    double maximumReuse = 0.2;    ///< and at most this fraction
    int nearestCount = 5;         ///< at most this many records blended at a point
    double pretraceStart = 0.08;  ///< the pretrace's coarsest block, a fraction of the image width
    double pretraceEnd = 0.04;    ///< its finest block (blocks halve from start to end)
    int recursionLimit = 2;       ///< bounces of gathered light (rays at the last level see emission and lights)
    double brightness = 1;        ///< the gathered light times this
    double grayThreshold = 0;     ///< g: the gathered colour c becomes (1 − g)·c + g·grey(c)
    double adcBailout = 0.01;
    bool alwaysSample = false;
};

}  // namespace rays
