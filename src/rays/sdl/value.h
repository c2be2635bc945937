// Values of POV-Ray's scene language: floats, vectors of 2–5 components, colours (always five:
// red green blue filter transmit), strings, arrays, scene items (objects, textures, pigments,
// cameras, transforms, ... as the host reads them: item.h), user functions, splines, macros and
// file handles. Numbers are held inline; everything else behind one shared pointer.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rays/sdl/source_file.h"

namespace rays::sdl {

enum class VType : uint8_t { Undefined, Float, Vector, Color, String, Array, Item, Function, Spline, Macro, File };

/// Floats, vectors and colours: the types expressions compute with and promote into each other.
inline bool isNumericType(VType t) { return t == VType::Float || t == VType::Vector || t == VType::Color; }

/// "float", "vector", "colour", "string", "array", ... for messages.
const char* typeName(VType t);

struct ArrayData;
struct Item;
struct FunctionValue;
struct Spline;
struct MacroDef;
struct FileHandle;

struct Value {
    VType type = VType::Undefined;
    uint8_t dim = 0;                    ///< Float 1, Vector 2..5, Color 5
    std::array<double, 5> c{};          ///< components (Float: c[0])
    std::shared_ptr<void> ref;          ///< String, Array, Item, Function, Spline, Macro, File

    static Value number(double v) {
        Value r;
        r.type = VType::Float;
        r.dim = 1;
        r.c[0] = v;
        return r;
    }
    static Value vector(int dim, const double* comps) {
        Value r;
        r.type = VType::Vector;
        r.dim = uint8_t(dim);
        for (int i = 0; i < dim; ++i) r.c[i] = comps[i];
        return r;
    }
    static Value vec3(double x, double y, double z) {
        const double v[3] = {x, y, z};
        return vector(3, v);
    }
    static Value color(double r, double g, double b, double f = 0, double t = 0) {
        Value v;
        v.type = VType::Color;
        v.dim = 5;
        v.c = {r, g, b, f, t};
        return v;
    }
    static Value string(std::string s);
    static Value array(std::shared_ptr<ArrayData> a);
    static Value item(std::shared_ptr<const Item> i);
    static Value function(std::shared_ptr<const FunctionValue> f);
    static Value spline(std::shared_ptr<const Spline> s);
    static Value macro(std::shared_ptr<const MacroDef> m);
    static Value file(std::shared_ptr<FileHandle> f);

    bool isNumeric() const { return isNumericType(type); }
    bool defined() const { return type != VType::Undefined; }

    const std::string& str() const { return *static_cast<const std::string*>(ref.get()); }
    ArrayData& arr() const { return *static_cast<ArrayData*>(ref.get()); }
    const Item& item() const { return *static_cast<const Item*>(ref.get()); }
    std::shared_ptr<const Item> itemRef() const { return std::static_pointer_cast<const Item>(ref); }
    const FunctionValue& fn() const { return *static_cast<const FunctionValue*>(ref.get()); }
    const Spline& spline() const { return *static_cast<const Spline*>(ref.get()); }
    const MacroDef& macro() const { return *static_cast<const MacroDef*>(ref.get()); }
    FileHandle& file() const { return *static_cast<FileHandle*>(ref.get()); }
};

/// A float, vector or colour without Value's shared part: what expressions compute with
/// (trivially copied through the expression reader's levels).
struct Num {
    VType type = VType::Float;
    uint8_t dim = 1;
    std::array<double, 5> c{};

    static Num number(double v) {
        Num n;
        n.c[0] = v;
        return n;
    }
    /// The numeric part of a float, vector or colour value.
    static Num of(const Value& v) {
        Num n;
        n.type = v.type;
        n.dim = v.dim;
        n.c = v.c;
        return n;
    }
    Value value() const {
        Value v;
        v.type = type;
        v.dim = dim;
        v.c = c;
        return v;
    }
    bool isNumeric() const { return isNumericType(type); }
};

/// A POV-Ray array: up to 5 dimensions, elements unset until assigned; all assigned elements
/// share one type (the first assigned decides). Arrays are copied when assigned to another
/// identifier (POV-Ray copies them).
struct ArrayData {
    std::vector<int> sizes;
    std::vector<Value> elems;  ///< row-major; type Undefined while unset
    VType elemType = VType::Undefined;
};

/// A deep copy of a value (arrays and their nested arrays are copied; everything else is
/// immutable and shared).
Value copyValue(const Value& v);
/// The elements copyValue(v) makes: those of v and of its nested arrays (0 for a non-array).
uint64_t arrayElementCount(const Value& v);

/// A macro: its parameters and where its body starts (the token after the parameter list).
struct MacroDef {
    uint32_t name = 0;
    std::vector<uint32_t> params;
    std::vector<bool> optional;  ///< POV-Ray 3.8's `optional` parameters (Rays accepts them)
    uint32_t file = 0;           ///< SourceFile id
    uint32_t bodyStart = 0;      ///< token index
    Loc loc;
};

/// A spline value: `spline { [type] t0, <p0>, t1, <p1>, ... }` (POV-Ray 3.7 reference, "Spline").
struct Spline {
    enum class Type : uint8_t { Linear, Quadratic, Cubic, Natural };
    Type type = Type::Linear;
    int dim = 3;  ///< components of the widest point (2..5)
    std::vector<double> t;                      ///< parameters, ascending
    std::vector<std::array<double, 5>> points;  ///< one per parameter
};

/// The spline's point at parameter t, interpolated as type (not necessarily the spline's own).
std::array<double, 5> evaluateSpline(const Spline& s, Spline::Type type, double t);

}  // namespace rays::sdl
