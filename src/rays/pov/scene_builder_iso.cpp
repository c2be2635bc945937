// SceneBuilder's isosurface (reference 3.4.5.1.6): its function, container, threshold, accuracy,
// max_gradient and open. evaluate, max_trace, all_intersections and method are read and have no
// effect here (the march of scene/shapes/isosurface.cpp needs no adaptive gradient and finds every
// surface on its own).

#include "rays/error.h"
#include "rays/pov/scene_builder.h"
#include "rays/scene/shapes/isosurface.h"
#include "rays/sdl/function_value.h"

namespace rays::pov {

namespace {

// True when the program or a function it calls runs a pattern or pigment function's stand-in
// (those give 0 outside the parser; the isosurface would be wrong).
bool callsPatternStub(const fn::Program& p, int depth = 0) {
    for (const fn::HostFunction& h : p.hosts)
        if (sdl::isPatternStub(h)) return true;
    for (const auto& c : p.callees)
        if (c && depth < 64 && callsPatternStub(*c, depth + 1)) return true;
    return false;
}

// contained_by { box { A, B } } or { sphere { C, R } } into spec (the last one written counts).
void readContainer(const Item& block, IsosurfaceSpec& spec, const std::string& where) {
    for (const Entry& e : block.entries) {
        if (e.args.empty() || e.args[0].type != sdl::VType::Item) continue;
        const Item& shape = e.args[0].item();
        const std::vector<const Value*> v = positionals(shape);
        if (shape.kind == Kw::box) {
            if (v.size() < 2) throw Error(where + ": error: contained_by's box needs two corners");
            spec.sphere = false;
            spec.lo = toVec3(*v[0]);
            spec.hi = toVec3(*v[1]);
        } else if (shape.kind == Kw::sphere) {
            if (v.size() < 2) throw Error(where + ": error: contained_by's sphere needs a centre and a radius");
            spec.sphere = true;
            spec.centre = toVec3(*v[0]);
            spec.radius = toFloat(*v[1]);
        }
    }
}

}  // namespace

void SceneBuilder::addIsosurface(const std::vector<const Entry*>& entries, const sdl::Loc& at,
                                 const Transform& toWorld, const Appearance& look, bool open, bool inverse) {
    IsosurfaceSpec spec;
    spec.open = open;
    const sdl::FunctionValue* f = nullptr;
    for (const Entry* e : entries) {
        if (e->positional() || e->args.empty()) continue;
        switch (e->kw()) {
            case Kw::function:
                if (e->args[0].type == sdl::VType::Function) f = &e->args[0].fn();
                break;
            case Kw::contained_by:
                if (e->args[0].type == sdl::VType::Item) readContainer(e->args[0].item(), spec, notes_.where(e->loc));
                break;
            case Kw::threshold: spec.threshold = toFloat(e->args[0]); break;
            case Kw::accuracy: spec.accuracy = toFloat(e->args[0]); break;
            case Kw::max_gradient: spec.maxGradient = toFloat(e->args[0]); break;
            default: break;
        }
    }
    if (!f) throw Error(notes_.where(at) + ": error: an isosurface needs function { ... }");
    if (f->kind != sdl::FunctionValue::Kind::Float || !f->table || f->index < 0 ||
        callsPatternStub(f->table->program(f->index))) {
        notes_.note("isosurface function calling a pattern or pigment function of a pattern Rays does not render", at,
                    "(left out)");
        return;
    }
    spec.function = f->table->shared(f->index);
    Object o;
    o.line = int(at.line);
    o.col = int(at.col);
    auto data = std::make_unique<ShapeData>();
    if (!makeIsosurface(spec, o, *data)) return;
    o.material = material(look);
    prepareObject(o, toWorld);
    o.data = data.get();
    scene_.shapeData.push_back(std::move(data));
    emit(o, inverse);
}

}  // namespace rays::pov
