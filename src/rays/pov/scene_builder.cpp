#include "rays/pov/scene_builder.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "rays/error.h"
#include "rays/pov/build_mesh.h"
#include "rays/pov/build_shapes.h"
#include "rays/pov/grammar.h"

namespace rays::pov {

using sdl::VType;

namespace {

constexpr int kMaxObjectDepth = 1000;

// v as an int in [lo, hi], clamped as a float first (1e300 has no int); NaN gives lo.
int clampedInt(double v, int lo, int hi) { return std::isnan(v) ? lo : int(std::clamp(v, double(lo), double(hi))); }

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

// An object's entries with `object { Base ... }` copies unrolled: the base's entries come first,
// then the copy's (POV-Ray applies a copy's modifiers after the base's own).
Kw unrollObject(const Item& item, std::vector<const Entry*>& out, int depth) {
    if (item.kind != Kw::object || depth > kMaxObjectDepth) {
        for (const Entry& e : item.entries) out.push_back(&e);
        return item.kind;
    }
    Kw kind = Kw::object;
    bool baseDone = false;
    for (const Entry& e : item.entries) {
        // The base: an object identifier, or an object written inside (`object { union {...} }`).
        if (!baseDone && (e.positional() || isObjectKind(e.kw())) && !e.args.empty() &&
            e.args[0].type == VType::Item && isObjectKind(e.args[0].item().kind)) {
            kind = unrollObject(e.args[0].item(), out, depth + 1);
            baseDone = true;
            continue;
        }
        out.push_back(&e);
    }
    return kind;
}

// The object of a looks_like block (nullptr when it holds none).
const Item* lookedLikeObject(const Entry& e) {
    if (e.args.empty() || e.args[0].type != VType::Item) return nullptr;
    for (const Entry& inner : e.args[0].item().entries)
        for (const Value& v : inner.args)
            if (v.type == VType::Item && isObjectKind(v.item().kind)) return &v.item();
    return nullptr;
}

}  // namespace

void SceneBuilder::add(const ParsedScene::Top& top) {
    version_ = top.version;
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
        case Kw::rainbow: return notes_.note("rainbow", item.loc);
        case Kw::media: return notes_.note("atmospheric media", item.loc);
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
    }
    if (top.defaultsCount > defaultsApplied_) {
        Item added;
        added.kind = Kw::texture;
        added.entries.assign(top.defaults->begin() + std::ptrdiff_t(defaultsApplied_),
                             top.defaults->begin() + std::ptrdiff_t(top.defaultsCount));
        applyTexture(added, defaultsLook_, notes_, &pigments_);
        defaultsApplied_ = top.defaultsCount;
    }
    fallback_ = defaultsLook_;
    fallback_.set = false;
}

// ---- camera ----------------------------------------------------------------------------------
// POV-Ray 3.7 reference, "Placing the Camera": items apply in order; angle sets the direction's
// length from the right vector's; look_at turns direction, right and up (right = sky × direction,
// keeping the handedness of the vectors before it); transformations move the location and turn
// the vectors.
void SceneBuilder::addCamera(const Item& cam) {
    Vec3 loc{0, 0, 0}, dir{0, 0, 1}, up{0, 1, 0}, right{1.33, 0, 0}, sky{0, 1, 0};
    Vec3 lookAt{0, 0, 1};  // POV-Ray's default look_at point (measured: orthographic's window size)
    Camera c;
    bool rightOrUpSet = false, angleSet = false;
    double angles[2] = {-1, -1};  // the angle values given (degrees; −1: none)
    std::vector<const Entry*> entries;
    std::function<void(const Item&)> collect = [&](const Item& it) {
        for (const Entry& e : it.entries) {
            if (e.positional() && !e.args.empty() && e.args[0].type == VType::Item && e.args[0].item().kind == Kw::camera)
                collect(e.args[0].item());
            else
                entries.push_back(&e);
        }
    };
    collect(cam);
    for (const Entry* ep : entries) {
        const Entry& e = *ep;
        if (e.positional()) continue;
        if (isTransformEntry(e)) {
            Transform m;
            applyTransform(e, m);
            loc = m.point(loc);
            lookAt = m.point(lookAt);
            dir = m.vector(dir);
            up = m.vector(up);
            right = m.vector(right);
            continue;
        }
        switch (e.kw()) {
            case Kw::perspective: c.projection = Projection::Perspective; break;
            case Kw::orthographic: c.projection = Projection::Orthographic; break;
            case Kw::fisheye: c.projection = Projection::Fisheye; break;
            case Kw::ultra_wide_angle: c.projection = Projection::UltraWideAngle; break;
            case Kw::omnimax: c.projection = Projection::Omnimax; break;
            case Kw::panoramic: c.projection = Projection::Panoramic; break;
            case Kw::spherical: c.projection = Projection::Spherical; break;
            case Kw::cylinder: {
                const int type = clampedInt(toFloat(e.args[0]), 0, 5);
                if (type < 1 || type > 4) throw Error(notes_.where(e.loc) + ": error: cylinder camera type must be 1 to 4");
                c.projection = Projection(int(Projection::Cylinder1) + type - 1);
                break;
            }
            case Kw::mesh_camera:
                c.projection = Projection::Perspective;
                notes_.note(std::string("camera type ") + std::string(sdl::keywordName(e.kw())), e.loc,
                            "(rendered as a perspective camera)");
                break;
            case Kw::location: loc = toVec3(e.args[0]); break;
            case Kw::direction: dir = toVec3(e.args[0]); break;
            case Kw::up: up = toVec3(e.args[0]); rightOrUpSet = true; break;
            case Kw::right: right = toVec3(e.args[0]); rightOrUpSet = true; break;
            case Kw::sky: sky = toVec3(e.args[0]); break;
            case Kw::angle: {
                angleSet = true;
                for (size_t i = 0; i < 2; ++i) angles[i] = i < e.args.size() ? toFloat(e.args[i]) : -1;
                if (c.projection != Projection::Perspective || e.args.empty()) break;
                const double a = angles[0];
                if (a > 0 && a < 180 && length(dir) > 0)
                    dir = normalize(dir) * (0.5 * length(right) / std::tan(a * std::numbers::pi / 360.0));
                break;
            }
            case Kw::look_at: {
                const Vec3 at = toVec3(e.args[0]);
                lookAt = at;
                const double handed = dot(cross(up, dir), right);
                const double dl = length(dir), ul = length(up), rl = length(right);
                if (length(at - loc) == 0) throw Error(notes_.where(e.loc) + ": error: look_at is the camera location");
                const Vec3 d = normalize(at - loc);
                Vec3 r = cross(sky, d);
                if (length(r) < 1e-12 * length(sky)) {
                    // Looking along the sky vector: keep the right vector, made perpendicular.
                    r = right - dot(right, d) * d;
                    if (length(r) == 0) r = std::fabs(d.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
                    if (handed < 0) r = -r;
                }
                r = normalize(r);
                dir = d * dl;
                up = normalize(cross(d, r)) * ul;
                right = r * (handed < 0 ? -rl : rl);
                break;
            }
            case Kw::focal_point: c.focalPoint = toVec3(e.args[0]); break;
            case Kw::aperture: c.aperture = 0.5 * toFloat(e.args[0]); break;
            case Kw::blur_samples: c.blurSamples = clampedInt(toFloat(e.args.back()), 0, 65536); break;
            case Kw::normal: notes_.note("camera normal", e.loc); break;
            case Kw::bokeh: notes_.note("bokeh", e.loc); break;
            default: break;
        }
    }
    const double dl = length(dir);
    if (dl == 0) throw Error(notes_.where(cam.loc) + ": error: the camera's direction is zero");
    c.location = loc;
    c.lookAt = loc + dir;
    c.right = right / dl;
    c.up = up / dl;
    if (c.projection != Projection::Perspective) finishProjection(c, dir, right, up, lookAt, rightOrUpSet, angleSet, angles);
    if (c.aperture > 0 && c.blurSamples == 0) c.blurSamples = 16;
    scene_.cameras.push_back(c);
}

// The vectors and angles of the non-perspective projections, as measured from POV-Ray 3.7 renders.
// Orthographic: the window is right × up as written; with no right and up given, or with angle,
// it is the view of a perspective camera with the same vectors at the look_at point (whose default
// is <0,0,1>): right·dist/|direction|, or 2·dist·tan(angle/2) wide keeping up's aspect. The angle
// projections default to 90° (spherical: 360° × 180°; its vertical angle to half the horizontal).
void SceneBuilder::finishProjection(Camera& c, Vec3 dir, Vec3 right, Vec3 up, Vec3 lookAt, bool rightOrUpSet,
                                    bool angleSet, const double angles[2]) {
    constexpr double kDeg = std::numbers::pi / 180.0;
    if (c.projection == Projection::Orthographic) {
        if (angleSet || !rightOrUpSet) {
            double dist = length(lookAt - c.location);
            if (dist == 0) dist = 1;
            const double a = angles[0];
            if (a > 0 && a < 180) {
                const double w = 2 * dist * std::tan(0.5 * a * kDeg);
                up = normalize(up) * (w * length(up) / length(right));
                right = normalize(right) * w;
            } else {
                right = right * (dist / length(dir));
                up = up * (dist / length(dir));
            }
        }
        c.right = right;
        c.up = up;
        return;
    }
    c.right = right;
    c.up = up;
    const bool spherical = c.projection == Projection::Spherical;
    c.angleH = (angles[0] > 0 ? angles[0] : spherical ? 360 : 90) * kDeg;
    c.angleV = angles[1] > 0 ? angles[1] * kDeg : (angles[0] > 0 ? 0.5 * c.angleH : 180 * kDeg);
}

// ---- lights ----------------------------------------------------------------------------------

void SceneBuilder::addLight(const Item& item, const Transform& toWorld) {
    Light l;
    std::vector<const Value*> p = positionals(item);
    Vec3 pos = p.empty() ? Vec3{} : toVec3(*p[0]);
    l.color = p.size() > 1 ? toColor(*p[1]).rgb : Vec3{1, 1, 1};
    Transform m;
    Vec3 pointAt{0, 0, 1};
    bool parallel = false, pointAtSet = false;
    double radius = -1, falloff = -1;  // < 0: the light type's default
    const Item* looksLike = nullptr;
    for (const Entry& e : item.entries) {
        if (e.positional()) continue;
        if (isTransformEntry(e)) {
            applyTransform(e, m);
            continue;
        }
        switch (e.kw()) {
            case Kw::spotlight: l.spot = Light::Spot::Cone; break;
            case Kw::cylinder: l.spot = Light::Spot::Cylinder; break;
            case Kw::parallel: parallel = true; break;
            case Kw::point_at:
                pointAt = toVec3(e.args[0]);
                pointAtSet = true;
                break;
            case Kw::radius: radius = toFloat(e.args[0]); break;
            case Kw::falloff: falloff = toFloat(e.args[0]); break;
            case Kw::tightness: l.tightness = std::max(0.0, toFloat(e.args[0])); break;
            case Kw::shadowless: l.shadowless = true; break;
            case Kw::area_light:
                if (e.args.size() == 4) {
                    l.area = true;
                    l.axis1 = toVec3(e.args[0]);
                    l.axis2 = toVec3(e.args[1]);
                    l.n1 = clampedInt(toFloat(e.args[2]), 1, 1024);
                    l.n2 = clampedInt(toFloat(e.args[3]), 1, 1024);
                }
                break;
            case Kw::jitter: l.jitter = e.args.empty() || toFloat(e.args[0]) != 0; break;
            case Kw::adaptive: l.adaptive = clampedInt(toFloat(e.args[0]), -1, 1000); break;
            case Kw::circular: l.circular = e.args.empty() || toFloat(e.args[0]) != 0; break;
            case Kw::orient: l.orient = e.args.empty() || toFloat(e.args[0]) != 0; break;
            case Kw::fade_distance: l.fadeDistance = std::max(0.0, toFloat(e.args[0])); break;
            case Kw::fade_power: l.fadePower = toFloat(e.args[0]); break;
            case Kw::looks_like: looksLike = lookedLikeObject(e); break;
            case Kw::projected_through: notes_.note("projected_through", e.loc); break;
            default: break;
        }
    }
    const Transform world = toWorld * m;
    l.position = world.point(pos);
    l.axis1 = world.vector(l.axis1);
    l.axis2 = world.vector(l.axis2);
    if (l.spot != Light::Spot::None) {
        // The manual's defaults: spotlights radius 30 and falloff 45 degrees (cosines kept);
        // cylindrical lights 0.75 and 1, measured to be distances from the axis.
        const Vec3 d = world.point(pointAtSet ? pointAt : Vec3{}) - l.position;
        if (length(d) == 0) {
            l.spot = Light::Spot::None;
        } else if (l.spot == Light::Spot::Cone) {
            auto cosDeg = [](double deg) { return std::cos(std::clamp(deg, 0.0, 180.0) * std::numbers::pi / 180); };
            l.spotRadius = cosDeg(radius < 0 ? 30 : radius);
            l.spotFalloff = cosDeg(falloff < 0 ? 45 : falloff);
            l.direction = normalize(d);
        } else {
            l.spotRadius = radius < 0 ? 0.75 : radius;
            l.spotFalloff = falloff < 0 ? 1 : falloff;
            // Cylindrical lights shine and cast shadows along their axis (measured).
            parallel = true;
            pointAt = pointAtSet ? pointAt : Vec3{};
        }
    }
    if (parallel) {
        const Vec3 d = world.point(pointAt) - l.position;
        if (length(d) > 0) {
            l.parallel = true;
            l.area = false;
            l.pointAt = world.point(pointAt);
            l.direction = normalize(d);
        } else if (l.spot == Light::Spot::Cylinder) {
            l.spot = Light::Spot::None;
        }
    }
    if (l.area && (length(cross(l.axis1, l.axis2)) == 0)) l.area = false;
    scene_.lights.push_back(l);
    // looks_like: the object, moved to the light's place, is seen but casts no shadow (the manual).
    if (looksLike) {
        const bool saved = noShadow_;
        noShadow_ = true;
        addObject(*looksLike, world * Transform::translate(pos), nullptr, 0);
        noShadow_ = saved;
    }
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
    s.transmit = look.pigment.transmit;
    s.noShadow = noShadow_;
    s.pigment = pigmentRoot(look);
    if (s.pigment >= 0) s.pigmentTransparent = scene_.pigments.mayLetLightThrough(look.pigmentNode);
    s.noImage = noImage_;
    s.noReflection = noReflection_;
    s.doubleIlluminate = doubleIlluminate_;
    s.normal = normalRoot(look);
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
    const Kw kind = unrollObject(item, entries, 0);
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
    bool inverse = false, open = false, noShadow = false, noImage = false, noReflection = false,
         doubleIlluminate = false;
    const Entry* font = nullptr;  // text: its ttf or internal entry
    for (const Entry* ep : entries) {
        const Entry& e = *ep;
        if (e.positional()) {
            for (const Value& v : e.args) args.push_back(&v);
            continue;
        }
        if (e.key == kMapEntry) continue;
        if (isTransformEntry(e)) {
            applyTransform(e, local);
            if (look.set) {  // transformations after the texture move it
                applyTransform(e, look.pigmentToObject);
                applyTransform(e, look.normalToObject);
            }
            continue;
        }
        if (applyAppearanceEntry(e, look, fallback_, notes_, &pigments_)) continue;
        const Kw k = e.kw();
        if ((kind == Kw::union_ || kind == Kw::merge || kind == Kw::light_group || kind == Kw::difference ||
             kind == Kw::intersection) && isObjectKind(k)) {
            children.push_back(&e.args[0].item());
            continue;
        }
        switch (k) {
            case Kw::clipped_by: clips.push_back(Clip{&e, local}); break;
            case Kw::bounded_by: bounds = &e; break;  // a speed hint only
            case Kw::inverse: inverse = true; break;
            case Kw::no_shadow: noShadow = e.args.empty() || toFloat(e.args[0]) != 0; break;
            case Kw::no_image: noImage = e.args.empty() || toFloat(e.args[0]) != 0; break;
            case Kw::no_reflection: noReflection = e.args.empty() || toFloat(e.args[0]) != 0; break;
            case Kw::double_illuminate: doubleIlluminate = e.args.empty() || toFloat(e.args[0]) != 0; break;
            case Kw::xyz: case Kw::quadratic_spline: case Kw::cubic_spline: case Kw::bezier_spline:
            case Kw::conic_sweep: case Kw::linear_spline: case Kw::linear_sweep:
                terms_.push_back(&e);  // polynomial's terms, a prism's kind
                break;
            case Kw::open: open = kind == Kw::cone || kind == Kw::cylinder || kind == Kw::prism; break;
            case Kw::ttf: case Kw::internal: font = &e; break;
            default: break;  // hollow, sturm, hierarchy, photons, radiosity: no visible change
        }
    }
    // no_shadow, no_image, no_reflection and double_illuminate hold for the object and everything
    // inside it.
    struct KeepFlag {
        bool& flag;
        bool saved;
        ~KeepFlag() { flag = saved; }
    } keep{noShadow_, noShadow_}, keepImage{noImage_, noImage_}, keepReflection{noReflection_, noReflection_},
        keepDouble{doubleIlluminate_, doubleIlluminate_};
    noShadow_ = noShadow_ || noShadow;
    noImage_ = noImage_ || noImage;
    noReflection_ = noReflection_ || noReflection;
    doubleIlluminate_ = doubleIlluminate_ || doubleIlluminate;
    const Transform toWorld = parent * local;
    if (local.determinant() == 0) throw Error(notes_.where(item.loc) + ": error: the object's transformation is singular");
    if (look.set) {  // texture space → world
        look.pigmentToObject = parent * look.pigmentToObject;
        look.normalToObject = parent * look.normalToObject;
    }
    const Appearance* own = look.set ? &look : inherited;
    // Intersection, difference, merge and clipped objects become one CSG object (csg.h); unions
    // outside them are flattened into their children.
    Csg tree;
    const bool started =
        !csg_ && (kind == Kw::difference || kind == Kw::intersection || kind == Kw::merge || !clips.empty());
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
    if (started) {
        csg_ = nullptr;
        finishCsg(std::move(tree), kind, item.loc);
    }
}

// The children of a CSG node (op from kind) under csgParent_. A child not rendered leaves an
// intersection empty, and a difference whose first child it is; a union or merge, or a
// difference losing a subtracted child, is drawn without it.
void SceneBuilder::addCsgChildren(Kw kind, bool inverse, const std::vector<const Item*>& children,
                                  const Transform& toWorld, const Appearance* own, int depth) {
    const CsgOp op = kind == Kw::difference ? CsgOp::Difference
                     : kind == Kw::intersection ? CsgOp::Intersection
                     : kind == Kw::merge        ? CsgOp::Merge
                                                : CsgOp::Union;
    const int node = csg_->add(csgParent_, op, inverse);
    const int outer = csgParent_;
    bool empty = false;
    for (size_t i = 0; i < children.size(); ++i) {
        csgParent_ = node;
        const int before = csg_->childCount(node);
        addObject(*children[i], toWorld, own, depth + 1);
        const bool lost = csg_->childCount(node) == before;
        empty = empty || (lost && (op == CsgOp::Intersection || (op == CsgOp::Difference && i == 0)));
    }
    csgParent_ = outer;
    if (empty) csg_->nodes[size_t(node)].op = CsgOp::Empty;
}

// The objects of a clipped_by block under csgParent_ (the clip node); `clipped_by { bounded_by }`
// takes the objects of the bounded_by block.
void SceneBuilder::addClippers(const Entry& clip, const Entry* bounds, const Transform& toWorld, int depth) {
    const int node = csgParent_;
    for (const Value& v : clip.args) {
        if (v.type != VType::Item) continue;
        for (const Entry& e : v.item().entries) {
            if (!e.positional() && e.key != kMapEntry && e.kw() == Kw::bounded_by && bounds && bounds != &clip) {
                addClippers(*bounds, nullptr, toWorld, depth);
                continue;
            }
            for (const Value& a : e.args)
                if (a.type == VType::Item && isObjectKind(a.item().kind)) {
                    csgParent_ = node;
                    addObject(a.item(), toWorld, nullptr, depth + 1);
                }
        }
    }
    csgParent_ = node;
}

// A finished CSG tree becomes one object, unless it needs the inside of a triangle or mesh (they
// have none) or can never be seen.
void SceneBuilder::finishCsg(Csg&& tree, Kw kind, const sdl::Loc& at) {
    if (tree.leaves.empty()) return;
    for (size_t k = 0; k < tree.leaves.size(); ++k)
        if (insideShape(tree.leaves[k], Vec3{}) < 0 && tree.needsInside(int(k))) {
            notes_.note(std::string(sdl::keywordName(kind)) + " of triangles or meshes", at, "(left out)");
            return;
        }
    // An opaque merge looks as a union does (its inner surfaces are hidden): its children become
    // objects of their own, in the scene's BVH.
    bool unionLike = true;
    for (const CsgNode& n : tree.nodes)
        unionLike = unionLike && !n.inverse && (n.op == CsgOp::Leaf || n.op == CsgOp::Union || n.op == CsgOp::Merge);
    for (const Object& leaf : tree.leaves)
        unionLike = unionLike && leaf.material.filter == 0 && scene_.povSurfaces[size_t(leaf.material.pov)].transmit == 0;
    if (unionLike) {
        for (const Object& leaf : tree.leaves) scene_.objects.push_back(leaf);
        return;
    }
    tree.finish();
    if (tree.boundsEmpty()) return;
    Object o;
    o.type = ShapeType::Csg;
    o.line = int(at.line);
    o.col = int(at.col);
    o.material = tree.leaves[0].material;
    for (size_t k = 0; k < tree.leaves.size(); ++k)
        if (tree.hasSurface[k]) {
            o.material = tree.leaves[k].material;  // the interior a ray inside it is in
            break;
        }
    scene_.csgs.push_back(std::make_unique<Csg>(std::move(tree)));
    o.csg = scene_.csgs.back().get();
    prepareObject(o, Transform{});
    scene_.objects.push_back(o);
}

// A finished object: into the CSG tree being built, or into the scene.
void SceneBuilder::emit(const Object& o, bool inverse) {
    if (csg_) csg_->addLeaf(csgParent_, o, inverse);
    else scene_.objects.push_back(o);
}

void SceneBuilder::addPrimitive(Kw kind, const std::vector<const Value*>& a, const sdl::Loc& at,
                                const Transform& toWorld, const Appearance& look, bool open, bool inverse) {
    auto need = [&](size_t n) {
        if (a.size() < n)
            throw Error(notes_.where(at) + ": error: " + std::string(sdl::keywordName(kind)) + " needs " +
                        std::to_string(n) + " values, found " + std::to_string(a.size()));
    };
    Object o;
    o.line = int(at.line);
    o.col = int(at.col);
    switch (kind) {
        case Kw::sphere:
            need(2);
            o.type = ShapeType::Sphere;
            o.p0 = toVec3(*a[0]);
            o.r0 = toFloat(*a[1]);
            if (o.r0 <= 0) return;
            break;
        case Kw::box: {
            need(2);
            o.type = ShapeType::Box;
            const Vec3 p = toVec3(*a[0]), q = toVec3(*a[1]);
            o.p0 = vmin(p, q);
            o.p1 = vmax(p, q);
            break;
        }
        case Kw::cone:
            need(4);
            o.type = ShapeType::Cone;
            o.p0 = toVec3(*a[0]);
            o.r0 = std::fabs(toFloat(*a[1]));
            o.p1 = toVec3(*a[2]);
            o.r1 = std::fabs(toFloat(*a[3]));
            if (length(o.p1 - o.p0) == 0 || (o.r0 == 0 && o.r1 == 0)) return;
            break;
        case Kw::cylinder:
            need(3);
            o.type = ShapeType::Cone;
            o.p0 = toVec3(*a[0]);
            o.p1 = toVec3(*a[1]);
            o.r0 = o.r1 = std::fabs(toFloat(*a[2]));
            if (length(o.p1 - o.p0) == 0 || o.r0 == 0) return;
            break;
        case Kw::plane: {
            need(2);
            o.type = ShapeType::Plane;
            const Vec3 n = toVec3(*a[0]);
            if (length(n) == 0) throw Error(notes_.where(at) + ": error: the plane's normal is zero");
            o.p0 = normalize(n);
            o.r0 = toFloat(*a[1]);  // points with n̂·p = d
            break;
        }
        case Kw::triangle: case Kw::smooth_triangle: {
            const bool smooth = kind == Kw::smooth_triangle;
            need(smooth ? 6 : 3);
            o.type = ShapeType::Triangle;
            o.p0 = toVec3(*a[0]);
            o.p1 = toVec3(*a[smooth ? 2 : 1]);
            o.p2 = toVec3(*a[smooth ? 4 : 2]);
            if (length(cross(o.p1 - o.p0, o.p2 - o.p0)) == 0) return;
            if (smooth) {
                o.smooth = true;
                o.n0 = toVec3(*a[1]);
                o.n1 = toVec3(*a[3]);
                o.n2 = toVec3(*a[5]);
                if (length(o.n0) == 0 || length(o.n1) == 0 || length(o.n2) == 0) o.smooth = false;
                else o.n0 = normalize(o.n0), o.n1 = normalize(o.n1), o.n2 = normalize(o.n2);
            }
            break;
        }
        default: {
            std::unique_ptr<ShapeData> data;
            const ShapeBuild made = buildShape(kind, a, terms_, o, data, notes_.where(at));
            if (made == ShapeBuild::Empty) return;
            if (made == ShapeBuild::NotAShape) {
                notes_.note(std::string(sdl::keywordName(kind)), at, "(left out)");
                return;
            }
            if (data) {
                o.data = data.get();
                scene_.shapeData.push_back(std::move(data));
            }
            break;
        }
    }
    o.open = open && (o.type == ShapeType::Cone || o.type == ShapeType::Prism);
    o.material = material(look);
    prepareObject(o, toWorld);
    emit(o, inverse);
}

// ---- text -----------------------------------------------------------------------------------

namespace {

// POV-Ray 3.7's built-in fonts by number (reference 3.4.5.1.16 "Text"), out of range → 0; the
// Debian package fonts-povray holds the same files.
const char* internalFont(double n) {
    static const char* const kFonts[] = {"povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf"};
    const int i = std::isnan(n) ? 0 : int(n);
    return kFonts[i >= 0 && i < 4 ? i : 0];
}

// Where fonts-povray installs its fonts: searched after the include path.
constexpr const char* kInstalledFonts = "/usr/share/fonts/truetype/povray";

}  // namespace

// `text { ttf FILE STRING thickness, offset }`: the font file is looked up as `#include` files
// are (the scene's folder, the library paths, the installed include folder), then in fonts-povray's folder.
void SceneBuilder::addText(const Entry* font, const std::vector<const Value*>& a, const sdl::Loc& at,
                           const Transform& toWorld, const Appearance& look, bool inverse) {
    if (!font || font->args.empty()) throw Error(notes_.where(at) + ": error: text needs ttf \"FILE\" or internal N");
    if (a.size() < 3 || a[0]->type != VType::String)
        throw Error(notes_.where(at) + ": error: text needs a string, a thickness and an offset after the font");
    std::string name;
    if (font->kw() == Kw::internal) name = internalFont(toFloat(font->args[0]));
    else if (font->args[0].type == VType::String) name = font->args[0].str();
    else throw Error(notes_.where(font->loc) + ": error: ttf needs the font file's name as a string");
    // A name without an extension is also tried with ".ttf" (POV-Ray's examples write "cyrvetic").
    std::vector<std::string> names{name};
    if (!std::filesystem::path(name).has_extension()) names.push_back(name + ".ttf");
    std::string path;
    for (const std::string& n : names) {
        if (path.empty() && findFile_) path = findFile_(n);
        if (path.empty() && !std::filesystem::path(n).is_absolute()) {
            const std::string installed = (std::filesystem::path(kInstalledFonts) / n).string();
            if (std::filesystem::is_regular_file(installed)) path = installed;
        }
    }
    if (path.empty())
        throw Error(notes_.where(font->loc) + ": error: cannot find the font file \"" + name +
                    "\" (looked in the scene's folder, the library paths and " + kInstalledFonts + ")");
    const double thickness = toFloat(*a[1]);
    const Vec3 offset = toVec3(*a[2]);
    if (!std::isfinite(thickness)) return;
    std::unique_ptr<TtfFont>& f = (*fonts_)[path];
    try {
        if (!f) f = std::make_unique<TtfFont>(path);
    } catch (const Error& err) {
        throw Error(notes_.where(font->loc) + ": " + err.what());
    }
    auto shape = std::make_unique<TextShape>(f->layout(a[0]->str(), thickness, offset));
    if (shape->bounds.empty()) return;  // "": nothing (a string of spaces is an empty box, as in POV-Ray)
    Object o;
    o.type = ShapeType::Text;
    o.text = shape.get();
    o.line = int(at.line);
    o.col = int(at.col);
    o.material = material(look);
    prepareObject(o, toWorld);
    scene_.texts.push_back(std::move(shape));
    emit(o, inverse);
}

void SceneBuilder::addMesh(const Item& m, const Transform& toWorld, const Appearance& look, bool inverse) {
    std::string problem;
    std::unique_ptr<Mesh> mesh = meshFromItem(m, problem);
    if (!mesh) throw Error(notes_.where(m.loc) + ": error: " + problem);
    if (mesh->triangleCount() == 0) return;
    countObjects(mesh->triangleCount(), m.loc);
    for (const Entry& e : m.entries)
        if (!e.positional() && e.key != kMapEntry && e.kw() == Kw::texture_list)
            notes_.note("mesh2 texture_list", e.loc, "(the mesh's own texture is used)");
    try {
        mesh->finalize();
    } catch (const Error& err) {
        throw Error(notes_.where(m.loc) + ": error: " + err.what());
    }
    Object o;
    o.type = ShapeType::Mesh;
    o.mesh = mesh.get();
    o.line = int(m.loc.line);
    o.col = int(m.loc.col);
    o.material = material(look);
    prepareObject(o, toWorld);
    scene_.meshes.push_back(std::move(mesh));
    emit(o, inverse);
}

// ---- atmosphere -----------------------------------------------------------------------------

// POV-Ray 3.7 reference, "Fog": fog_type 1 (constant) and 2 (ground fog along up), distance and
// the colour with filter and transmit; transformations turn up. A fog identifier's items come
// first. distance 0 turns the fog off (the manual).
void SceneBuilder::addFog(const Item& item) {
    PovFog f;
    bool turbulent = false;
    Transform m;
    std::function<void(const Item&)> read = [&](const Item& it) {
        for (const Entry& e : it.entries) {
            if (e.positional()) {
                for (const Value& v : e.args) {
                    if (v.type == VType::Item && v.item().kind == Kw::fog) {
                        read(v.item());
                    } else {
                        const Rgbft c = toColor(v);
                        f.color = c.rgb;
                        f.filter = c.filter;
                        f.transmit = c.transmit;
                    }
                }
                continue;
            }
            if (isTransformEntry(e)) {
                applyTransform(e, m);
                continue;
            }
            switch (e.kw()) {
                case Kw::fog_type: f.ground = toFloat(e.args[0]) == 2; break;
                case Kw::distance: f.distance = toFloat(e.args[0]); break;
                case Kw::fog_offset: f.offset = toFloat(e.args[0]); break;
                case Kw::fog_alt: f.alt = toFloat(e.args[0]); break;
                case Kw::up: f.up = toVec3(e.args[0]); break;
                case Kw::turbulence: turbulent = turbulent || length(toVec3(e.args[0])) > 0; break;
                default: break;  // turb_depth, omega, lambda, octaves: only with turbulence
            }
        }
    };
    read(item);
    if (turbulent) notes_.note("fog turbulence", item.loc, "(the fog is drawn smooth)");
    f.up = m.vector(f.up);
    if (f.distance <= 0 || length(f.up) == 0) return;
    f.up = normalize(f.up);
    scene_.pov.fogs.push_back(f);
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
            case Kw::radiosity: notes_.note("radiosity", e.loc); break;
            case Kw::photons: notes_.note("photons", e.loc); break;
            case Kw::subsurface: notes_.note("subsurface", e.loc); break;
            default: break;
        }
    }
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
