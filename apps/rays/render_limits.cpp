#include "render_limits.h"

#include <string>

#include "rays/error.h"
#include "render_command.h"

namespace rays::cli {
namespace {

void inRange(long long v, long long lo, long long hi, const char* what) {
    if (v < lo || v > hi)
        throw Error(std::string("rays: error: ") + what + " must be a whole number from " + std::to_string(lo) + " to " +
                    std::to_string(hi) + ", got " + std::to_string(v));
}

}  // namespace

void checkSettingsLimits(const RenderSettings& s) {
    checkImageSize(s.width, s.height);
    inRange(s.maxDepth, 0, kMaxDepth, "the recursion depth");
    inRange(s.spp, 1, kMaxSamplesPerPixel, "the number of samples per pixel");
    if (s.dofSamples != 0) inRange(s.dofSamples, 1, kMaxSamplesPerPixel, "the number of depth-of-field samples");
    if (s.areaSamples != 0) inRange(s.areaSamples, 1, kMaxAreaSamples, "the number of area-light samples per axis");
    inRange(s.threads, 0, kMaxThreads, "the number of threads");
    if (s.gi) {
        inRange(s.giSamples[0], 1, kMaxGiSamples, "the number of GI samples");
        inRange(s.giSamples[1], 1, kMaxGiSamples, "the number of GI samples");
        inRange(s.giBounces, 1, kMaxGiBounces, "the number of GI bounces");
    }
}

}  // namespace rays::cli
