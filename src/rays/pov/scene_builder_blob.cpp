// SceneBuilder's blob (reference 3.4.5.1.1): its sphere and cylinder components with their
// strengths, transformations and textures, the obsolete `component`, and the threshold.

#include "rays/error.h"
#include "rays/pov/scene_builder.h"
#include "rays/scene/shapes/blob.h"

namespace rays::pov {

namespace {

bool isBlobEntry(Kw k) { return k == Kw::sphere || k == Kw::cylinder || k == Kw::component || k == Kw::threshold; }

}  // namespace

bool SceneBuilder::collectBlobEntry(Kw kind, const Entry& e) {
    if (kind != Kw::blob || !isBlobEntry(e.kw())) return false;
    if ((e.kw() == Kw::sphere || e.kw() == Kw::cylinder) && (e.args.empty() || e.args[0].type != sdl::VType::Item))
        return false;
    terms_.push_back(&e);
    return true;
}

// One sphere or cylinder component: its values, strength, transformations and own texture.
BlobComponent SceneBuilder::blobComponent(const Item& item, const Transform& toWorld, Appearance& own) {
    BlobComponent c;
    c.cylinder = item.kind == Kw::cylinder;
    std::vector<const Value*> v;
    bool strengthSet = false;
    for (const Entry& e : item.entries) {
        if (e.positional()) {
            for (const Value& x : e.args) v.push_back(&x);
            continue;
        }
        if (isTransformEntry(e)) {
            applyTransform(e, c.toBlob);
            if (own.set) placeLook(own, e);  // transformations after the texture move it (all its layers)
            continue;
        }
        if (applyAppearanceEntry(e, own, fallback_, notes_, &pigments_)) continue;
        if (e.kw() == Kw::strength && !e.args.empty()) {
            c.strength = toFloat(e.args[0]);
            strengthSet = true;
        }
    }
    const size_t n = c.cylinder ? 3 : 2;  // the values before the strength
    if (v.size() < n + (strengthSet ? 0 : 1))
        throw Error(notes_.where(item.loc) + ": error: a blob's " + std::string(sdl::keywordName(item.kind)) +
                    " needs " + (c.cylinder ? "two ends, a radius" : "a centre, a radius") + " and a strength");
    c.a = toVec3(*v[0]);
    c.b = c.cylinder ? toVec3(*v[1]) : c.a;
    c.radius = toFloat(*v[n - 1]);
    if (!strengthSet) c.strength = toFloat(*v[n]);
    if (c.toBlob.determinant() == 0)
        throw Error(notes_.where(item.loc) + ": error: the blob component's transformation is singular");
    if (own.set) placeLook(own, toWorld * c.toBlob);  // texture space → world
    return c;
}

// blob { components, threshold, modifiers } from the entries collectBlobEntry kept (terms_).
void SceneBuilder::addBlob(const sdl::Loc& at, const Transform& toWorld, const Appearance& look, bool inverse) {
    double threshold = 1;
    std::vector<BlobComponent> components;
    std::vector<Appearance> looks;  // the components' own textures
    for (const Entry* e : terms_) {
        if (e->kw() == Kw::threshold) {
            if (!e->args.empty()) threshold = toFloat(e->args[0]);
            continue;
        }
        if (e->kw() == Kw::component) {  // component Strength, Radius, <Center>: no texture, no transformation
            if (e->args.size() < 3) throw Error(notes_.where(e->loc) + ": error: component needs a strength, a radius and a centre");
            BlobComponent c;
            c.strength = toFloat(e->args[0]);
            c.radius = toFloat(e->args[1]);
            c.a = c.b = toVec3(e->args[2]);
            components.push_back(c);
            continue;
        }
        Appearance own;
        BlobComponent c = blobComponent(e->args[0].item(), toWorld, own);
        if (own.set) {
            c.part = int(looks.size());
            looks.push_back(own);
        }
        components.push_back(c);
    }
    terms_.clear();
    // A threshold of 0 or below draws nothing (measured: POV-Ray 3.7's trace() finds no surface).
    auto data = std::make_unique<ShapeData>();
    if (!(threshold > 0) || !makeBlob(components, *data)) return;
    Object o;
    o.line = int(at.line);
    o.col = int(at.col);
    o.type = ShapeType::Blob;
    o.r0 = threshold;
    o.material = material(look);
    prepareObject(o, toWorld);
    for (const Appearance& a : looks) {
        Object part = o;
        part.material = material(a);
        data->parts.push_back(part);
    }
    o.data = data.get();
    for (Object& part : data->parts) part.data = data.get();
    scene_.shapeData.push_back(std::move(data));
    emit(o, inverse);
}

}  // namespace rays::pov
