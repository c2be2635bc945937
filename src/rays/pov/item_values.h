// Reading the values the grammar stored in items: vectors and colours with POV-Ray's promotion,
// the positional arguments of a block, and transformation entries.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "rays/math/transform.h"
#include "rays/math/vec3.h"
#include "rays/sdl/item.h"

namespace rays::pov {

using sdl::Entry;
using sdl::Item;
using sdl::Kw;
using sdl::Value;

/// A float promoted to <f, f, f>, a vector's first three components (missing ones 0).
Vec3 toVec3(const Value& v);
/// A float, or the first component of a vector.
double toFloat(const Value& v);

/// A boolean modifier (`no_shadow`, `refraction on`, ...): on when written bare or with a value
/// other than 0.
inline bool isOn(const Entry& e) { return e.args.empty() || toFloat(e.args[0]) != 0; }

/// v as an int in [lo, hi], clamped as a float first (1e300 has no int); NaN gives lo.
inline int clampedInt(double v, int lo, int hi) { return std::isnan(v) ? lo : int(std::clamp(v, double(lo), double(hi))); }

struct Rgbft {
    Vec3 rgb;
    double filter = 0, transmit = 0;
};
/// A colour value: a float fills all five components, a vector leaves filter and transmit 0.
Rgbft toColor(const Value& v);

/// The bare values of a block in order (a sphere's centre and radius, ...).
std::vector<const Value*> positionals(const Item& item);
/// The first entry with keyword k, or null.
const Entry* findEntry(const Item& item, Kw k);
bool hasEntry(const Item& item, Kw k);

/// True for translate, rotate, scale, matrix and transform.
bool isTransformEntry(const Entry& e);
/// m becomes the entry's transformation applied after m (POV-Ray applies modifiers in order).
/// A zero scale component is changed to 1, as POV-Ray does.
void applyTransform(const Entry& e, Transform& m);
/// The transformation of a `transform { ... }` item (its entries in order, then `inverse`).
Transform transformOf(const Item& t);

}  // namespace rays::pov
