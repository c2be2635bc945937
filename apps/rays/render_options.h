// The options shared by `rays render` and the course commands, and how they map onto RenderSettings.
#pragma once
#include <CLI/CLI.hpp>

#include <string>

#include "rays/render/settings.h"

namespace rays::cli {

/// Flags the course writes with one dash (-altbrdf, -ss=4, -gi_samples=64,16).
struct CourseFlags {
    bool altbrdf = false, fresnel = false, beers = false, sds = false, gi = false;
    int ss = 0;  ///< 0: not given
    std::string giSamples, giBounces;
};

/// Options of `rays render` beyond the course's.
struct ModernOptions {
    std::string shading, aa, filter;
    int spp = 0;  ///< 0: not given
    bool aaEdges = false;
    int areaSamples = 0, dofSamples = 0;
    double aperture = -1, focalDistance = -1;
};

void addCourseFlags(CLI::App* cmd, CourseFlags& f);
void addModernOptions(CLI::App* cmd, ModernOptions& o, RenderSettings& s);

/// Applies both to s; throws Error for values CLI11 cannot check (names, lists) and for -ss with
/// --spp; warns on stderr when -gi_samples or -gi_bounces turns GI on without -gi.
void applyOptions(const CourseFlags& f, const ModernOptions& o, RenderSettings& s);

/// Course flags normalised for CLI11: "-altbrdf" → "--altbrdf", "-ss=4" → "--ss=4".
std::vector<std::string> normaliseCourseFlags(int argc, char** argv);

}  // namespace rays::cli
