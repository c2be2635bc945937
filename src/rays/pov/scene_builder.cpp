#include "rays/pov/scene_builder.h"

#include <algorithm>
#include <cmath>

#include "rays/accel/huge_pages.h"
#include "rays/error.h"
#include "rays/pattern/ripples.h"
#include "rays/pov/grammar.h"
#include "rays/pov/pattern_object.h"
#include "rays/pov/photon_settings.h"
#include "rays/pov/radiosity_settings.h"
#include "rays/pov/scene_builder_parts.h"
#include "rays/pov/subsurface_settings.h"

namespace rays::pov {

using sdl::VType;

namespace {

constexpr int kMaxObjectDepth = 1000;

// Puts a builder state back as it was when the object that changed it is done (no_shadow, a
// light_group, ... hold for the object and everything inside it).
template <class T>
struct Restore {
    T& state;
    T saved;
    ~Restore() { state = saved; }
};

// The keywords of a julia_fractal's own items (reference's JF_ITEM), read by build_shapes.
bool isJuliaTerm(Kw k) {
    switch (k) {
        case Kw::quaternion: case Kw::hypercomplex: case Kw::sqr: case Kw::cube: case Kw::exp: case Kw::reciprocal:
        case Kw::sin: case Kw::asin: case Kw::sinh: case Kw::asinh: case Kw::cos: case Kw::acos: case Kw::cosh:
        case Kw::acosh: case Kw::tan: case Kw::atan: case Kw::tanh: case Kw::atanh: case Kw::ln: case Kw::pwr:
        case Kw::max_iteration: case Kw::precision: case Kw::slice:
            return true;
        default:
            return false;
    }
}

}  // namespace

bool isObjectKind(Kw k) {
    switch (k) {
        case Kw::sphere: case Kw::box: case Kw::cone: case Kw::cylinder: case Kw::plane: case Kw::torus: case Kw::disc:
        case Kw::polygon: case Kw::prism: case Kw::lathe: case Kw::sor: case Kw::superellipsoid: case Kw::blob:
        case Kw::height_field: case Kw::text: case Kw::quadric: case Kw::cubic: case Kw::quartic: case Kw::poly:
        case Kw::polynomial: case Kw::julia_fractal: case Kw::sphere_sweep: case Kw::bicubic_patch: case Kw::ovus:
        case Kw::isosurface: case Kw::parametric: case Kw::mesh: case Kw::mesh2: case Kw::triangle:
        case Kw::smooth_triangle: case Kw::union_: case Kw::merge: case Kw::difference: case Kw::intersection:
        case Kw::object: case Kw::light_group: case Kw::light_source:
            return true;
        default:
            return false;
    }
}

namespace {

bool isMeshKind(Kw k) { return k == Kw::mesh || k == Kw::mesh2; }

}  // namespace

// An object's entries with `object { Base ... }` copies unrolled: the base's entries come first,
// then the copy's (POV-Ray applies a copy's modifiers after the base's own). `mesh { M ... }`
// with M a declared mesh or mesh2 is such a copy too (measured: POV-Ray 3.7 draws M with the
// modifiers; the mesh_camera demos write their camera meshes so). `marks`, when given, gets the
// hostMark of the item each entry was written in.
Kw unrollObject(const Item& item, std::vector<const Entry*>& out, int depth, std::vector<uint32_t>* marks) {
    const bool meshCopy = isMeshKind(item.kind);
    if ((item.kind != Kw::object && !meshCopy) || depth > kMaxObjectDepth) {
        for (const Entry& e : item.entries) out.push_back(&e);
        if (marks) marks->resize(out.size(), item.hostMark);
        return item.kind;
    }
    Kw kind = item.kind;
    bool baseDone = false;
    for (const Entry& e : item.entries) {
        // The base: an object identifier, or an object written inside (`object { union {...} }`).
        const bool base = !e.args.empty() && e.args[0].type == VType::Item &&
                          (meshCopy ? e.positional() && isMeshKind(e.args[0].item().kind)
                                    : (e.positional() || isObjectKind(e.kw())) && isObjectKind(e.args[0].item().kind));
        if (!baseDone && base) {
            kind = unrollObject(e.args[0].item(), out, depth + 1, marks);
            baseDone = true;
            continue;
        }
        out.push_back(&e);
        if (marks) marks->push_back(item.hostMark);
    }
    return kind;
}

void SceneBuilder::add(const ParsedScene::Top& top) {
    version_ = top.version;
    pigments_.setLanguageVersion(version_);
    const Item& item = *top.item;
    updateDefaults(top);
    switch (item.kind) {
        case Kw::camera: return addCamera(item);
        case Kw::light_source: return addLight(item, Transform{});
        case Kw::global_settings: return globalSettings(item);
        case Kw::background: {
            const std::vector<const Value*> p = positionals(item);
            if (!p.empty()) scene_.pov.background = toColor(*p[0]).rgb;
            backgroundSet_ = true;
            return;
        }
        case Kw::sky_sphere: return addSkySphere(item);
        case Kw::fog: return addFog(item);
        case Kw::rainbow: return addRainbow(item);
        case Kw::media: return addAtmosphericMedia(item);
        default:
            if (isObjectKind(item.kind)) return addObject(item, Transform{}, nullptr, 0);
            notes_.note(std::string(sdl::keywordName(item.kind)) + " at the top level", item.loc);
    }
}

// The #default entries not applied yet are applied to the default look kept from the items before
// (items come in file order and their defaults only grow), so n items under n #defaults cost O(n).
void SceneBuilder::updateDefaults(const ParsedScene::Top& top) {
    if (top.defaults != defaultsSeen_ || top.defaultsCount < defaultsApplied_) {
        defaultsSeen_ = top.defaults;
        defaultsApplied_ = 0;
        defaultsLook_ = Appearance{};
        earlierDefaults_.clear();
    }
    applyDefaults(defaultsLook_, defaultsApplied_, top.defaultsCount);
    defaultsApplied_ = top.defaultsCount;
    fallback_ = defaultsLook_;
    fallback_.set = false;
}

// `#default { texture {...} }` makes that texture the default one; `#default { pigment {...} }`,
// `finish` and `normal` change the part of it they name (measured: a default texture of rgbf
// glass shows as glass, not as the black default pigment).
void SceneBuilder::applyDefaults(Appearance& look, size_t from, size_t to) {
    for (size_t i = from; i < to; ++i) {
        const Entry& e = (*defaultsSeen_)[i];
        if (!e.positional() && e.kw() == Kw::texture && !e.args.empty() && e.args[0].type == VType::Item) {
            look = Appearance{};
            applyTexture(e.args[0].item(), look, notes_, &pigments_);
            continue;
        }
        Item added;
        added.kind = Kw::texture;
        added.entries.push_back(e);
        applyTexture(added, look, notes_, &pigments_);
    }
}

// The default texture of an item read when `mark` #default entries were in force. POV-Ray gives
// a texture the default in force where it is written (POV-Ray 3.7 reference, "The #default
// Directive"; measured: an orange sphere's `texture { pigment { Orange } }` declared before
// `#default { texture { finish { ambient 0 diffuse 0 } } }` and drawn after it keeps the finish
// before, as interior/iortest.pov shows); an object with no texture at all takes the one in force
// where it is placed in the scene (fallback_). Earlier defaults are made once each, from the
// nearest one made before; every 64th is kept on the way, so that marks asked for in any order
// cost at most 64 steps each beyond the first.
const Appearance& SceneBuilder::defaultLookAt(uint32_t mark) {
    constexpr uint32_t kEvery = 64;
    if (!defaultsSeen_ || mark >= defaultsApplied_) return fallback_;
    auto at = earlierDefaults_.find(mark);
    if (at != earlierDefaults_.end()) return at->second;
    Appearance look;
    size_t from = 0;
    auto below = earlierDefaults_.lower_bound(mark);
    if (below != earlierDefaults_.begin()) {
        --below;
        look = below->second;
        from = below->first;
    }
    while (from < mark) {
        const size_t to = std::min<size_t>(mark, (from / kEvery + 1) * kEvery);
        applyDefaults(look, from, to);
        look.set = false;
        from = to;
        if (from < mark) earlierDefaults_.emplace(uint32_t(from), look);
    }
    return earlierDefaults_.emplace(mark, std::move(look)).first->second;
}

// ---- objects ---------------------------------------------------------------------------------

Material SceneBuilder::material(const Appearance& look) {
    Material m;
    m.color = look.pigment.rgb;
    m.filter = std::clamp(look.pigment.filter, 0.0, 1.0);
    m.ambient = look.finish.ambient.x;
    m.diffuse = look.finish.diffuse;
    m.specular = look.finish.specular;
    m.reflection = look.finish.reflectionMax.x;
    m.ior = look.interior.ior;
    PovSurface s;
    s.finish = look.finish;
    s.interior = look.interior;
    placeInteriorMedia(look.interior, s.interior);
    s.hollow = hollow_;
    s.transmit = look.pigment.transmit;
    s.noShadow = noShadow_;
    s.pigment = pigmentRoot(look);
    if (s.pigment >= 0) s.pigmentTransparent = scene_.pigments.mayLetLightThrough(look.pigmentNode);
    s.noImage = noImage_;
    s.noReflection = noReflection_;
    s.noRadiosity = noRadiosity_;
    s.doubleIlluminate = doubleIlluminate_;
    s.photons = photons_;
    s.lightGroup = lightGroup_;
    s.globalLights = lightGroup_ < 0 || groupGlobalLights_;
    s.normal = normalRoot(look);
    if (!look.layers.empty() || !look.choices.empty()) {
        s.texture = textureNode(look, s, 0);
        if (s.texture >= 0) s.pigmentTransparent = s.pigmentTransparent || textureMayLetLightThrough(s.texture);
    }
    if (!look.inside.empty()) {
        s.interiorTexture = textureNode(look.inside[0], s, 0);
        s.pigmentTransparent = s.pigmentTransparent || textureMayLetLightThrough(s.interiorTexture);
    }
    // Objects made one after another mostly look alike (a CSG's leaves, copies in a loop): they
    // share the surface then.
    if (!scene_.povSurfaces.empty() && scene_.povSurfaces.back() == s) {
        m.pov = int(scene_.povSurfaces.size() - 1);
        return m;
    }
    m.pov = int(scene_.povSurfaces.size());
    scene_.povSurfaces.push_back(s);
    return m;
}

void SceneBuilder::countObjects(uint64_t n, const sdl::Loc& at) {
    objects_ += n;
    if (objects_ > maxObjects_)
        throw Error(notes_.where(at) + ": error: the scene makes more than " + std::to_string(maxObjects_) +
                    " objects (each copy of a declared object counts, and each mesh triangle)");
}

void SceneBuilder::addObject(const Item& item, const Transform& parent, const Appearance* inherited, int depth) {
    if (depth > kMaxObjectDepth) throw Error(notes_.where(item.loc) + ": error: objects nested deeper than 1000 levels");
    countObjects(1, item.loc);  // a union of copies of a union of copies ... doubles at every level
    std::vector<const Entry*> entries;
    std::vector<uint32_t> marks;  // each entry's item's #default count (defaultLookAt)
    const Kw kind = unrollObject(item, entries, 0, &marks);
    if (kind == Kw::light_source) {
        Item copy;
        copy.kind = Kw::light_source;
        copy.loc = item.loc;
        for (const Entry* e : entries) copy.entries.push_back(*e);
        return addLight(copy, parent);
    }
    Transform local;
    Appearance look;
    std::vector<const Value*> args;
    std::vector<const Item*> children;
    std::vector<Clip> clips;
    const Entry* bounds = nullptr;
    Transform boundsBefore;  // the transformations written before bounded_by (they do not move it)
    bool cutaway = false;  // cutaway_textures (on a difference or intersection)
    bool noRadiosity = false;
    bool inverse = false, open = false, noShadow = false, noImage = false, noReflection = false,
         doubleIlluminate = false, hollow = false, uvMapping = false, globalLights = false;
    const Entry* font = nullptr;  // text: its ttf or internal entry
    const Item* photonBlock = nullptr;
    for (size_t i = 0; i < entries.size(); ++i) {
        const Entry& e = *entries[i];
        if (e.positional()) {
            for (const Value& v : e.args) args.push_back(&v);
            continue;
        }
        if (e.key == kMapEntry) continue;
        if (isTransformEntry(e)) {
            applyTransform(e, local);
            if (look.set || look.interiorSet) placeLook(look, e);  // transformations after the texture (or interior) move it
            continue;
        }
        if (applyAppearanceEntry(e, look, defaultLookAt(marks[i]), notes_, &pigments_)) {
            if (uvMapping && look.set) mapLookByUV(look);  // the object's uv_mapping: all of its texture
            continue;
        }
        const Kw k = e.kw();
        if (k == Kw::uv_mapping) {
            uvMapping = true;
            if (look.set) mapLookByUV(look);
            continue;
        }
        if (collectBlobEntry(kind, e)) continue;
        if (kind == Kw::height_field &&
            (ImageFiles::isImageType(k) || k == Kw::function || k == Kw::smooth || k == Kw::water_level)) {
            terms_.push_back(&e);  // the field's source and modifiers (build_height_field)
            continue;
        }
        if ((kind == Kw::julia_fractal && isJuliaTerm(k)) ||
            (kind == Kw::bicubic_patch && (k == Kw::type || k == Kw::flatness || k == Kw::u_steps ||
                                           k == Kw::v_steps || k == Kw::uv_vectors || k == Kw::accuracy)) ||
            (kind == Kw::parametric && (k == Kw::function || k == Kw::contained_by))) {
            terms_.push_back(&e);  // a julia fractal's algebra, function, ...; a bicubic patch's steps and uv
            continue;
        }
        if ((kind == Kw::union_ || kind == Kw::merge || kind == Kw::light_group || kind == Kw::difference ||
             kind == Kw::intersection) && isObjectKind(k)) {
            children.push_back(&e.args[0].item());
            continue;
        }
        switch (k) {
            case Kw::clipped_by: clips.push_back(Clip{&e, local}); break;
            case Kw::bounded_by:
                bounds = &e;
                boundsBefore = local;
                break;
            case Kw::inverse: inverse = true; break;
            case Kw::cutaway_textures: cutaway = kind == Kw::difference || kind == Kw::intersection; break;
            case Kw::no_shadow: noShadow = isOn(e); break;
            case Kw::no_image: noImage = isOn(e); break;
            case Kw::no_reflection: noReflection = isOn(e); break;
            case Kw::no_radiosity: noRadiosity = isOn(e); break;
            case Kw::double_illuminate: doubleIlluminate = isOn(e); break;
            case Kw::hollow: hollow = isOn(e); break;
            case Kw::global_lights: globalLights = isOn(e); break;
            case Kw::xyz: case Kw::quadratic_spline: case Kw::cubic_spline: case Kw::bezier_spline:
            case Kw::conic_sweep: case Kw::linear_spline: case Kw::linear_sweep: case Kw::b_spline:
                terms_.push_back(&e);  // polynomial's terms, a prism's, lathe's or sphere_sweep's kind
                break;
            case Kw::open:
                open = kind == Kw::cone || kind == Kw::cylinder || kind == Kw::prism || kind == Kw::sor ||
                       kind == Kw::isosurface;
                break;
            case Kw::ttf: case Kw::internal: font = &e; break;
            case Kw::photons: photonBlock = &e.args[0].item(); break;
            default: break;  // sturm, hierarchy, radiosity: no visible change
        }
    }
    // no_shadow, no_image, no_reflection, no_radiosity and double_illuminate hold for the object
    // and everything inside it.
    const Restore<bool> keep{noShadow_, noShadow_}, keepImage{noImage_, noImage_},
        keepReflection{noReflection_, noReflection_}, keepRadiosity{noRadiosity_, noRadiosity_},
        keepDouble{doubleIlluminate_, doubleIlluminate_}, keepHollow{hollow_, hollow_},
        keepGlobal{groupGlobalLights_, groupGlobalLights_};
    const Restore<int> keepGroup{lightGroup_, lightGroup_};
    const Restore<PovPhotonFlags> keepPhotons{photons_, photons_};
    if (photonBlock) photons_ = readPhotonFlags(*photonBlock, photons_);
    noShadow_ = noShadow_ || noShadow;
    noImage_ = noImage_ || noImage;
    noReflection_ = noReflection_ || noReflection;
    noRadiosity_ = noRadiosity_ || noRadiosity;
    doubleIlluminate_ = doubleIlluminate_ || doubleIlluminate;
    hollow_ = hollow_ || hollow;
    if (kind == Kw::light_group) {  // measured: global_lights is off unless given
        lightGroup_ = lightGroups_++;
        groupGlobalLights_ = globalLights;
    }
    const Transform toWorld = parent * local;
    if (local.determinant() == 0) throw Error(notes_.where(item.loc) + ": error: the object's transformation is singular");
    // Finite steps can still overflow or underflow together (scale 1e300 scale 1e300): the object
    // would vanish without a word.
    if (!toWorld.isUsable())
        throw Error(notes_.where(item.loc) + ": error: the object's transformation overflows or is singular");
    if (look.set || look.interiorSet) placeLook(look, parent);  // texture space → world
    if (!look.set && look.interiorSet) {  // an interior alone: the texture it would have had, with it
        const InteriorLook interior = look.interior;
        look = inherited ? *inherited : fallback_;
        look.interior = interior;
        look.interiorSet = true;
        look.set = true;
    }
    const Appearance* own = look.set ? &look : inherited;
    leafTextured_ = own != nullptr;
    // Intersection, difference, merge, clipped and inverted objects become one CSG object (csg.h);
    // other unions outside them are flattened into their children.
    // A bounded_by on the object itself (not within another CSG) gates the rays that see it, on the
    // kinds POV-Ray 3.7 keeps it for (SceneBuilder::gatedByBounds).
    const bool gated = !csg_ && bounds && gatedByBounds(kind);
    Csg tree;
    const bool started = !csg_ && (kind == Kw::difference || kind == Kw::intersection || kind == Kw::merge ||
                                   !clips.empty() || (kind == Kw::union_ && inverse) || gated);
    struct Reset {  // the builder forgets the tree when an error leaves the object half made
        SceneBuilder& b;
        bool on;
        ~Reset() {
            if (on) b.csg_ = nullptr, b.csgParent_ = -1;
        }
    } reset{*this, started};
    if (started) {
        csg_ = &tree;
        csgParent_ = -1;
    }
    const int outer = csgParent_;
    const int clipNode = csg_ && !clips.empty() ? csg_->add(outer, CsgOp::Clip, false) : -1;
    if (clipNode >= 0) csgParent_ = clipNode;
    switch (kind) {
        case Kw::union_: case Kw::merge: case Kw::light_group: case Kw::difference: case Kw::intersection:
            if (csg_) {
                addCsgChildren(kind, inverse, children, toWorld, own, depth);
                break;
            }
            for (const Item* c : children) addObject(*c, toWorld, own, depth + 1);
            break;
        case Kw::mesh: case Kw::mesh2: {
            Item m;
            m.kind = kind;
            m.loc = item.loc;
            for (const Entry* e : entries) m.entries.push_back(*e);
            addMesh(m, toWorld, own ? *own : fallback_, inverse);
            break;
        }
        case Kw::text: addText(font, args, item.loc, toWorld, own ? *own : fallback_, inverse); break;
        case Kw::blob: addBlob(item.loc, toWorld, own ? *own : fallback_, inverse); break;
        case Kw::isosurface: addIsosurface(entries, item.loc, toWorld, own ? *own : fallback_, open, inverse); break;
        default:
            addPrimitive(kind, args, item.loc, toWorld, own ? *own : fallback_, open, inverse);
            terms_.clear();
    }
    if (clipNode >= 0) {
        // The clipping objects follow the transformations written after clipped_by.
        if (csg_->childCount(clipNode) == 0) csg_->nodes[size_t(clipNode)].op = CsgOp::Empty;
        for (const Clip& c : clips) addClippers(*c.entry, bounds, parent * local * c.before.inverse(), depth);
    }
    csgParent_ = outer;
    if (gated) {
        // The bound follows the transformations written after bounded_by, as a clip does.
        auto gate = std::make_shared<Csg>();
        csg_ = gate.get();
        csgParent_ = gate->add(-1, CsgOp::Union, false);
        addClippers(*bounds, nullptr, parent * local * boundsBefore.inverse(), depth);
        csg_ = &tree;
        csgParent_ = outer;
        if (!gate->leaves.empty()) {
            gate->finish();
            tree.gate = std::move(gate);
        }
    }
    if (started) {
        csg_ = nullptr;
        tree.cutaway = cutaway;
        finishCsg(std::move(tree), kind, item.loc);
    }
}

// The kinds whose bounded_by POV-Ray 3.7 keeps as a gate on their rays, measured: each object
// under a bound that covers a small part of it, rendered with and without the bound. Spheres,
// boxes, planes, discs, blobs, polygons, triangles, meshes, height fields and julia fractals show
// whole (POV-Ray drops the bound); the others show only where the rays cross the bound.
bool SceneBuilder::gatedByBounds(Kw kind) {
    switch (kind) {
        case Kw::cylinder: case Kw::cone: case Kw::torus: case Kw::lathe: case Kw::sor: case Kw::prism:
        case Kw::superellipsoid: case Kw::quadric: case Kw::cubic: case Kw::quartic: case Kw::poly:
        case Kw::polynomial: case Kw::text: case Kw::isosurface: case Kw::sphere_sweep: case Kw::ovus:
        case Kw::parametric: case Kw::bicubic_patch: case Kw::union_: case Kw::merge:
        case Kw::intersection: case Kw::difference:
            return true;
        default:
            return false;
    }
}

// A finished object: into the CSG tree being built, or into the scene.
void SceneBuilder::emit(const Object& o, bool inverse) {
    if (csg_) {
        csg_->addLeaf(csgParent_, o, inverse);
        csg_->leafTextured.push_back(leafTextured_);
        return;
    }
    // Grown four times at a time: a scene of many objects made in a loop copies a third of them
    // once instead of all of them, and touches 1.33 times their memory instead of twice (room not
    // yet used is not touched, and the memory budget counts only the objects made). From 4 MiB on
    // the array is marked for transparent huge pages, as the BVH's big buffers are.
    std::vector<Object>& all = scene_.objects;
    if (all.size() == all.capacity()) {
        all.reserve(std::max<size_t>(256, all.capacity() * 4));
        const size_t bytes = all.capacity() * sizeof(Object);
        if (bytes >= tribvh::kHugeThreshold) tribvh::adviseHugePages(all.data(), bytes);  // as the BVH's buffers
    }
    all.push_back(o);
}

// ---- global settings -------------------------------------------------------------------------

void SceneBuilder::globalSettings(const Item& g) {
    for (const Entry& e : g.entries) {
        if (e.positional()) continue;
        switch (e.kw()) {
            case Kw::assumed_gamma:
                // `assumed_gamma srgb` (kept as -1) writes colours as they are, as legacy scenes do.
                scene_.pov.assumedGamma = toFloat(e.args[0]) < 0 ? 0.0 : toFloat(e.args[0]);
                gammaSet_ = true;
                break;
            case Kw::ambient_light: scene_.pov.ambientLight = toColor(e.args[0]).rgb; break;
            case Kw::max_trace_level: scene_.pov.maxTraceLevel = clampedInt(toFloat(e.args[0]), 1, 256); break;
            case Kw::adc_bailout: scene_.pov.adcBailout = toFloat(e.args[0]); break;
            case Kw::irid_wavelength: scene_.pov.iridWavelength = toColor(e.args[0]).rgb; break;
            case Kw::noise_generator:
                scene_.pov.noiseGenerator = std::clamp(int(toFloat(e.args[0])), 1, 3);
                break;
            case Kw::number_of_waves:
                scene_.pov.numberOfWaves = clampedInt(toFloat(e.args[0]), 1, pattern::kMaxWaves);
                break;
            case Kw::radiosity: scene_.pov.radiosity = readRadiosity(e.args[0].item()); break;
            case Kw::photons: scene_.pov.photons = readPhotonSettings(e.args[0].item()); break;
            case Kw::subsurface: readSubsurfaceSettings(e.args[0].item(), scene_.pov.subsurface); break;
            case Kw::mm_per_unit:  // a scale: only a positive one is taken (the default is 10)
                if (const double mm = toFloat(e.args[0]); mm > 0 && std::isfinite(mm)) scene_.pov.subsurface.mmPerUnit = mm;
                break;
            default: break;
        }
    }
}

SceneBuilder::SceneBuilder(NotRendered& notes, uint64_t maxObjects) : notes_(notes), maxObjects_(maxObjects) {
    pigments_.setObjectBuilder([this](const Item& pattern) {
        return buildPatternObject(pattern, [this](const sdl::Loc& at) { return notes_.where(at); }, findFile_, fonts_);
    });
}

void SceneBuilder::reserve(size_t n) {
    scene_.objects.reserve(n);
    scene_.povSurfaces.reserve(n);
}

Scene SceneBuilder::finish(const std::string& fileName) {
    scene_.fileName = fileName;
    scene_.pov.enabled = true;
    // Without assumed_gamma POV-Ray 3.7 works in linear light (1.0) for #version 3.7 scenes and
    // writes older scenes' colours as they are (0) (measured with POV-Ray 3.7.0.10).
    if (!gammaSet_) scene_.pov.assumedGamma = version_ >= 3.7 ? 1.0 : 0.0;
    scene_.pigments.setWorkingGamma(scene_.pov.assumedGamma);
    // Patterns without their own noise_generator take the scene's, wherever global_settings is;
    // number_of_waves likewise.
    for (pattern::PigmentNode& n : scene_.pigments.nodes) {
        if (n.params.noiseGenerator == 0) n.params.noiseGenerator = scene_.pov.noiseGenerator;
        n.params.waves = scene_.pov.numberOfWaves;
    }
    scene_.pov.version = version_;
    if (scene_.cameras.empty()) {
        Camera c;  // POV-Ray's default camera: at the origin looking along +z, right 1.33x, up y
        c.location = {0, 0, 0};
        c.lookAt = {0, 0, 1};
        c.right = {1.33, 0, 0};
        c.up = {0, 1, 0};
        scene_.cameras.push_back(c);
    }
    return std::move(scene_);
}

}  // namespace rays::pov
