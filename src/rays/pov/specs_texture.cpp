// Specs of textures and their parts (POV-Ray 3.7 reference, "Texture", "Pattern", "Media",
// "Interior"): pigment, normal, finish, texture, interior, media, density, material, the maps,
// warps and image maps.
#include "rays/pov/specs.h"

namespace rays::pov {

using sdl::Entry;
using sdl::Interpreter;
using sdl::Value;

namespace {

// diffuse / phong / specular [albedo] F [, F]: the albedo flag is kept as the first argument
// (1 or 0), then the amounts.
void readAlbedoAmount(Interpreter& in, Entry& e) {
    const bool albedo = in.acceptKw(Kw::albedo);
    e.args.push_back(Value::number(albedo ? 1 : 0));
    e.args.push_back(in.parseNumeric(false));
    if (in.isSym(',')) {
        in.next();
        if (in.atNumericStart()) e.args.push_back(in.parseNumeric(false));
    }
}

// image_map's `filter all F` / `filter N, F` and `transmit ...`: args (-1 for all, or the palette
// index) and the amount.
void readPaletteAmount(Interpreter& in, Entry& e) {
    if (in.acceptKw(Kw::all)) {
        e.args.push_back(Value::number(-1));
        e.args.push_back(Value::number(in.parseFloat()));
        return;
    }
    e.args.push_back(Value::number(in.parseFloat()));
    in.expectSym(',', "between the palette index and the amount");
    e.args.push_back(Value::number(in.parseFloat()));
}

// density_file df3 "file.df3" [interpolate N].
void readDensityFile(Interpreter& in, Entry& e) {
    in.expectKw(Kw::df3, "after density_file");
    e.args.push_back(Value::string(in.parseString()));
    if (in.acceptKw(Kw::interpolate)) e.args.push_back(Value::number(in.parseFloat()));
}

// magnet 1|2 mandel|julia [<c>] N.
void readMagnet(Interpreter& in, Entry& e) {
    e.args.push_back(Value::number(in.parseFloat()));
    if (in.acceptKw(Kw::julia)) {
        e.args.push_back(Value::number(1));
        e.args.push_back(in.parseNumeric(false));
        in.acceptSym(',');
    } else {
        in.expectKw(Kw::mandel, "after magnet's type");
        e.args.push_back(Value::number(0));
    }
    e.args.push_back(Value::number(in.parseFloat()));
}

// warp { planar [<normal>, distance] }.
void readOptionalList(Interpreter& in, Entry& e) {
    if (!in.atNumericStart()) return;
    e.args.push_back(in.parseNumeric(false));
    while (in.isSym(',')) {
        in.next();
        if (!in.atNumericStart()) return;
        e.args.push_back(in.parseNumeric(false));
    }
}

// The pattern types (POV-Ray 3.7 reference, "Patterns"), each with what follows its keyword.
RuleGroup patternKinds(const Specs& s) {
    return {flag(Kw::agate), optExpr(Kw::aoi), flag(Kw::average), flag(Kw::boxed), flag(Kw::bozo), flag(Kw::brick),
            optNumber(Kw::bumps), flag(Kw::cells), flag(Kw::checker), flag(Kw::crackle), flag(Kw::cubic),
            flag(Kw::cylindrical), custom(Kw::density_file, readDensityFile), optNumber(Kw::dents),
            flag(Kw::facets), function(Kw::function), expr(Kw::gradient), flag(Kw::granite), flag(Kw::hexagon),
            sub(Kw::image_pattern, s.imageMap), list(Kw::julia, 2), flag(Kw::leopard),
            custom(Kw::magnet, readMagnet), number(Kw::mandel), flag(Kw::marble), item(Kw::object), flag(Kw::onion),
            flag(Kw::pavement), sub(Kw::pigment_pattern, s.pigmentBody), flag(Kw::planar), flag(Kw::quilted),
            flag(Kw::radial), optNumber(Kw::ripples), subOrExpr(Kw::slope, s.slope), flag(Kw::spherical),
            list(Kw::spiral1, 2), list(Kw::spiral2, 2), flag(Kw::spotted), flag(Kw::square), number(Kw::tiling),
            flag(Kw::triangular), optNumber(Kw::waves), flag(Kw::wood), optNumber(Kw::wrinkles)};
}

// Modifiers of one pattern type or another (agate_turb, brick_size, mortar, ...).
RuleGroup patternSpecificModifiers() {
    return {number(Kw::agate_turb), expr(Kw::brick_size), number(Kw::mortar), number(Kw::control0), number(Kw::control1), expr(Kw::form),
            number(Kw::metric), number(Kw::offset), flag(Kw::solid), number(Kw::coords), number(Kw::size),
            number(Kw::exponent), list(Kw::exterior, 2), list(Kw::interior, 2), number(Kw::number_of_sides),
            number(Kw::number_of_tiles), number(Kw::pattern), expr(Kw::orientation), number(Kw::dist_exp),
            number(Kw::major_radius), number(Kw::max_iteration), number(Kw::precision)};
}

RuleGroup patternModifiers(const Specs& s) {
    RuleGroup g{expr(Kw::turbulence), number(Kw::octaves), number(Kw::omega), number(Kw::lambda),
                number(Kw::frequency), number(Kw::phase), number(Kw::noise_generator), flag(Kw::ramp_wave),
                flag(Kw::triangle_wave), flag(Kw::sine_wave), flag(Kw::scallop_wave), flag(Kw::cubic_wave),
                optNumber(Kw::poly_wave), sub(Kw::warp, s.warp), item(Kw::color_map), item(Kw::colour_map),
                item(Kw::pigment_map), item(Kw::normal_map), item(Kw::slope_map), item(Kw::texture_map),
                item(Kw::density_map), color(Kw::quick_color), color(Kw::quick_colour), number(Kw::accuracy),
                boolean(Kw::no_bump_scale), number(Kw::bump_size), flag(Kw::uv_mapping), number(Kw::interpolate)};
    g.insert(g.end(), transformRules().begin(), transformRules().end());
    return g;
}

}  // namespace

void Specs::buildTextures() {
    const RuleGroup kinds = patternKinds(*this);
    patternTypes = makeSpec("a pattern type", Kw::pattern, {&kinds});
    RuleGroup types = kinds;
    const RuleGroup specific = patternSpecificModifiers();
    types.insert(types.end(), specific.begin(), specific.end());
    const RuleGroup mods = patternModifiers(*this);

    const RuleGroup pigmentOnly{sub(Kw::image_map, imageMap), item(Kw::pigment)};
    pigment = makeSpec("a pigment", Kw::pigment, {&types, &mods, &pigmentOnly}, true);
    pigmentBody = makeSpec("a pigment", Kw::pigment, {&types, &mods, &pigmentOnly}, true);

    const RuleGroup normalOnly{sub(Kw::bump_map, imageMap), item(Kw::normal)};
    normal = makeSpec("a normal", Kw::normal, {&types, &mods, &normalOnly}, true);
    normalBody = makeSpec("a normal", Kw::normal, {&types, &mods, &normalOnly}, true);

    const RuleGroup finishRules{expr(Kw::ambient), expr(Kw::emission), custom(Kw::diffuse, readAlbedoAmount),
                                number(Kw::brilliance), custom(Kw::phong, readAlbedoAmount), number(Kw::phong_size),
                                custom(Kw::specular, readAlbedoAmount), number(Kw::roughness), optNumber(Kw::metallic),
                                subOrExpr(Kw::reflection, reflection), number(Kw::reflection_exponent),
                                flag(Kw::conserve_energy), sub(Kw::irid, irid), number(Kw::crand),
                                sub(Kw::subsurface, subsurfaceFinish), boolean(Kw::fresnel),
                                // POV-Ray 3.0 finish items, still accepted by 3.7
                                number(Kw::refraction), number(Kw::ior), number(Kw::caustics),
                                number(Kw::fade_distance), number(Kw::fade_power)};
    finish = makeSpec("a finish", Kw::finish, {&finishRules}, true);
    const RuleGroup reflectionRules{boolean(Kw::fresnel), number(Kw::falloff), number(Kw::exponent),
                                    optNumber(Kw::metallic)};
    reflection = makeSpec("a reflection block", Kw::reflection, {&reflectionRules}, true);
    const RuleGroup iridRules{number(Kw::thickness), expr(Kw::turbulence)};
    irid = makeSpec("an irid block", Kw::irid, {&iridRules}, true);
    const RuleGroup subsurfaceRules{expr(Kw::translucency)};
    subsurfaceFinish = makeSpec("a subsurface block", Kw::subsurface, {&subsurfaceRules}, true);

    const RuleGroup textureRules{item(Kw::pigment), item(Kw::normal), item(Kw::finish), sub(Kw::material_map, materialMap),
                                 sub(Kw::tiles, tiles), sub(Kw::image_map, imageMap), item(Kw::texture)};
    texture = makeSpec("a texture", Kw::texture, {&textureRules, &types, &mods}, true);
    textureBody = makeSpec("a texture", Kw::texture, {&textureRules, &types, &mods}, true);
    const RuleGroup tilesRules{item(Kw::texture), flag(Kw::tile2)};
    tiles = makeSpec("a tiles block", Kw::tiles, {&tilesRules, &transformRules()});
    const RuleGroup materialMapRules{item(Kw::texture), flag(Kw::once), number(Kw::map_type), number(Kw::interpolate)};
    materialMap = makeSpec("a material_map", Kw::material_map, {&imageTypeRules(), &materialMapRules, &transformRules()}, true);

    const RuleGroup interiorRules{number(Kw::ior), number(Kw::caustics), number(Kw::dispersion),
                                  number(Kw::dispersion_samples), number(Kw::fade_distance), number(Kw::fade_power),
                                  color(Kw::fade_color), color(Kw::fade_colour), item(Kw::media)};
    interior = makeSpec("an interior", Kw::interior, {&interiorRules}, true);

    const RuleGroup mediaRules{number(Kw::method), number(Kw::intervals), list(Kw::samples, 2), number(Kw::confidence),
                               number(Kw::variance), number(Kw::ratio), number(Kw::jitter), color(Kw::absorption),
                               color(Kw::emission), sub(Kw::scattering, scattering), item(Kw::density),
                               number(Kw::aa_level), number(Kw::aa_threshold), boolean(Kw::collect)};
    media = makeSpec("a media", Kw::media, {&mediaRules, &transformRules()}, true);
    const RuleGroup scatteringRules{number(Kw::eccentricity), number(Kw::extinction)};
    scattering = makeSpec("a scattering block", Kw::scattering, {&scatteringRules}, true);
    const RuleGroup densityOnly{item(Kw::density)};
    density = makeSpec("a density", Kw::density, {&types, &mods, &densityOnly}, true);
    pattern = makeSpec("a pattern", Kw::pattern, {&types, &mods}, true);
    densityBody = makeSpec("a density", Kw::density, {&types, &mods}, true);

    const RuleGroup materialRules{item(Kw::texture), item(Kw::interior), item(Kw::pigment), item(Kw::normal),
                                  item(Kw::finish)};
    material = makeSpec("a material", Kw::material, {&materialRules, &transformRules()}, true);

    colorMap = makeSpec("a color_map", Kw::color_map, {}, true, false, BlockSpec::Map::Colors);
    pigmentMap = makeSpec("a pigment_map", Kw::pigment_map, {}, true, false, BlockSpec::Map::Bodies, &pigmentBody);
    normalMap = makeSpec("a normal_map", Kw::normal_map, {}, true, false, BlockSpec::Map::Bodies, &normalBody);
    textureMap = makeSpec("a texture_map", Kw::texture_map, {}, true, false, BlockSpec::Map::Bodies, &textureBody);
    densityMap = makeSpec("a density_map", Kw::density_map, {}, true, false, BlockSpec::Map::Bodies, &densityBody);
    slopeMap = makeSpec("a slope_map", Kw::slope_map, {}, true, false, BlockSpec::Map::Slopes);

    const RuleGroup slopeRules{list(Kw::altitude, 3)};
    slope = makeSpec("a slope block", Kw::slope, {&slopeRules}, true);

    const RuleGroup warpRules{expr(Kw::turbulence), number(Kw::octaves), number(Kw::omega), number(Kw::lambda),
                              expr(Kw::repeat), expr(Kw::offset), expr(Kw::flip), list(Kw::black_hole, 2),
                              number(Kw::falloff), number(Kw::strength), flag(Kw::inverse), expr(Kw::type),
                              flag(Kw::cylindrical), flag(Kw::spherical), flag(Kw::toroidal),
                              custom(Kw::planar, readOptionalList), flag(Kw::cubic), expr(Kw::orientation),
                              number(Kw::dist_exp), number(Kw::major_radius)};
    warp = makeSpec("a warp", Kw::warp, {&warpRules});

    const RuleGroup imageRules{custom(Kw::function, readFunctionImage), number(Kw::map_type), flag(Kw::once),
                               number(Kw::interpolate), custom(Kw::filter, readPaletteAmount),
                               custom(Kw::transmit, readPaletteAmount), flag(Kw::use_color), flag(Kw::use_colour),
                               flag(Kw::use_index), flag(Kw::use_alpha), number(Kw::gamma), boolean(Kw::premultiplied),
                               number(Kw::bump_size)};
    imageMap = makeSpec("an image map", Kw::image_map, {&imageTypeRules(), &imageRules}, true);
}

}  // namespace rays::pov
