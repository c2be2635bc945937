// Specs of the scene's other items (POV-Ray 3.7 reference, "Camera", "Light Source",
// "Atmospheric Effects", "Global Settings"), and of transform blocks.
#include "rays/pov/specs.h"

namespace rays::pov {

using sdl::Entry;
using sdl::Interpreter;
using sdl::Value;

namespace {

// assumed_gamma F | srgb: srgb is kept as -1 (the builder writes colours unchanged then).
void readAssumedGamma(Interpreter& in, Entry& e) {
    if (in.isKw(Kw::srgb)) {
        in.next();
        e.args.push_back(Value::number(-1));
        return;
    }
    e.args.push_back(Value::number(in.parseFloat()));
}

// Camera angle [H [[,] V]]: orthographic takes angle with no value (POV-Ray 3.7 reference,
// "Orthographic projection"); spherical takes a vertical angle after the horizontal one.
void readCameraAngle(Interpreter& in, Entry& e) {
    if (!in.atNumericStart()) return;
    e.args.push_back(in.parseNumeric(false));
    if (in.isSym(',')) in.next();
    if (in.atNumericStart()) e.args.push_back(in.parseNumeric(false));
}

// charset ascii | utf8 | sys.
void readCharset(Interpreter& in, Entry& e) {
    const Kw k = in.kw();
    if (k != Kw::ascii && k != Kw::utf8 && k != Kw::sys) in.errorHere("expected ascii, utf8 or sys after charset, found " + in.describe());
    e.args.push_back(Value::number(double(k)));
    in.next();
}

}  // namespace

void Specs::buildScene() {
    const RuleGroup cameraRules{flag(Kw::perspective), flag(Kw::orthographic), flag(Kw::fisheye),
                                flag(Kw::ultra_wide_angle), flag(Kw::omnimax), flag(Kw::panoramic),
                                flag(Kw::spherical), number(Kw::cylinder), sub(Kw::mesh_camera, meshCamera),
                                expr(Kw::location), expr(Kw::look_at), expr(Kw::right), expr(Kw::up),
                                expr(Kw::direction), expr(Kw::sky), custom(Kw::angle, readCameraAngle), expr(Kw::focal_point),
                                number(Kw::aperture), list(Kw::blur_samples, 2), number(Kw::confidence),
                                number(Kw::variance), sub(Kw::bokeh, pigmentBody), item(Kw::normal)};
    camera = makeSpec("a camera", Kw::camera, {&cameraRules, &transformRules()}, true);
    const RuleGroup meshCameraRules{item(Kw::mesh), item(Kw::mesh2), flag(Kw::smooth)};
    meshCamera = makeSpec("a mesh_camera", Kw::mesh_camera, {&meshCameraRules}, true);

    const RuleGroup lightRules{flag(Kw::spotlight), flag(Kw::cylinder), flag(Kw::parallel), flag(Kw::shadowless),
                               expr(Kw::point_at), number(Kw::radius), number(Kw::falloff), number(Kw::tightness),
                               list(Kw::area_light, 4), number(Kw::adaptive), boolean(Kw::jitter), boolean(Kw::circular),
                               boolean(Kw::orient), boolean(Kw::area_illumination), number(Kw::fade_distance),
                               number(Kw::fade_power), boolean(Kw::media_interaction), boolean(Kw::media_attenuation),
                               sub(Kw::looks_like, lookLike), sub(Kw::projected_through, lookLike),
                               sub(Kw::photons, photonsLight)};
    lightSource = makeSpec("a light_source", Kw::light_source, {&lightRules, &transformRules()}, true);
    const RuleGroup none;
    lookLike = makeSpec("looks_like / projected_through", Kw::looks_like, {&none}, false, true);
    const RuleGroup photonLightRules{boolean(Kw::refraction), boolean(Kw::reflection), flag(Kw::area_light)};
    photonsLight = makeSpec("a light's photons block", Kw::photons, {&photonLightRules});

    const RuleGroup fogRules{number(Kw::fog_type), number(Kw::distance), number(Kw::fog_offset), number(Kw::fog_alt),
                             expr(Kw::turbulence), number(Kw::turb_depth), number(Kw::omega), number(Kw::lambda),
                             number(Kw::octaves), expr(Kw::up)};
    fog = makeSpec("a fog", Kw::fog, {&fogRules, &transformRules()}, true);
    const RuleGroup rainbowRules{expr(Kw::direction), number(Kw::angle), number(Kw::width), number(Kw::distance),
                                 item(Kw::color_map), item(Kw::colour_map), number(Kw::jitter), expr(Kw::up),
                                 number(Kw::arc_angle), number(Kw::falloff_angle)};
    rainbow = makeSpec("a rainbow", Kw::rainbow, {&rainbowRules}, true);
    const RuleGroup skyRules{item(Kw::pigment), expr(Kw::emission)};
    skySphere = makeSpec("a sky_sphere", Kw::sky_sphere, {&skyRules, &transformRules()}, true);
    background = makeSpec("a background", Kw::background, {&none}, true);

    const RuleGroup globalRules{number(Kw::adc_bailout), expr(Kw::ambient_light), custom(Kw::assumed_gamma, readAssumedGamma),
                                boolean(Kw::hf_gray_16), expr(Kw::irid_wavelength), custom(Kw::charset, readCharset),
                                number(Kw::max_intersections), number(Kw::max_trace_level),
                                number(Kw::number_of_waves), number(Kw::noise_generator),
                                sub(Kw::radiosity, radiositySettings), sub(Kw::photons, photonsGlobal),
                                sub(Kw::subsurface, subsurfaceGlobal), number(Kw::mm_per_unit)};
    globalSettings = makeSpec("global_settings", Kw::global_settings, {&globalRules});
    const RuleGroup radiosityRules{number(Kw::adc_bailout), boolean(Kw::always_sample), number(Kw::brightness),
                                   list(Kw::count, 2), number(Kw::error_bound), number(Kw::gray_threshold),
                                   number(Kw::low_error_factor), number(Kw::max_sample), number(Kw::maximum_reuse),
                                   number(Kw::minimum_reuse), list(Kw::nearest_count, 2), boolean(Kw::normal),
                                   number(Kw::pretrace_start), number(Kw::pretrace_end), number(Kw::recursion_limit),
                                   boolean(Kw::media), boolean(Kw::subsurface), string(Kw::save_file),
                                   string(Kw::load_file), number(Kw::importance)};
    radiositySettings = makeSpec("a radiosity block", Kw::radiosity, {&radiosityRules});
    const RuleGroup photonGlobalRules{number(Kw::spacing), number(Kw::count), list(Kw::gather, 2), list(Kw::media, 2),
                                      number(Kw::jitter), number(Kw::max_trace_level), number(Kw::adc_bailout),
                                      string(Kw::save_file), string(Kw::load_file), number(Kw::autostop),
                                      list(Kw::expand_thresholds, 2), list(Kw::radius, 4)};
    photonsGlobal = makeSpec("a photons block", Kw::photons, {&photonGlobalRules});
    const RuleGroup subsurfaceRules{list(Kw::samples, 2), boolean(Kw::radiosity)};
    subsurfaceGlobal = makeSpec("a subsurface block", Kw::subsurface, {&subsurfaceRules});

    const RuleGroup transformOnly{flag(Kw::inverse)};
    transform = makeSpec("a transform", Kw::transform, {&transformOnly, &transformRules()}, true);
}

}  // namespace rays::pov
