#include "rays/pov/scene_builder.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rays/error.h"
#include "rays/pov/build_mesh.h"
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
        case Kw::fog: return notes_.note("fog", item.loc);
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
    Camera c;
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
            dir = m.vector(dir);
            up = m.vector(up);
            right = m.vector(right);
            continue;
        }
        switch (e.kw()) {
            case Kw::perspective: break;
            case Kw::orthographic: case Kw::fisheye: case Kw::ultra_wide_angle: case Kw::omnimax: case Kw::panoramic:
            case Kw::spherical: case Kw::cylinder: case Kw::mesh_camera:
                notes_.note(std::string("camera type ") + std::string(sdl::keywordName(e.kw())), e.loc,
                            "(rendered as a perspective camera)");
                break;
            case Kw::location: loc = toVec3(e.args[0]); break;
            case Kw::direction: dir = toVec3(e.args[0]); break;
            case Kw::up: up = toVec3(e.args[0]); break;
            case Kw::right: right = toVec3(e.args[0]); break;
            case Kw::sky: sky = toVec3(e.args[0]); break;
            case Kw::angle: {
                const double a = toFloat(e.args[0]);
                if (a > 0 && a < 180 && length(dir) > 0)
                    dir = normalize(dir) * (0.5 * length(right) / std::tan(a * std::numbers::pi / 360.0));
                break;
            }
            case Kw::look_at: {
                const Vec3 at = toVec3(e.args[0]);
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
    if (c.aperture > 0 && c.blurSamples == 0) c.blurSamples = 16;
    scene_.cameras.push_back(c);
}

// ---- lights ----------------------------------------------------------------------------------

void SceneBuilder::addLight(const Item& item, const Transform& toWorld) {
    Light l;
    std::vector<const Value*> p = positionals(item);
    Vec3 pos = p.empty() ? Vec3{} : toVec3(*p[0]);
    l.color = p.size() > 1 ? toColor(*p[1]).rgb : Vec3{1, 1, 1};
    Transform m;
    Vec3 pointAt{0, 0, 1};
    bool parallel = false;
    for (const Entry& e : item.entries) {
        if (e.positional()) continue;
        if (isTransformEntry(e)) {
            applyTransform(e, m);
            continue;
        }
        switch (e.kw()) {
            case Kw::spotlight: notes_.note("spotlight", e.loc, "(lit as a point light)"); break;
            case Kw::cylinder: notes_.note("cylindrical light", e.loc, "(lit as a point light)"); break;
            case Kw::parallel: parallel = true; break;
            case Kw::point_at: pointAt = toVec3(e.args[0]); break;
            case Kw::shadowless: notes_.note("shadowless light", e.loc, "(casts shadows)"); break;
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
            case Kw::fade_distance: case Kw::fade_power: notes_.note("light fading", e.loc); break;
            case Kw::looks_like: notes_.note("looks_like", e.loc); break;
            case Kw::projected_through: notes_.note("projected_through", e.loc); break;
            default: break;
        }
    }
    const Transform world = toWorld * m;
    l.position = world.point(pos);
    l.axis1 = world.vector(l.axis1);
    l.axis2 = world.vector(l.axis2);
    if (parallel) {
        const Vec3 d = world.point(pointAt) - l.position;
        if (length(d) > 0) {
            l.parallel = true;
            l.area = false;
            l.pointAt = world.point(pointAt);
            l.direction = normalize(d);
        }
    }
    if (l.area && (length(cross(l.axis1, l.axis2)) == 0)) l.area = false;
    scene_.lights.push_back(l);
}

// ---- objects ---------------------------------------------------------------------------------

Material SceneBuilder::material(const Appearance& look) {
    Material m;
    m.color = look.pigment.rgb;
    m.filter = std::clamp(look.pigment.filter, 0.0, 1.0);
    m.shading = int(ShadingModel::Povray);
    m.ambient = look.finish.ambient.x;
    m.diffuse = look.finish.diffuse;
    m.specular = look.finish.specular;
    m.reflection = look.finish.reflectionMax.x;
    m.ior = look.interior.ior;
    PovSurface s;
    s.finish = look.finish;
    s.interior = look.interior;
    s.transmit = look.pigment.transmit;
    s.pigment = pigmentRoot(look);
    if (s.pigment >= 0) s.pigmentTransparent = scene_.pigments.mayLetLightThrough(look.pigmentNode);
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
    bool leftOut = false;
    for (const Entry* ep : entries) {
        const Entry& e = *ep;
        if (e.positional()) {
            for (const Value& v : e.args) args.push_back(&v);
            continue;
        }
        if (e.key == kMapEntry) continue;
        if (isTransformEntry(e)) {
            applyTransform(e, local);
            if (look.set) applyTransform(e, look.pigmentToObject);  // transformations after the texture move it
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
            case Kw::clipped_by: notes_.note("clipped_by", e.loc, "(objects clipped are left out)"); leftOut = true; break;
            case Kw::no_shadow: notes_.note("no_shadow", e.loc, "(the object casts shadows)"); break;
            case Kw::no_image: notes_.note("no_image", e.loc); break;
            case Kw::no_reflection: notes_.note("no_reflection", e.loc); break;
            case Kw::double_illuminate: break;
            case Kw::open:
                if (kind == Kw::cone || kind == Kw::cylinder) notes_.note("open cone and cylinder", e.loc, "(drawn closed)");
                break;
            default: break;  // hollow, sturm, hierarchy, photons, radiosity, bounded_by: no visible change
        }
    }
    if (leftOut) return;
    const Transform toWorld = parent * local;
    if (local.determinant() == 0) throw Error(notes_.where(item.loc) + ": error: the object's transformation is singular");
    if (look.set) look.pigmentToObject = parent * look.pigmentToObject;  // texture space → world
    const Appearance* own = look.set ? &look : inherited;
    switch (kind) {
        case Kw::union_: case Kw::merge: case Kw::light_group:
            for (const Item* c : children) addObject(*c, toWorld, own, depth + 1);
            return;
        case Kw::difference: case Kw::intersection:
            notes_.note(std::string(sdl::keywordName(kind)), item.loc, "(left out)");
            return;
        case Kw::mesh: case Kw::mesh2: {
            Item m;
            m.kind = kind;
            m.loc = item.loc;
            for (const Entry* e : entries) m.entries.push_back(*e);
            return addMesh(m, toWorld, own ? *own : fallback_);
        }
        default:
            return addPrimitive(kind, args, item.loc, toWorld, own ? *own : fallback_);
    }
}

void SceneBuilder::addPrimitive(Kw kind, const std::vector<const Value*>& a, const sdl::Loc& at,
                                const Transform& toWorld, const Appearance& look) {
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
        default:
            notes_.note(std::string(sdl::keywordName(kind)), at, "(left out)");
            return;
    }
    o.material = material(look);
    prepareObject(o, toWorld);
    scene_.objects.push_back(o);
}

void SceneBuilder::addMesh(const Item& m, const Transform& toWorld, const Appearance& look) {
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
    scene_.objects.push_back(o);
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
