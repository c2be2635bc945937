#include "rays/pov/item_values.h"

#include "rays/pov/grammar.h"

namespace rays::pov {

using sdl::VType;

Vec3 toVec3(const Value& v) {
    if (v.type == VType::Float) return Vec3(v.c[0]);
    if (!v.isNumeric()) return {};
    return {v.c[0], v.dim > 1 ? v.c[1] : 0.0, v.dim > 2 ? v.c[2] : 0.0};
}

double toFloat(const Value& v) { return v.isNumeric() ? v.c[0] : 0.0; }

Rgbft toColor(const Value& v) {
    Rgbft c;
    if (v.type == VType::Float) {
        c.rgb = Vec3(v.c[0]);
        c.filter = c.transmit = v.c[0];
    } else if (v.isNumeric()) {
        c.rgb = {v.c[0], v.dim > 1 ? v.c[1] : 0.0, v.dim > 2 ? v.c[2] : 0.0};
        c.filter = v.dim > 3 ? v.c[3] : 0.0;
        c.transmit = v.dim > 4 ? v.c[4] : 0.0;
    }
    return c;
}

std::vector<const Value*> positionals(const Item& item) {
    std::vector<const Value*> out;
    for (const Entry& e : item.entries)
        if (e.positional())
            for (const Value& v : e.args) out.push_back(&v);
    return out;
}

const Entry* findEntry(const Item& item, Kw k) {
    for (const Entry& e : item.entries)
        if (e.key == uint16_t(k)) return &e;
    return nullptr;
}

bool hasEntry(const Item& item, Kw k) { return findEntry(item, k) != nullptr; }

bool isTransformEntry(const Entry& e) {
    if (e.positional() || e.key == kMapEntry) return false;
    const Kw k = e.kw();
    return k == Kw::translate || k == Kw::rotate || k == Kw::scale || k == Kw::matrix || k == Kw::transform;
}

void applyTransform(const Entry& e, Transform& m) {
    Transform t;
    switch (e.kw()) {
        case Kw::translate: t = Transform::translate(toVec3(e.args[0])); break;
        case Kw::rotate: t = Transform::rotatePovray(toVec3(e.args[0])); break;
        case Kw::scale: {
            Vec3 s = toVec3(e.args[0]);
            for (int i = 0; i < 3; ++i)
                if (s[i] == 0) s[i] = 1;
            t = Transform::scale(s);
            break;
        }
        case Kw::matrix: {
            // matrix <m00..m32>: p' = p·M with p a row vector (POV-Ray 3.7 reference, "Matrix").
            double v[12];
            for (int i = 0; i < 12; ++i) v[i] = toFloat(e.args[size_t(i)]);
            for (int r = 0; r < 3; ++r) {
                for (int c = 0; c < 3; ++c) t.m[r][c] = v[c * 3 + r];
                t.m[r][3] = v[9 + r];
            }
            break;
        }
        case Kw::transform:
            t = transformOf(e.args[0].item());
            break;
        default:
            return;
    }
    m = t * m;
}

Transform transformOf(const Item& t) {
    Transform m;
    bool inverse = false;
    for (const Entry& e : t.entries) {
        if (e.positional()) {
            for (const Value& v : e.args)
                if (v.type == VType::Item && v.item().kind == Kw::transform) m = transformOf(v.item()) * m;
        } else if (e.kw() == Kw::inverse) {
            inverse = true;
        } else {
            applyTransform(e, m);
        }
    }
    if (inverse && m.determinant() != 0) m = m.inverse();
    return m;
}

}  // namespace rays::pov
