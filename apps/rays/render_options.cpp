#include "render_options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "flag_values.h"
#include "rays/error.h"
#include "render_limits.h"

namespace rays::cli {
namespace {

[[noreturn]] void bad(const std::string& msg) { throw Error("rays: error: " + msg); }

int positiveInt(const std::string& text, const char* what, int most) {
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || v < 1 || v > most)
        bad(std::string(what) + " must be a whole number from 1 to " + std::to_string(most) + ", got '" + text + "'");
    return int(v);
}

// CLI::NonNegativeNumber and CLI::PositiveNumber print DBL_MAX in full ("not in range 0.000000 to
// 17976931348623157...") when they fail: the same checks with a short message.
CLI::Validator atLeast(double lo, bool strict) {
    const std::string rule = std::string(strict ? "must be greater than " : "must be at least ") + (lo == 0 ? "0" : std::to_string(lo));
    return CLI::Validator(
        [lo, strict, rule](std::string& in) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(in.c_str(), &end);
            if (in.empty() || *end != '\0' || !std::isfinite(v)) return "expected a number, got '" + in + "'";
            if (strict ? !(v > lo) : !(v >= lo)) return rule + ", got " + in;
            return {};
        },
        strict ? "POSITIVE" : "NONNEGATIVE");
}

}  // namespace

std::vector<std::string> normaliseCourseFlags(int argc, char** argv) {
    static const char* kCourse[] = {"-altbrdf", "-fresnel", "-beers", "-sds", "-gi", "-ss=", "-gi_samples=", "-gi_bounces="};
    std::vector<std::string> out;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        for (const char* f : kCourse) {
            const std::string flag = f;
            const bool prefix = flag.back() == '=';
            if ((prefix && a.rfind(flag, 0) == 0) || (!prefix && a == flag)) {
                a = "-" + a;
                break;
            }
        }
        out.push_back(a);
    }
    return out;
}

void addCourseFlags(CLI::App* cmd, CourseFlags& f) {
    cmd->add_flag("--altbrdf", f.altbrdf, "Cook-Torrance shading (course: -altbrdf)");
    cmd->add_flag("--fresnel", f.fresnel, "Schlick Fresnel on reflection/refraction (course: -fresnel)");
    cmd->add_flag("--beers", f.beers, "Beer's law attenuation inside refractive objects (course: -beers)");
    cmd->add_flag("--sds", f.sds, "accepted for the course; Rays always uses its BVH (course: -sds)");
    cmd->add_option("--ss", f.ss, "N×N regular supersampling grid per pixel (course: -ss=N)")->check(CLI::Range(1, kMaxSupersampleGrid));
    cmd->add_flag("--gi", f.gi, "global illumination: cosine-weighted hemisphere samples replace the ambient term (course: -gi)");
    cmd->add_option("--gi_samples", f.giSamples, "GI samples at the first and later bounces, e.g. 64,16 (course: -gi_samples=)");
    cmd->add_option("--gi_bounces", f.giBounces, "levels of indirect light (default 2; course: -gi_bounces=)");
}

void addModernOptions(CLI::App* cmd, ModernOptions& o, RenderSettings& s) {
    cmd->add_option("--shading", o.shading, "blinn-phong | cook-torrance | oren-nayar | lambert | flat | normals");
    cmd->add_option("--aa", o.aa, "sample placement: grid | random | stratified (default stratified with --spp, else grid)");
    cmd->add_option("--spp", o.spp, "samples per pixel (grid and stratified use the nearest square)")->check(CLI::Range(1, kMaxSamplesPerPixel));
    cmd->add_option("--filter", o.filter, "reconstruction filter: box | tent | gaussian (default box)");
    cmd->add_flag("--aa-edges", o.aaEdges, "edge-guided anti-aliasing: supersample only where object ids or shadows change");
    cmd->add_option("--area-samples", o.areaSamples, "samples per axis for every area light (overrides the scene)")->check(CLI::Range(1, kMaxAreaSamples));
    cmd->add_option("--aperture", o.aperture, "lens radius for depth of field (overrides the camera's aperture)")->check(atLeast(0, false));
    cmd->add_option("--focal-distance", o.focalDistance, "distance to the focal plane along the view direction")->check(atLeast(0, true));
    cmd->add_option("--dof-samples", o.dofSamples, "samples per pixel with depth of field (overrides blur_samples)")->check(CLI::Range(1, kMaxSamplesPerPixel));
    cmd->add_flag("--gi-physical", s.giPhysical, "global illumination with the physically based (Lambertian) estimator kd*C*E instead of the course's plain mean E (implies --gi)");
    cmd->add_option("--depth", s.maxDepth, "recursion depth for reflection and refraction (default 6)")->check(CLI::Range(0, kMaxDepth));
    cmd->add_option("--threads", s.threads, "worker threads (default: all cores)")->check(CLI::Range(0, kMaxThreads));
    cmd->add_option("--seed", s.seed, "random seed for jittered samples, area lights, lens and GI")->check(unsigned64Check());
    cmd->add_option("--camera", s.cameraIndex, "index of the camera in the scene (default 0)")->check(atLeast(0, false));
}

void applyOptions(const CourseFlags& f, const ModernOptions& o, RenderSettings& s) {
    if (f.altbrdf) s.shading = ShadingModel::CookTorrance;
    s.fresnel = f.fresnel;
    s.beers = f.beers;
    if (f.ss > 0 && o.spp > 0)
        bad("-ss=" + std::to_string(f.ss) + " and --spp " + std::to_string(o.spp) +
            " both set the samples per pixel: give one of them");
    if (f.ss > 0) {
        s.aa = AaMode::Grid;
        s.spp = f.ss * f.ss;
    }
    if (f.gi || s.giPhysical || !f.giSamples.empty() || !f.giBounces.empty()) s.gi = true;
    if (!f.giSamples.empty()) {
        const size_t comma = f.giSamples.find(',');
        s.giSamples[0] = positiveInt(f.giSamples.substr(0, comma), "gi_samples", kMaxGiSamples);
        s.giSamples[1] = comma == std::string::npos ? std::max(1, s.giSamples[0] / 4)
                                                     : positiveInt(f.giSamples.substr(comma + 1), "gi_samples", kMaxGiSamples);
    }
    if (!f.giBounces.empty()) s.giBounces = positiveInt(f.giBounces, "gi_bounces", kMaxGiBounces);
    if (!f.gi && (!f.giSamples.empty() || !f.giBounces.empty()))  // once the values are known to be good
        std::fprintf(stderr, "rays: warning: %s turns global illumination on (as -gi)\n",
                     f.giSamples.empty() ? "-gi_bounces" : "-gi_samples");

    if (!o.shading.empty() && !parseShadingName(o.shading.c_str(), s.shading))
        bad("unknown shading model '" + o.shading + "' (use blinn-phong, cook-torrance, oren-nayar, lambert, flat or normals)");
    if (o.spp > 0) {
        s.spp = o.spp;
        s.aa = AaMode::Stratified;
    }
    if (!o.aa.empty()) {
        if (o.aa == "grid") s.aa = AaMode::Grid;
        else if (o.aa == "random") s.aa = AaMode::Random;
        else if (o.aa == "stratified") s.aa = AaMode::Stratified;
        else bad("unknown anti-aliasing mode '" + o.aa + "' (use grid, random or stratified)");
    }
    if (!o.filter.empty()) {
        if (o.filter == "box") s.filter = PixelFilter::Box;
        else if (o.filter == "tent") s.filter = PixelFilter::Tent;
        else if (o.filter == "gaussian") s.filter = PixelFilter::Gaussian;
        else bad("unknown filter '" + o.filter + "' (use box, tent or gaussian)");
    }
    s.aaEdges = o.aaEdges;
    if (s.aaEdges && s.spp == 1) bad("--aa-edges needs more than one sample per pixel (--spp N or -ss=N)");
    s.areaSamples = o.areaSamples;
    s.aperture = o.aperture;
    s.focalDistance = o.focalDistance;
    s.dofSamples = o.dofSamples;
}

}  // namespace rays::cli
