#include "rays/pov/specs.h"

namespace rays::pov {

using sdl::Entry;
using sdl::Interpreter;
using sdl::Value;

namespace {

// matrix <m00, m01, m02, m10, m11, m12, m20, m21, m22, m30, m31, m32>: twelve floats.
void readMatrix(Interpreter& in, Entry& e) {
    in.expectSym('<', "after 'matrix'");
    for (int i = 0; i < 12; ++i) {
        if (i) in.expectSym(',', "between the twelve values of matrix");
        e.args.push_back(Value::number(in.parseFloat()));
    }
    in.expectSym('>', "after the twelve values of matrix");
}

// transform { ... } or transform IDENTIFIER.
void readTransform(Interpreter& in, Entry& e) {
    if (in.isSym('{')) {
        e.args.push_back(Value::item(readBlockBody(in, specs().transform, Kw::transform)));
        return;
    }
    const sdl::Binding* b = in.identBinding();
    if (!b || b->value.type != sdl::VType::Item || b->value.item().kind != Kw::transform)
        in.errorHere("expected '{' or a transform identifier after 'transform', found " + in.describe());
    e.args.push_back(b->value);
    in.next();
}

}  // namespace

void readFunctionImage(Interpreter& in, Entry& e) {
    const sdl::Loc at = in.loc();
    e.args.push_back(Value::number(in.parseFloat()));
    in.expectSym(',', "between the width and height of a function image");
    e.args.push_back(Value::number(in.parseFloat()));
    e.args.push_back(in.parseFunctionBody({uint32_t(Kw::x), uint32_t(Kw::y), uint32_t(Kw::z)}, at));
}

const RuleGroup& transformRules() {
    static const RuleGroup g{expr(Kw::translate), expr(Kw::rotate), expr(Kw::scale), custom(Kw::matrix, readMatrix),
                             custom(Kw::transform, readTransform)};
    return g;
}

const RuleGroup& imageTypeRules() {
    static const RuleGroup g{string(Kw::gif), string(Kw::iff), string(Kw::jpeg), string(Kw::pgm), string(Kw::png),
                             string(Kw::pot), string(Kw::ppm), string(Kw::sys), string(Kw::tga), string(Kw::tiff),
                             string(Kw::exr), string(Kw::hdr)};
    return g;
}

Specs::Specs() {
    buildTextures();
    buildObjects();
    buildScene();
}

const Specs& specs() {
    static const Specs s;
    return s;
}

const BlockSpec* itemSpec(Kw k) {
    const Specs& s = specs();
    switch (k) {
        case Kw::pigment: return &s.pigment;
        case Kw::normal: return &s.normal;
        case Kw::finish: return &s.finish;
        case Kw::texture: return &s.texture;
        case Kw::interior: return &s.interior;
        case Kw::media: return &s.media;
        case Kw::density: return &s.density;
        case Kw::pattern: return &s.pattern;
        case Kw::material: return &s.material;
        case Kw::color_map: case Kw::colour_map: return &s.colorMap;
        case Kw::pigment_map: return &s.pigmentMap;
        case Kw::normal_map: return &s.normalMap;
        case Kw::slope_map: return &s.slopeMap;
        case Kw::texture_map: return &s.textureMap;
        case Kw::density_map: return &s.densityMap;
        case Kw::sphere: return &s.sphere;
        case Kw::box: return &s.box;
        case Kw::cone: return &s.cone;
        case Kw::cylinder: return &s.cylinder;
        case Kw::plane: return &s.plane;
        case Kw::torus: return &s.torus;
        case Kw::disc: return &s.disc;
        case Kw::polygon: return &s.polygon;
        case Kw::prism: return &s.prism;
        case Kw::lathe: return &s.lathe;
        case Kw::sor: return &s.sor;
        case Kw::superellipsoid: return &s.superellipsoid;
        case Kw::blob: return &s.blob;
        case Kw::height_field: return &s.heightField;
        case Kw::text: return &s.text;
        case Kw::quadric: return &s.quadric;
        case Kw::cubic: return &s.cubic;
        case Kw::quartic: return &s.quartic;
        case Kw::poly: return &s.poly;
        case Kw::polynomial: return &s.polynomial;
        case Kw::julia_fractal: return &s.juliaFractal;
        case Kw::sphere_sweep: return &s.sphereSweep;
        case Kw::bicubic_patch: return &s.bicubicPatch;
        case Kw::ovus: return &s.ovus;
        case Kw::isosurface: return &s.isosurface;
        case Kw::parametric: return &s.parametric;
        case Kw::mesh: return &s.mesh;
        case Kw::mesh2: return &s.mesh2;
        case Kw::triangle: return &s.triangle;
        case Kw::smooth_triangle: return &s.smoothTriangle;
        case Kw::union_: case Kw::merge: case Kw::difference: case Kw::intersection: return &s.csg;
        case Kw::object: return &s.object;
        case Kw::light_group: return &s.lightGroup;
        case Kw::camera: return &s.camera;
        case Kw::light_source: return &s.lightSource;
        case Kw::fog: return &s.fog;
        case Kw::rainbow: return &s.rainbow;
        case Kw::sky_sphere: return &s.skySphere;
        case Kw::background: return &s.background;
        case Kw::global_settings: return &s.globalSettings;
        case Kw::transform: return &s.transform;
        default: return nullptr;
    }
}

}  // namespace rays::pov
