// Every block spec of POV-Ray 3.7's scene items, built once (specs.cpp and the specs_*.cpp files
// that fill it): the Specs object owns them all so that specs may refer to each other
// (a pigment holds a pigment_map whose entries are pigments).
#pragma once
#include "rays/pov/grammar.h"

namespace rays::pov {

struct Specs {
    // textures (specs_texture.cpp)
    BlockSpec pigment, normal, finish, texture, interior, media, density, material, pattern;
    BlockSpec colorMap, pigmentMap, normalMap, slopeMap, textureMap, densityMap;
    BlockSpec pigmentBody, normalBody, textureBody, densityBody;  // map entries' bodies
    BlockSpec warp, imageMap, reflection, irid, subsurfaceFinish, scattering, materialMap, tiles, slope;
    BlockSpec patternTypes;  ///< the pattern type keywords alone (agate ... wrinkles), for isPatternType
    // objects (specs_objects.cpp)
    BlockSpec sphere, box, cone, cylinder, plane, torus, disc, polygon, prism, lathe, sor, superellipsoid, blob,
        heightField, text, quadric, cubic, quartic, poly, polynomial, juliaFractal, sphereSweep, bicubicPatch, ovus,
        isosurface, parametric, mesh, mesh2, triangle, smoothTriangle, csg, object, lightGroup;
    BlockSpec bounds, containedBy, vectorList, textureList, photonsObject, radiosityObject;
    // scene (specs_scene.cpp)
    BlockSpec camera, meshCamera, lightSource, lookLike, photonsLight, fog, rainbow, skySphere, background,
        globalSettings, radiositySettings, photonsGlobal, subsurfaceGlobal, transform;

    Specs();
    void buildTextures();
    void buildObjects();
    void buildScene();
};

/// The one Specs of the program.
const Specs& specs();
/// True when k names a pattern type (checker, wood, gradient, ...).
inline bool isPatternType(Kw k) { return specs().patternTypes.find(k) != nullptr; }

// Rule constructors and the rule groups shared between files.
inline Rule flag(Kw k) { return {k, Arg::Flag}; }
inline Rule boolean(Kw k) { return {k, Arg::Bool}; }
inline Rule number(Kw k) { return {k, Arg::Float}; }
inline Rule optNumber(Kw k) { return {k, Arg::OptFloat}; }
inline Rule expr(Kw k) { return {k, Arg::Expr}; }
inline Rule optExpr(Kw k) { return {k, Arg::OptExpr}; }
inline Rule list(Kw k, int n = 0) { return {k, Arg::List, n}; }
inline Rule color(Kw k) { return {k, Arg::Color}; }
inline Rule string(Kw k) { return {k, Arg::String}; }
inline Rule sub(Kw k, const BlockSpec& s) { return {k, Arg::Sub, 0, &s}; }
inline Rule subOrExpr(Kw k, const BlockSpec& s) { return {k, Arg::SubOrExpr, 0, &s}; }
inline Rule item(Kw k) { return {k, Arg::Item}; }
inline Rule function(Kw k) { return {k, Arg::Function}; }
inline Rule custom(Kw k, CustomReader r) { return {k, Arg::Custom, 0, nullptr, r}; }

/// translate, rotate, scale, matrix, transform.
const RuleGroup& transformRules();
/// The image file types: gif iff jpeg pgm png pot ppm sys tga tiff exr hdr, each with a file name.
const RuleGroup& imageTypeRules();
/// `function W, H { ... }` (image maps and height fields made from a function).
void readFunctionImage(sdl::Interpreter& in, sdl::Entry& e);

}  // namespace rays::pov
