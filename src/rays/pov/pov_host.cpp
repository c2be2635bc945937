#include "rays/pov/pov_host.h"

#include <algorithm>
#include <cmath>

#include "rays/accel/bvh.h"
#include "rays/pattern/noise.h"
#include "rays/pov/grammar.h"
#include "rays/pov/item_values.h"
#include "rays/pov/pattern_function.h"
#include "rays/pov/pattern_object.h"
#include "rays/pov/scene_builder.h"
#include "rays/pov/standalone_object.h"

namespace rays::pov {

using sdl::Kw;

// Parse-time geometry (trace, min_extent, max_extent): the object built as the scene builder
// builds it, alone, with its own BVH; built once per object value.
struct PovHost::Probe {
    sdl::ItemRef object;  ///< keeps the item (the cache's key) alive
    Scene scene;
    Bvh bvh;
    bool complete = true;  ///< every part of the object could be built
};

PovHost::PovHost(ParsedScene& out) : out_(out) {}
PovHost::~PovHost() = default;

const PovHost::Probe& PovHost::probe(const sdl::ItemRef& object) {
    auto& slot = probes_[object.get()];
    if (!slot) {
        slot = std::make_unique<Probe>();
        slot->object = object;
        StandaloneObject built = buildStandalone(object, where_, findFile_, &fonts_);
        slot->scene = std::move(built.scene);
        // trace(), inside() and the extents need the shapes only: a texture drawn otherwise (a
        // pattern Rays does not render) leaves them whole.
        slot->complete = built.complete;
        slot->bvh = Bvh(slot->scene.objects);
    }
    return *slot;
}

// Pattern and pigment functions are compiled here, while parsing, so that calls made while
// parsing and the render evaluate the same thing. What the pattern compiler notes (a warp Rays
// leaves out) stays quiet: the function is evaluated without it; an unrendered pattern gives no
// function, and its users are noted where they are built.
fn::HostFunction PovHost::patternFunction(const sdl::Item& item, bool pigment) {
    std::function<std::string(const sdl::Loc&)> where = where_;
    if (!where) where = [](const sdl::Loc&) { return std::string(); };
    NotRendered quiet(where, nullptr, false);
    // An object pattern's object is built alone, as inside() builds its object.
    const PatternObjectBuilder buildObject = [this, where](const sdl::Item& pattern) {
        return buildPatternObject(pattern, where, findFile_, &fonts_);
    };
    return compilePatternFunction(item, pigment, quiet, findFile_, buildObject, noiseGenerator_);
}

bool PovHost::startsItem(Kw k) const { return itemSpec(k) != nullptr; }

sdl::ItemRef PovHost::readItem(sdl::Interpreter& in) {
    const BlockSpec* spec = itemSpec(in.kw());
    if (!spec) in.errorHere("expected a scene item, found " + in.describe());
    sdl::ItemRef item = readBlock(in, *spec);
    if (item->kind == Kw::texture && in.peekRawKw(Kw::texture)) item = readTextureLayers(in, *spec, std::move(item));
    // Parts of a texture the item leaves unset come from the #default in force here, not where the
    // item is used (builder's defaultLookAt). The item was just made and is not shared yet.
    const_cast<sdl::Item&>(*item).hostMark = uint32_t(defaults_ ? defaults_->size() : 0);
    return item;
}


void PovHost::topLevel(sdl::Interpreter& in, const sdl::ItemRef& item) {
    if (item->kind == Kw::global_settings) {
        // srgb colours read later in the file need the working gamma.
        for (const sdl::Entry& e : item->entries)
        {
            if (e.key == uint16_t(Kw::assumed_gamma) && !e.args.empty()) in.setAssumedGamma(e.args[0].c[0]);
            // Pattern functions compiled after this use the scene's noise generator.
            if (e.key == uint16_t(Kw::noise_generator) && !e.args.empty())
                noiseGenerator_ = std::clamp(int(e.args[0].c[0]), 1, 3);
        }
    }
    ParsedScene::Top top{item, defaults_, defaults_ ? defaults_->size() : 0, in.compatibilityVersion()};
    if (out_.sink) out_.sink(top);
    else out_.items.push_back(std::move(top));
}

// Each #default adds to the defaults in force (POV-Ray 3.7 reference, "Default Directive"): the
// default texture is one list of texture entries applied in order. Items read so far keep their
// prefix of it: the list is appended to, never copied (a loop of #default and objects stays linear).
void PovHost::setDefault(sdl::Interpreter&, const sdl::ItemRef& item) {
    if (!defaults_) defaults_ = std::make_shared<std::vector<sdl::Entry>>();
    sdl::Entry e;
    e.key = uint16_t(item->kind);
    e.loc = item->loc;
    e.args.push_back(sdl::Value::item(item));
    defaults_->push_back(std::move(e));
}

PovHost::TraceResult PovHost::trace(const sdl::ItemRef& object, const double origin[3], const double dir[3]) {
    TraceResult r;
    const Probe& p = probe(object);
    r.supported = p.complete;
    const Vec3 d{dir[0], dir[1], dir[2]};
    if (length(d) == 0) return r;
    const Ray ray{Vec3{origin[0], origin[1], origin[2]}, normalize(d)};
    const Hit h = p.bvh.closest(p.scene.objects, ray, 1e-6, kInfinity);
    if (!h.valid()) return r;
    r.hit = true;
    const Vec3 at = ray.at(h.t);
    // POV-Ray gives the surface's outward normal, whichever side the ray came from (measured).
    const Vec3 n = h.normal;
    for (int i = 0; i < 3; ++i) {
        r.point[i] = at[i];
        r.normal[i] = n[i];
    }
    return r;
}

// inside(): the object pattern's inside test (pattern_object.h): inside any part of the object (a
// union's parts, as POV-Ray's union is inside where any child is), `inverse` honoured; shapes
// without an inside are outside.
int PovHost::inside(const sdl::ItemRef& object, const double point[3]) {
    auto [it, added] = insides_.try_emplace(object.get());
    InsideProbe& p = it->second;
    if (added) {
        p.object = object;
        p.test = buildInsideTest(object, where_, findFile_, &fonts_);
    }
    if (!p.test.complete || !p.test.object) return -1;
    return p.test.object->index(Vec3{point[0], point[1], point[2]});
}

bool PovHost::extent(const sdl::ItemRef& object, double lo[3], double hi[3]) {
    const Probe& p = probe(object);
    if (!p.complete || p.scene.objects.empty()) return false;
    constexpr double kHuge = 2e10;  // an unbounded object's extent
    Bounds all;
    bool unbounded = false;
    for (const Object& o : p.scene.objects) {
        const Bounds b = worldBounds(o);
        if (b.empty()) unbounded = true;
        else all.extend(b);
    }
    for (int i = 0; i < 3; ++i) {
        lo[i] = unbounded ? -kHuge : all.lo[i];
        hi[i] = unbounded ? kHuge : all.hi[i];
    }
    return true;
}

// vturbulence (POV-Ray 3.7 reference, "Vector Functions": the turbulence vector at a point for
// the given lambda, omega and octaves): the displacement Rays' own turbulence applies at amount 1
// (pattern/noise: the sum of the octaves' vector noise), so the vectors match Rays' patterns, not
// POV-Ray's noise.
bool PovHost::turbulence(const double p[3], double lambda, double omega, int octaves, double out[3]) {
    pattern::Turbulence t;
    t.amount = {1, 1, 1};
    t.lambda = lambda;
    t.omega = omega;
    t.octaves = std::clamp(octaves, 1, 10);
    const Vec3 v = pattern::turbulenceVector({p[0], p[1], p[2]}, t);
    out[0] = v.x, out[1] = v.y, out[2] = v.z;
    return true;
}

std::array<double, 12> PovHost::transformMatrix(const sdl::Item& t) {
    const Transform m = transformOf(t);
    std::array<double, 12> out{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) out[size_t(r * 4 + c)] = m.m[r][c];
    return out;
}

}  // namespace rays::pov
