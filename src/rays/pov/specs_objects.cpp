// Specs of objects (POV-Ray 3.7 reference, "Object"): every primitive, CSG, object copies and
// light groups, with the modifiers every object takes.
#include "rays/pov/specs.h"

namespace rays::pov {

using sdl::Entry;
using sdl::Interpreter;
using sdl::Value;

namespace {

// polynomial { order, xyz(i, j, k): value, ... }: args are the order, then per term i, j, k, value.
void readPolynomialTerm(Interpreter& in, Entry& e) {
    in.expectSym('(', "after xyz");
    for (int i = 0; i < 3; ++i) {
        if (i) in.expectSym(',', "in xyz(...)");
        e.args.push_back(Value::number(in.parseFloat()));
    }
    in.expectSym(')', "to close xyz(...)");
    in.expectSym(':', "after xyz(...)");
    e.args.push_back(Value::number(in.parseFloat()));
}

// julia_fractal's pwr(X, Y).
void readPwr(Interpreter& in, Entry& e) {
    in.expectSym('(', "after pwr");
    e.args.push_back(Value::number(in.parseFloat()));
    in.expectSym(',', "in pwr(...)");
    e.args.push_back(Value::number(in.parseFloat()));
    in.expectSym(')', "to close pwr(...)");
}

// bicubic_patch's uv_vectors: four 2-D vectors, the commas between them optional (POV-Ray's
// portfolio/allobjects.pov writes none).
void readPatchUv(Interpreter& in, Entry& e) {
    for (int i = 0; i < 4; ++i) {
        if (i) in.acceptSym(',');
        e.args.push_back(in.parseNumeric(false));
    }
}

// parametric's precompute DEPTH, x, y, z (any of the three names).
void readPrecompute(Interpreter& in, Entry& e) {
    e.args.push_back(Value::number(in.parseFloat()));
    while (in.acceptSym(',')) {
        const Kw k = in.kw();
        if (k != Kw::x && k != Kw::y && k != Kw::z) in.errorHere("precompute takes x, y and z, found " + in.describe());
        e.args.push_back(Value::number(k == Kw::x ? 0 : k == Kw::y ? 1 : 2));
        in.next();
    }
}

}  // namespace

void Specs::buildObjects() {
    RuleGroup mods{item(Kw::texture), item(Kw::pigment), item(Kw::normal), item(Kw::finish), item(Kw::interior),
                   item(Kw::material), sub(Kw::interior_texture, textureBody), boolean(Kw::hollow),
                   boolean(Kw::no_shadow), boolean(Kw::no_image), boolean(Kw::no_reflection),
                   boolean(Kw::no_radiosity), boolean(Kw::double_illuminate), flag(Kw::inverse),
                   sub(Kw::bounded_by, bounds), sub(Kw::clipped_by, bounds), sub(Kw::photons, photonsObject),
                   sub(Kw::radiosity, radiosityObject), flag(Kw::uv_mapping), flag(Kw::cutaway_textures),
                   boolean(Kw::sturm), boolean(Kw::hierarchy), boolean(Kw::split_union), flag(Kw::open)};
    mods.insert(mods.end(), transformRules().begin(), transformRules().end());

    const RuleGroup none;
    const RuleGroup strength{number(Kw::strength)};
    sphere = makeSpec("a sphere", Kw::sphere, {&mods, &strength}, true);
    box = makeSpec("a box", Kw::box, {&mods}, true);
    cone = makeSpec("a cone", Kw::cone, {&mods}, true);
    cylinder = makeSpec("a cylinder", Kw::cylinder, {&mods, &strength}, true);
    plane = makeSpec("a plane", Kw::plane, {&mods}, true);
    torus = makeSpec("a torus", Kw::torus, {&mods}, true);
    disc = makeSpec("a disc", Kw::disc, {&mods}, true);
    polygon = makeSpec("a polygon", Kw::polygon, {&mods}, true);
    const RuleGroup splines{flag(Kw::linear_spline), flag(Kw::quadratic_spline), flag(Kw::cubic_spline),
                            flag(Kw::bezier_spline), flag(Kw::linear_sweep), flag(Kw::conic_sweep)};
    prism = makeSpec("a prism", Kw::prism, {&mods, &splines}, true);
    lathe = makeSpec("a lathe", Kw::lathe, {&mods, &splines}, true);
    sor = makeSpec("a sor", Kw::sor, {&mods}, true);
    superellipsoid = makeSpec("a superellipsoid", Kw::superellipsoid, {&mods}, true);
    const RuleGroup blobRules{number(Kw::threshold), item(Kw::sphere), item(Kw::cylinder), list(Kw::component, 3)};
    blob = makeSpec("a blob", Kw::blob, {&blobRules, &mods}, true);
    const RuleGroup hfRules{custom(Kw::function, readFunctionImage), flag(Kw::smooth), number(Kw::water_level),
                            number(Kw::gamma), boolean(Kw::premultiplied)};
    heightField = makeSpec("a height_field", Kw::height_field, {&imageTypeRules(), &hfRules, &mods}, true);
    const RuleGroup textRules{string(Kw::ttf), number(Kw::internal)};
    text = makeSpec("a text", Kw::text, {&textRules, &mods}, true);
    quadric = makeSpec("a quadric", Kw::quadric, {&mods}, true);
    cubic = makeSpec("a cubic", Kw::cubic, {&mods}, true);
    quartic = makeSpec("a quartic", Kw::quartic, {&mods}, true);
    poly = makeSpec("a poly", Kw::poly, {&mods}, true);
    cubic.coefficients = quartic.coefficients = poly.coefficients = true;
    const RuleGroup polynomialRules{custom(Kw::xyz, readPolynomialTerm)};
    polynomial = makeSpec("a polynomial", Kw::polynomial, {&polynomialRules, &mods}, true);
    const RuleGroup juliaRules{flag(Kw::quaternion), flag(Kw::hypercomplex), flag(Kw::sqr), flag(Kw::cube),
                               flag(Kw::exp), flag(Kw::reciprocal), flag(Kw::sin), flag(Kw::asin), flag(Kw::sinh),
                               flag(Kw::asinh), flag(Kw::cos), flag(Kw::acos), flag(Kw::cosh), flag(Kw::acosh),
                               flag(Kw::tan), flag(Kw::atan), flag(Kw::tanh), flag(Kw::atanh), flag(Kw::ln),
                               custom(Kw::pwr, readPwr), number(Kw::max_iteration), number(Kw::precision),
                               list(Kw::slice, 2)};
    juliaFractal = makeSpec("a julia_fractal", Kw::julia_fractal, {&juliaRules, &mods}, true);
    const RuleGroup sweepRules{flag(Kw::linear_spline), flag(Kw::b_spline), flag(Kw::cubic_spline),
                               number(Kw::tolerance)};
    sphereSweep = makeSpec("a sphere_sweep", Kw::sphere_sweep, {&sweepRules, &mods}, true);
    const RuleGroup patchRules{number(Kw::type), number(Kw::flatness), number(Kw::u_steps), number(Kw::v_steps),
                               number(Kw::accuracy), custom(Kw::uv_vectors, readPatchUv)};
    bicubicPatch = makeSpec("a bicubic_patch", Kw::bicubic_patch, {&patchRules, &mods}, true);
    ovus = makeSpec("an ovus", Kw::ovus, {&mods}, true);
    const RuleGroup isoRules{function(Kw::function), sub(Kw::contained_by, containedBy), number(Kw::threshold),
                             number(Kw::accuracy), number(Kw::max_gradient), list(Kw::evaluate, 3),
                             number(Kw::max_trace), flag(Kw::all_intersections), number(Kw::method)};
    isosurface = makeSpec("an isosurface", Kw::isosurface, {&isoRules, &mods}, true);
    const RuleGroup parametricRules{function(Kw::function), sub(Kw::contained_by, containedBy),
                                    number(Kw::max_gradient), number(Kw::accuracy),
                                    custom(Kw::precompute, readPrecompute)};
    parametric = makeSpec("a parametric", Kw::parametric, {&parametricRules, &mods}, true);
    const RuleGroup containedRules{item(Kw::sphere), item(Kw::box)};
    containedBy = makeSpec("contained_by", Kw::contained_by, {&containedRules});

    const RuleGroup meshRules{item(Kw::triangle), item(Kw::smooth_triangle), expr(Kw::inside_vector)};
    mesh = makeSpec("a mesh", Kw::mesh, {&meshRules, &mods}, true);
    const RuleGroup mesh2Rules{sub(Kw::vertex_vectors, vectorList), sub(Kw::normal_vectors, vectorList),
                               sub(Kw::uv_vectors, vectorList), sub(Kw::texture_list, textureList),
                               sub(Kw::face_indices, vectorList), sub(Kw::normal_indices, vectorList),
                               sub(Kw::uv_indices, vectorList), expr(Kw::inside_vector)};
    mesh2 = makeSpec("a mesh2", Kw::mesh2, {&mesh2Rules, &mods}, true);
    vectorList = makeSpec("a vector list", Kw::vertex_vectors, {&none}, true);
    const RuleGroup textureListRules{item(Kw::texture)};
    textureList = makeSpec("a texture_list", Kw::texture_list, {&textureListRules}, true);
    const RuleGroup triangleRules{list(Kw::uv_vectors, 3)};
    triangle = makeSpec("a triangle", Kw::triangle, {&triangleRules, &mods}, true);
    smoothTriangle = makeSpec("a smooth_triangle", Kw::smooth_triangle, {&triangleRules, &mods}, true);

    csg = makeSpec("a CSG object", Kw::union_, {&mods}, false, true);
    object = makeSpec("an object", Kw::object, {&mods}, true, true);
    const RuleGroup groupRules{boolean(Kw::global_lights)};
    lightGroup = makeSpec("a light_group", Kw::light_group, {&groupRules, &mods}, false, true);

    const RuleGroup boundsRules{flag(Kw::clipped_by), flag(Kw::bounded_by)};
    bounds = makeSpec("bounded_by / clipped_by", Kw::bounded_by, {&boundsRules}, false, true);
    const RuleGroup photonRules{optNumber(Kw::target), boolean(Kw::refraction), boolean(Kw::reflection),
                                boolean(Kw::collect), boolean(Kw::pass_through), boolean(Kw::split_union)};
    photonsObject = makeSpec("an object's photons block", Kw::photons, {&photonRules});
    const RuleGroup radiosityRules{number(Kw::importance)};
    radiosityObject = makeSpec("an object's radiosity block", Kw::radiosity, {&radiosityRules});
}

}  // namespace rays::pov
