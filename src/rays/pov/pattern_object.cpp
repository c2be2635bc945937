#include "rays/pov/pattern_object.h"

#include <cmath>
#include <vector>

#include "rays/pov/standalone_object.h"
#include "rays/scene/csg.h"

namespace rays::pov {

using sdl::Kw;

namespace {

// The built object and its parts' world boxes (empty for unbounded parts: always tested).
struct ObjectInside {
    Scene scene;
    std::vector<Bounds> bounds;
};

// Within box b, widened a little: some insides reach beyond their surfaces (csg.cpp insideShape).
bool inBox(const Bounds& b, Vec3 p) {
    for (int a = 0; a < 3; ++a) {
        const double pad = 1e-8 * (1 + std::fabs(b.lo[a]) + std::fabs(b.hi[a]));
        if (!(p[a] >= b.lo[a] - pad && p[a] <= b.hi[a] + pad)) return false;
    }
    return true;
}

// Inside any part (a union's parts: POV-Ray's union is inside where any child is), as PovHost's
// inside() decides; shapes without an inside (triangles, polygons, meshes without inside_vector)
// are outside everywhere, as in POV-Ray (measured).
bool insideObject(const void* data, Vec3 p) {
    const auto& o = *static_cast<const ObjectInside*>(data);
    for (size_t i = 0; i < o.scene.objects.size(); ++i) {
        if (!o.bounds[i].empty() && !inBox(o.bounds[i], p)) continue;
        if (insideShape(o.scene.objects[i], p) > 0) return true;
    }
    return false;
}

}  // namespace

bool isObjectPatternListEntry(const sdl::Entry& e) {
    if (e.positional()) {
        for (const sdl::Value& v : e.args)
            if (v.type == sdl::VType::Item) return false;
        return true;  // a colour
    }
    const Kw k = e.kw();
    return k == Kw::pigment || k == Kw::normal || k == Kw::texture || k == Kw::density;
}

BuiltPatternObject buildInsideTest(const sdl::ItemRef& object, const std::function<std::string(const sdl::Loc&)>& where,
                                   const std::function<std::string(const std::string&)>& findFile, FontCache* fonts) {
    BuiltPatternObject out;
    // Inside an intersection of one, so that `inverse` (which the scene builder reads only in CSG)
    // turns the object inside out; the object alone when that leaves a part out (a mesh without
    // inside_vector in CSG).
    auto wrapped = std::make_shared<sdl::Item>();
    wrapped->kind = Kw::intersection;
    wrapped->loc = object->loc;
    wrapped->depth = object->depth + 1;
    wrapped->size = object->size + 1;
    sdl::Entry child;
    child.key = uint16_t(object->kind);
    child.loc = object->loc;
    child.args.push_back(sdl::Value::item(object));
    wrapped->entries.push_back(std::move(child));
    StandaloneObject built = buildStandalone(wrapped, where, findFile, fonts);
    if (!built.complete || built.scene.objects.empty()) built = buildStandalone(object, where, findFile, fonts);
    out.complete = built.complete;
    if (built.scene.objects.empty()) return out;
    auto inside = std::make_shared<ObjectInside>();
    inside->scene = std::move(built.scene);
    for (const Object& o : inside->scene.objects) inside->bounds.push_back(worldBounds(o));
    auto test = std::make_shared<pattern::PatternObject>();
    test->inside = insideObject;
    test->data = inside.get();
    test->keep = std::move(inside);
    out.object = std::move(test);
    return out;
}

BuiltPatternObject buildPatternObject(const sdl::Item& pattern, const std::function<std::string(const sdl::Loc&)>& where,
                                      const std::function<std::string(const std::string&)>& findFile, FontCache* fonts) {
    auto item = std::make_shared<sdl::Item>();
    item->kind = Kw::object;
    item->loc = pattern.loc;
    item->depth = pattern.depth;
    item->size = pattern.size;
    for (const sdl::Entry& e : pattern.entries)
        if (!isObjectPatternListEntry(e)) item->entries.push_back(e);
    return buildInsideTest(item, where, findFile, fonts);
}

}  // namespace rays::pov
