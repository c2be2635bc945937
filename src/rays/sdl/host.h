// The boundary between the scene language and whoever reads scenes with it (as Lua's API is for
// its host): the language knows which keywords start scene items and asks the host to read
// them; the host reads them with the interpreter's token and expression calls and gives back an
// Item; top-level items and `#default` go to the host. Parse-time questions about geometry
// (trace, inside, min_extent, max_extent) are answered by the host too.
#pragma once
#include <array>
#include <string>

#include "rays/fn/program.h"
#include "rays/sdl/item.h"
#include "rays/sdl/keywords.h"

namespace rays::sdl {

class Interpreter;

class ItemHost {
public:
    virtual ~ItemHost() = default;
    /// True when keyword k starts a scene item (sphere, union, texture, pigment, camera, ...).
    virtual bool startsItem(Kw k) const = 0;
    /// Reads the item whose keyword is the current token; returns it with the token after it current.
    virtual ItemRef readItem(Interpreter& in) = 0;
    /// A top-level item of the scene (an object, camera, light, global_settings, fog, ...).
    virtual void topLevel(Interpreter& in, const ItemRef& item) = 0;
    /// `#default { ... }`: the item is a texture, pigment, normal or finish.
    virtual void setDefault(Interpreter& in, const ItemRef& item) = 0;

    /// Parse-time geometry. supported = false when the host cannot answer (the caller then warns
    /// that the feature is not available yet and uses zeros).
    struct TraceResult {
        bool supported = false;
        bool hit = false;
        double point[3]{}, normal[3]{};
    };
    virtual TraceResult trace(const ItemRef& object, const double origin[3], const double dir[3]) = 0;
    /// inside(): 1 inside, 0 outside, -1 not supported.
    virtual int inside(const ItemRef& object, const double point[3]) = 0;
    /// The 3×4 matrix (rows, object → world) of a transform item, for transform functions.
    virtual std::array<double, 12> transformMatrix(const Item& transform) = 0;
    /// min_extent / max_extent: false when not supported.
    virtual bool extent(const ItemRef& object, double lo[3], double hi[3]) = 0;
    /// `function { pattern { ... } }` (pigment = false: the pattern's value, one output) or
    /// `function { pigment { ... } }` (the colour: red, green, blue, filter, transmit) compiled
    /// into a host function of x, y, z that owns what it evaluates (HostFunction::keep). A function
    /// with fn == nullptr when the host cannot evaluate the item (the caller uses a stand-in that
    /// gives 0).
    virtual fn::HostFunction patternFunction(const Item& item, bool pigment) {
        (void)item;
        (void)pigment;
        return {};
    }
    /// vturbulence(lambda, omega, octaves, p): the displacement vector the host's turbulence
    /// moves p by at amount 1; false when the host has no turbulence (the caller gives <0,0,0>).
    virtual bool turbulence(const double p[3], double lambda, double omega, int octaves, double out[3]) {
        (void)p, (void)lambda, (void)omega, (void)octaves, (void)out;
        return false;
    }
};

}  // namespace rays::sdl
